/**
 * \file
 * \brief What only the digiview backend does, in every format, against the DigiView emulator on 127.0.0.1 and
 * against a DigiView that answers with the published implementations' frames (the backend contract suite covers what
 * every device does).
 */
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "startup_error.h"
#include "wait_until.h"

#include "digiview_test_devices.h"
#include "digiview_test_formats.h"
#include "ptz_action_server/core/text.h"

using namespace ptz_action_server;
using namespace ptz_action_server::digiview;
using namespace ptz_action_server::digiview_devices;

namespace
{
/// A message of \p type about \p param asking for reports every \p interval ms (0: none, or a cancel).
std::function<bool(const ReceivedMessage&)> is(MessageType type, digiview::ParamType param, std::uint32_t interval = 0)
{
  return [type, param, interval](const ReceivedMessage& item) {
    IntervalRequest request;  // 0.5: GET_INTERVAL's data; later a GET's interval_ms
    const std::uint32_t asked = unpackInterval(item.message, request) == UnpackError::NONE ? request.interval_ms : 0;
    return item.error == UnpackError::NONE && item.message.message_type == type && item.message.param_type == param &&
           asked == interval;
  };
}

/// The subscription to \p param at \p interval ms in \p format: 0.5 GET_INTERVAL, later a GET with interval_ms.
std::function<bool(const ReceivedMessage&)> subscription(Format format, digiview::ParamType param,
                                                         std::uint32_t interval)
{
  return is(subscribesWithGet(format) ? MessageType::GET_PARAMETERS : MessageType::GET_INTERVAL, param, interval);
}

class DigiViewBackend : public ::testing::TestWithParam<Format>
{
};
}  // namespace

TEST_P(DigiViewBackend, StartupSubscribesToTheViewAndLearnsTheStream)
{
  DigiViewEmulator emulator(emulatorConfig(GetParam()));
  auto backend = makeDeviceBackend<DigiViewProtocol>(backendConfig(emulator.port(), GetParam()));
  backend->start();
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  EXPECT_TRUE(emulator.received().waitFor(is(MessageType::GET_PARAMETERS, digiview::ParamType::VIDEO_OUTPUT), WAIT));
  EXPECT_TRUE(emulator.received().waitFor(subscription(GetParam(), digiview::ParamType::CAM_TARGETING, 100), WAIT));
  EXPECT_TRUE(
      emulator.received().waitFor(subscription(GetParam(), digiview::ParamType::CAM_OPTICS_AND_CONTROL, 100), WAIT));
  EXPECT_EQ(backend->protocol<DigiViewProtocol>().numUserViews(), 4);
  EXPECT_NEAR(backend->sample().position[ZOOM], 1.0, 1e-3);  // the emulator starts at fov 1.2 = fov_wide: zoom 1x
  // States keep coming, every 100 ms.
  const std::uint64_t states = backend->protocol<DigiViewProtocol>().counters().states;
  EXPECT_TRUE(waitUntil([&] { return backend->protocol<DigiViewProtocol>().counters().states >= states + 6; }, WAIT));
  EXPECT_DOUBLE_EQ(backend->capabilities().axes[ZOOM].range.max, 12.0);  // fov_wide / 0.1
  // What DigiView does for a view, in every format: every axis goes to positions, moves at a speed (a moving target)
  // and is reported (zoom through the field of view); the view turns by an offset of its own (euler_delta).
  const Capabilities capabilities = backend->capabilities();
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities.axes[axis];
    EXPECT_TRUE(capability.present && capability.absolute && capability.velocity && capability.feedback) << axis;
    EXPECT_EQ(capability.limitation, "") << axis;
  }
  EXPECT_TRUE(capabilities.relative_moves);
  EXPECT_FALSE(capabilities.device_presets);
  EXPECT_FALSE(capabilities.device_home);
  for (const ReceivedMessage& item : emulator.received().items())
  {
    EXPECT_EQ(item.error, UnpackError::NONE) << "the emulator could not read a message of the backend's";
  }
}

TEST_P(DigiViewBackend, QuitIsSentAtShutdownAndClosesTheConnection)
{
  DigiViewEmulator emulator(emulatorConfig(GetParam()));
  {
    auto backend = makeDeviceBackend<DigiViewProtocol>(backendConfig(emulator.port(), GetParam()));
    backend->start();
    ASSERT_TRUE(waitUntil([&] { return emulator.connections() == 1; }, WAIT));
    emulator.received().clear();
  }
  // The backend is gone; what it wrote last may still be on its way to the emulator.
  EXPECT_TRUE(emulator.received().waitFor(subscription(GetParam(), digiview::ParamType::CAM_TARGETING, 0), WAIT));
  EXPECT_TRUE(emulator.received().waitFor(is(MessageType::QUIT, digiview::ParamType::SYSTEM_STATUS), WAIT));
  EXPECT_TRUE(waitUntil([&] { return emulator.connections() == 0; }, WAIT)) << "QUIT closes the connection";
}

TEST_P(DigiViewBackend, LearnsTheNumberOfViewsFromThePublishedVideoOutput)
{
  // Camera 3 exists only if the backend reads num_user_views = 4 from its own byte @15 of the published reply.
  PublishedDigiView digiview(GetParam());
  DeviceConfig<DigiViewProtocol> config = backendConfig(digiview.port(), GetParam());
  config.settings.cam_id = 3;
  auto backend = makeDeviceBackend<DigiViewProtocol>(config);
  ASSERT_EQ(startupError(*backend), "");
  EXPECT_EQ(backend->protocol<DigiViewProtocol>().numUserViews(), 4);
  EXPECT_EQ(backend->protocol<DigiViewProtocol>().counters().bad[static_cast<std::size_t>(UnpackError::BAD_CHECKSUM)],
            0u);
}

TEST_P(DigiViewBackend, ACameraTheStreamDoesNotHaveFailsAtStart)
{
  DigiViewEmulatorConfig emulator_config = emulatorConfig(GetParam());
  emulator_config.layout_mode = 0;  // one user view
  DigiViewEmulator emulator(emulator_config);
  DeviceConfig<DigiViewProtocol> config = backendConfig(emulator.port(), GetParam());
  config.settings.cam_id = 1;
  auto backend = makeDeviceBackend<DigiViewProtocol>(config);
  const std::string text = startupError(*backend);
  EXPECT_NE(text.find("DigiView view 'main' camera 1 on tcp 127.0.0.1:"), std::string::npos) << text;
  EXPECT_NE(text.find("stream 'main' has 1 user view(s), so cam_id 1 does not exist"), std::string::npos) << text;
}

TEST_P(DigiViewBackend, ADigiViewOfAFormatOfAnotherSizeFailsAtStartSayingSo)
{
  for (Format other : FORMATS)
  {
    if (layoutOf(other).size == layoutOf(GetParam()).size)
    {
      continue;  // 1.0 and 1.1 read each other (see OneAndOneOneReadEachOtherButForDetectionId)
    }
    const std::string names = formatsOfSize(layoutOf(other).size);  // "0.5", "1.0 or 1.1", "1.2"
    for (LinkKind transport : { LinkKind::TCP, LinkKind::UDP })
    {
      DigiViewEmulator emulator(emulatorConfig(other, transport));
      auto backend = makeDeviceBackend<DigiViewProtocol>(backendConfig(emulator.port(), GetParam(), transport));
      const std::string text = startupError(*backend);
      const std::string expected =
          formatText("DigiView speaks format %s (%zu-byte messages), but format is set to "
                     "\"%s\" (%zu-byte messages)",
                     names.c_str(), layoutOf(other).size, toString(GetParam()), layoutOf(GetParam()).size);
      EXPECT_NE(text.find(expected), std::string::npos)
          << toString(other) << " " << toString(transport) << ": " << text;
    }
  }
}

TEST_P(DigiViewBackend, AimsInDirectionalModeAndNamesNoDetection)
{
  DigiViewEmulator emulator(emulatorConfig(GetParam()));
  auto backend = makeDeviceBackend<DigiViewProtocol>(backendConfig(emulator.port(), GetParam()));
  backend->start();
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up; }, WAIT));
  backend->goTo(AxisValues{ { 0.3, -0.2, 2.0 } });
  auto targeting = [](const ReceivedMessage& item) {
    return item.error == UnpackError::NONE && item.message.message_type == MessageType::SET_PARAMETERS &&
           item.message.param_type == digiview::ParamType::CAM_TARGETING;
  };
  ASSERT_TRUE(emulator.received().waitFor(targeting, WAIT));
  for (const ReceivedMessage& item : emulator.received().items())
  {
    if (!targeting(item))
    {
      continue;
    }
    CamTargeting sent;
    ASSERT_EQ(unpackTargeting(item.message, sent), UnpackError::NONE);
    EXPECT_EQ(sent.targeting_mode, 0);
    EXPECT_NEAR(sent.yaw, 0.3, 1e-3);
    EXPECT_NEAR(sent.pitch, -0.2, 1e-3);
    // 1.1 carries detection_id -1 (no detection: FF FF), 1.2 track_id 0 and view_id -1 (no detection lock); the
    // others have no such field.
    EXPECT_EQ(sent.detection_id, -1);
    EXPECT_EQ(sent.view_id, -1);
    EXPECT_EQ(sent.track_id, 0);
    EXPECT_FALSE(sent.lock_target);
    const std::size_t tail = layoutOf(GetParam()).data_offset + nameSizeOf(GetParam()) + 32;
    const std::size_t at = GetParam() == Format::V1_2 ? tail + 2 : tail;
    if (GetParam() == Format::V1_1 || GetParam() == Format::V1_2)
    {
      const Bytes bytes = item.message.pack();
      EXPECT_EQ(bytes[at], 0xFF);
      EXPECT_EQ(bytes[at + 1], 0xFF);
    }
  }
  EXPECT_TRUE(waitUntil([&] { return std::abs(backend->sample().position[PAN] - 0.3) < 0.01; }, WAIT));
}

TEST_P(DigiViewBackend, ADigiViewThatLeavesTheChecksumZeroIsUsedOnlyWhenTheSettingSaysSo)
{
  DigiViewEmulatorConfig emulator_config = emulatorConfig(GetParam());
  emulator_config.fill_checksum = false;
  DigiViewEmulator emulator(emulator_config);

  DeviceConfig<DigiViewProtocol> config = backendConfig(emulator.port(), GetParam());
  config.session.startup_timeout = 2.0;
  auto strict = makeDeviceBackend<DigiViewProtocol>(config);
  EXPECT_NE(startupError(*strict).find("no answer from DigiView"), std::string::npos);
  EXPECT_GT(strict->protocol<DigiViewProtocol>().counters().bad[static_cast<std::size_t>(UnpackError::BAD_CHECKSUM)],
            0u);
  EXPECT_EQ(strict->protocol<DigiViewProtocol>().counters().unverified, 0u);
  strict.reset();

  config.settings.wire.checksum = ChecksumRule::ZERO_ACCEPTED;
  config.session.startup_timeout = WAIT;
  auto lenient = makeDeviceBackend<DigiViewProtocol>(config);
  ASSERT_EQ(startupError(*lenient), "");
  EXPECT_TRUE(waitUntil([&] { return lenient->sample().link_up; }, WAIT));
  EXPECT_GT(lenient->protocol<DigiViewProtocol>().counters().unverified, 0u);
  EXPECT_EQ(lenient->protocol<DigiViewProtocol>().counters().bad[static_cast<std::size_t>(UnpackError::BAD_CHECKSUM)],
            0u);
}

TEST_P(DigiViewBackend, AimsInTheConfiguredAngleUnit)
{
  // Either unit on any format (a setting: DigiViews in the field may differ from their documentation); the backend
  // and the emulator agree, and the wire carries the angle x 1000 in that unit.
  for (AngleUnit unit : { AngleUnit::RADIANS, AngleUnit::DEGREES })
  {
    DigiViewEmulatorConfig emulator_config = emulatorConfig(GetParam());
    emulator_config.wire.angles = unit;
    DigiViewEmulator emulator(emulator_config);
    DeviceConfig<DigiViewProtocol> config = backendConfig(emulator.port(), GetParam());
    config.settings.wire.angles = unit;
    auto backend = makeDeviceBackend<DigiViewProtocol>(config);
    ASSERT_EQ(startupError(*backend), "") << toString(unit);
    backend->goTo(AxisValues{ { 0.3, -0.2, 2.0 } });
    auto targeting = [](const ReceivedMessage& item) {
      return item.error == UnpackError::NONE && item.message.message_type == MessageType::SET_PARAMETERS &&
             item.message.param_type == digiview::ParamType::CAM_TARGETING;
    };
    ASSERT_TRUE(emulator.received().waitFor(targeting, WAIT)) << toString(unit);
    for (const ReceivedMessage& item : emulator.received().items())
    {
      if (targeting(item))
      {
        const Bytes bytes = item.message.pack();
        const std::size_t yaw_at = layoutOf(GetParam()).data_offset + nameSizeOf(GetParam()) + 3;
        const std::int32_t raw = static_cast<std::int32_t>(bytes[yaw_at] | (bytes[yaw_at + 1] << 8) |
                                                           (bytes[yaw_at + 2] << 16) | (bytes[yaw_at + 3] << 24));
        EXPECT_EQ(raw, unit == AngleUnit::DEGREES ? 17188 : 300) << toString(unit);  // 0.3 rad = 17.1887 degrees
      }
    }
    EXPECT_TRUE(waitUntil([&] { return std::abs(backend->sample().position[PAN] - 0.3) < 0.01; }, WAIT))
        << toString(unit);
    // fov = fov_wide / 2 out and back in the same unit: zoom 2.
    EXPECT_TRUE(waitUntil([&] { return std::abs(backend->sample().position[ZOOM] - 2.0) < 0.02; }, WAIT))
        << toString(unit);
  }
}

INSTANTIATE_TEST_SUITE_P(Formats, DigiViewBackend, ::testing::ValuesIn(digiview_test::FORMATS),
                         digiview_test::formatName);
