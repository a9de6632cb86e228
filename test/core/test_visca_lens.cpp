/**
 * \file
 * \brief VISCA focus and iris: the packets against Sony's command tables, and the commands reaching the emulator over a
 * real pseudo-terminal: what it received, what its lens did, a refusal counted as a lens fault, not the goal's.
 */
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <memory>
#include <string>

#include "line_test_support.h"
#include "wait_until.h"

#include "ptz_action_server/core/lens_commander.h"
#include "ptz_action_server/core/visca/visca_protocol.h"
#include "ptz_action_server/emulators/visca_emulator.h"

using namespace ptz_action_server;

namespace
{
constexpr double WAIT = LINE_TEST_WAIT;
constexpr LensFunction FOCUS = LensFunction::FOCUS;
constexpr LensFunction IRIS = LensFunction::IRIS;

std::string hexOf(const std::vector<visca::Packet>& packets)
{
  std::string text;
  for (const visca::Packet& packet : packets)
  {
    text += (text.empty() ? "" : " | ") + visca::toHex(packet);
  }
  return text;
}

// Sony's command tables (SRG-H40UH, FCB-EV7500): CAM_Focus 8x 01 04 08/38/18/48, CAM_AE 8x 01 04 39, CAM_Iris direct
// 8x 01 04 4B.
TEST(ViscaLens, PacketsAreSonysCommands)
{
  const visca::ViscaLens lens;
  LensState unknown;
  EXPECT_EQ(hexOf(visca::lensPackets(1, lens, LensCommand::mode(FOCUS, true), unknown)), "81 01 04 38 02 FF");
  EXPECT_EQ(hexOf(visca::lensPackets(1, lens, LensCommand::mode(FOCUS, false), unknown)), "81 01 04 38 03 FF");
  // A manual command switches an auto (or unknown) focus to manual first: Sony refuses it during auto focus.
  EXPECT_EQ(hexOf(visca::lensPackets(1, lens, LensCommand::velocity(FOCUS, 1.0), unknown)), "81 01 04 38 03 FF | 81 01 "
                                                                                            "04 08 27 FF");
  LensState manual;
  manual.mode = { { LensMode::MANUAL, LensMode::MANUAL } };
  EXPECT_EQ(hexOf(visca::lensPackets(2, lens, LensCommand::velocity(FOCUS, -0.1), manual)), "82 01 04 08 30 FF");
  EXPECT_EQ(hexOf(visca::lensPackets(1, lens, LensCommand::velocity(FOCUS, 0.0), manual)), "81 01 04 08 00 FF");
  EXPECT_EQ(hexOf(visca::lensPackets(1, lens, LensCommand::position(FOCUS, 1.0), manual)), "81 01 04 48 01 00 00 00 "
                                                                                           "FF");
  EXPECT_EQ(hexOf(visca::lensPackets(1, lens, LensCommand::position(FOCUS, 0.0), manual)), "81 01 04 48 0F 00 00 00 "
                                                                                           "FF");
  EXPECT_EQ(hexOf(visca::lensPackets(1, lens, LensCommand::onePush(), manual)), "81 01 04 18 01 FF");
  EXPECT_EQ(hexOf(visca::lensPackets(1, lens, LensCommand::mode(IRIS, true), manual)), "81 01 04 39 00 FF");
  EXPECT_EQ(hexOf(visca::lensPackets(1, lens, LensCommand::position(IRIS, 1.0), unknown)), "81 01 04 39 0B FF | 81 01 "
                                                                                           "04 4B 00 00 01 01 FF");
  EXPECT_TRUE(visca::lensPackets(1, lens, LensCommand::velocity(IRIS, 1.0), manual).empty());  // no iris drive
  EXPECT_DOUBLE_EQ(lens.focusShare(lens.focusPosition(0.25)), 0.25);
}

visca::Reply answerOf(std::initializer_list<std::uint8_t> bytes)
{
  return visca::classify(visca::Packet(bytes));
}

// The inquiries and their answers as Sony's inquiry lists give them (CAM_FocusModeInq, CAM_FocusPosInq, CAM_IrisPosInq:
// EVI-D70, SRG-300H, BRC-H900 tables; the same in PTZOptics', Avonic's and Vaddio's copies).
TEST(ViscaLens, InquiriesAndAnswersAreSonys)
{
  EXPECT_EQ(visca::toHex(visca::focusModeInquiry(1)), "81 09 04 38 FF");
  EXPECT_EQ(visca::toHex(visca::focusPositionInquiry(1)), "81 09 04 48 FF");
  EXPECT_EQ(visca::toHex(visca::irisPositionInquiry(3)), "83 09 04 4B FF");
  LensMode mode = LensMode::UNKNOWN;
  ASSERT_TRUE(visca::decodeFocusModeAnswer(answerOf({ 0x90, 0x50, 0x02, 0xFF }), mode));
  EXPECT_EQ(mode, LensMode::AUTO);
  ASSERT_TRUE(visca::decodeFocusModeAnswer(answerOf({ 0x90, 0x50, 0x03, 0xFF }), mode));
  EXPECT_EQ(mode, LensMode::MANUAL);
  ASSERT_TRUE(visca::decodeFocusModeAnswer(answerOf({ 0x90, 0x50, 0x04, 0xFF }), mode));  // one-push mode: manual
  EXPECT_EQ(mode, LensMode::MANUAL);
  EXPECT_FALSE(visca::decodeFocusModeAnswer(answerOf({ 0x90, 0x50, 0x05, 0xFF }), mode));
  EXPECT_FALSE(visca::decodeFocusModeAnswer(answerOf({ 0x90, 0x60, 0x02, 0xFF }), mode));  // a syntax error
  std::uint16_t focus = 0;
  ASSERT_TRUE(visca::decodeFocusPositionAnswer(answerOf({ 0x90, 0x50, 0x01, 0x02, 0x03, 0x04, 0xFF }), focus));
  EXPECT_EQ(focus, 0x1234);
  EXPECT_FALSE(visca::decodeFocusPositionAnswer(answerOf({ 0x90, 0x50, 0x02, 0xFF }), focus));
  std::uint8_t iris = 0;
  ASSERT_TRUE(visca::decodeIrisPositionAnswer(answerOf({ 0x90, 0x50, 0x00, 0x00, 0x01, 0x01, 0xFF }), iris));
  EXPECT_EQ(iris, 0x11);
  EXPECT_FALSE(visca::decodeIrisPositionAnswer(answerOf({ 0x90, 0x50, 0x01, 0x00, 0x01, 0x01, 0xFF }), iris));
  const visca::ViscaLens lens;
  EXPECT_DOUBLE_EQ(lens.focusShare(0x1000), 1.0);  // far
  EXPECT_DOUBLE_EQ(lens.focusShare(0xF000), 0.0);  // near
}

class ViscaLensTest : public ::testing::Test
{
protected:
  void start(const visca::ViscaLens& camera_lens, const visca::ViscaLens& backend_lens)
  {
    ViscaEmulatorConfig emulator_config;
    emulator_config.port.link = uniqueLink("visca_lens");
    emulator_config.lens = camera_lens;
    emulator_ = std::make_unique<ViscaEmulator>(emulator_config);
    DeviceConfig<ViscaProtocol> config;
    config.link = serialLink(emulator_config.port.link, 9600);
    config.session.state_timeout = LINE_TEST_STATE_TIMEOUT;
    config.settings.lens = backend_lens;
    backend_ = makeDeviceBackend<ViscaProtocol>(config);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
    commander_ = std::make_unique<LensCommander>(*backend_, backend_->capabilities().lens, "visca", 0.5);
  }

  /// The camera received \p hex (one packet, as visca::toHex writes it).
  bool received(const std::string& hex) const
  {
    return emulator_->received().waitFor(
        [&hex](const ReceivedPacket& item) { return visca::toHex(item.packet) == hex; }, WAIT);
  }

  std::unique_ptr<ViscaEmulator> emulator_;
  std::unique_ptr<DeviceBackend> backend_;
  std::unique_ptr<LensCommander> commander_;
};

TEST_F(ViscaLensTest, CapabilitiesDeclareWhatVISCATakes)
{
  start({}, {});
  const LensCapabilities lens = backend_->capabilities().lens;
  EXPECT_TRUE(lens.focus.present && lens.focus.auto_mode && lens.focus.velocity && lens.focus.absolute);
  EXPECT_TRUE(lens.focus.one_push);
  EXPECT_TRUE(lens.focus.feedback);  // polled
  EXPECT_TRUE(lens.iris.feedback);
  EXPECT_TRUE(lens.iris.present && lens.iris.auto_mode && lens.iris.absolute);
  EXPECT_FALSE(lens.iris.velocity);
}

TEST_F(ViscaLensTest, FocusCommandsReachTheCameraAsSonysPackets)
{
  start({}, {});
  EXPECT_EQ(emulator_->lensState().modeOf(FOCUS), LensMode::AUTO);
  ASSERT_EQ(commander_->command(LensCommand::velocity(FOCUS, -1.0), SteadyClock::now()), "");
  ASSERT_TRUE(received("81 01 04 38 03 FF"));  // manual first
  ASSERT_TRUE(received("81 01 04 08 37 FF"));  // near, top speed
  ASSERT_TRUE(waitUntil([&] { return emulator_->lensState().positionOf(FOCUS) == 0.0; }, WAIT));
  EXPECT_EQ(emulator_->lensState().modeOf(FOCUS), LensMode::MANUAL);
  ASSERT_EQ(commander_->command(LensCommand::position(FOCUS, 0.5), SteadyClock::now()), "");
  ASSERT_TRUE(received("81 01 04 48 08 00 00 00 FF"));  // half way between F000 (near) and 1000 (far)
  ASSERT_TRUE(waitUntil([&] { return emulator_->lensState().positionOf(FOCUS) == 0.5; }, WAIT));
  ASSERT_EQ(commander_->command(LensCommand::mode(FOCUS, true), SteadyClock::now()), "");
  ASSERT_TRUE(received("81 01 04 38 02 FF"));
  EXPECT_TRUE(waitUntil([&] { return emulator_->lensState().modeOf(FOCUS) == LensMode::AUTO; }, WAIT));
  EXPECT_EQ(backend_->lensState().modeOf(FOCUS), LensMode::AUTO);
  EXPECT_EQ(backend_->lensState().fault_count, 0u);
}

TEST_F(ViscaLensTest, IrisGoesManualInIrisPriorityThenToItsPosition)
{
  start({}, {});
  ASSERT_EQ(commander_->command(LensCommand::position(IRIS, 1.0), SteadyClock::now()), "");
  ASSERT_TRUE(received("81 01 04 39 0B FF"));
  ASSERT_TRUE(received("81 01 04 4B 00 00 01 01 FF"));
  EXPECT_TRUE(waitUntil([&] { return emulator_->lensState().positionOf(IRIS) == 1.0; }, WAIT));
  EXPECT_EQ(emulator_->lensState().modeOf(IRIS), LensMode::MANUAL);
}

TEST_F(ViscaLensTest, ACameraThatRefusesALensCommandCountsALensFaultNotADeviceFault)
{
  visca::ViscaLens without_iris;
  without_iris.iris = false;
  start(without_iris, {});  // the backend is told the camera has an iris; it has none
  const std::uint64_t device_faults = backend_->sample().fault_count;
  ASSERT_EQ(commander_->command(LensCommand::mode(IRIS, true), SteadyClock::now()), "");
  ASSERT_TRUE(received("81 01 04 39 00 FF"));
  ASSERT_TRUE(waitUntil([&] { return backend_->lensState().fault_count == 1; }, WAIT));
  EXPECT_NE(backend_->lastLensFault().find("81 01 04 39 00 FF"), std::string::npos) << backend_->lastLensFault();
  EXPECT_NE(backend_->lastLensFault().find("syntax error"), std::string::npos) << backend_->lastLensFault();
  EXPECT_EQ(backend_->sample().fault_count, device_faults);
}

TEST_F(ViscaLensTest, ACameraSetWithoutFocusSaysSoAndGetsNothing)
{
  visca::ViscaLens without_focus;
  without_focus.focus = false;
  start(without_focus, without_focus);
  emulator_->received().clear();
  const std::string refusal = commander_->command(LensCommand::velocity(FOCUS, 0.5), SteadyClock::now());
  EXPECT_EQ(refusal, "the VISCA camera is set without focus");
  // Only its polls reach the camera after the refusal.
  ASSERT_TRUE(emulator_->received().waitForCount(4, WAIT));
  for (const ReceivedPacket& item : emulator_->received().items())
  {
    EXPECT_EQ(item.packet[1], 0x09) << visca::toHex(item.packet);
  }
}

TEST_F(ViscaLensTest, LensStateFollowsTheCamerasFocusAsPolled)
{
  start({}, {});
  // Before any lens command: the mode and the position are the camera's own (the node sent none).
  ASSERT_TRUE(waitUntil([&] { return backend_->lensState().modeOf(FOCUS) == LensMode::AUTO; }, WAIT));
  ASSERT_TRUE(waitUntil(
      [&] {
        return std::abs(backend_->lensState().positionOf(FOCUS) - emulator_->lensState().positionOf(FOCUS)) < 1e-3 &&
               std::abs(backend_->lensState().positionOf(IRIS) - emulator_->lensState().positionOf(IRIS)) < 0.07;
      },
      WAIT));
  // A focus drive to the near end: the node sends a velocity only, so the position it shows is the camera's.
  ASSERT_EQ(commander_->command(LensCommand::velocity(FOCUS, -1.0), SteadyClock::now()), "");
  ASSERT_TRUE(waitUntil([&] { return emulator_->lensState().positionOf(FOCUS) == 0.0; }, WAIT));
  EXPECT_TRUE(waitUntil([&] { return std::abs(backend_->lensState().positionOf(FOCUS)) < 1e-3; }, WAIT));
  ASSERT_EQ(commander_->command(LensCommand::position(FOCUS, 0.75), SteadyClock::now()), "");
  EXPECT_TRUE(waitUntil([&] { return std::abs(backend_->lensState().positionOf(FOCUS) - 0.75) < 1e-3; }, WAIT));
  EXPECT_EQ(backend_->lensState().modeOf(FOCUS), LensMode::MANUAL);
}

TEST_F(ViscaLensTest, APoseRoundCarriesOneLensInquiryAtMost)
{
  start({}, {});
  emulator_->received().clear();
  ASSERT_TRUE(emulator_->received().waitForCount(60, WAIT));
  const visca::Packet pan_tilt = visca::panTiltInquiry(1);
  const std::vector<visca::Packet> lens_inquiries{ visca::focusModeInquiry(1), visca::focusPositionInquiry(1),
                                                   visca::irisPositionInquiry(1) };
  std::vector<int> asked(lens_inquiries.size(), 0);
  int in_round = 0;
  int most_in_a_round = 0;
  for (const ReceivedPacket& item : emulator_->received().items())
  {
    in_round = item.packet == pan_tilt ? 0 : in_round;
    for (std::size_t index = 0; index < lens_inquiries.size(); ++index)
    {
      if (item.packet == lens_inquiries[index])
      {
        ++asked[index];
        most_in_a_round = std::max(most_in_a_round, ++in_round);
      }
    }
  }
  EXPECT_EQ(most_in_a_round, 1);
  for (std::size_t index = 0; index < lens_inquiries.size(); ++index)
  {
    EXPECT_GT(asked[index], 0) << visca::toHex(lens_inquiries[index]) << " never asked";
  }
}

TEST_F(ViscaLensTest, ACameraWithoutLensInquiriesStillReportsItsPose)
{
  visca::ViscaLens no_lens;
  no_lens.focus = false;
  no_lens.iris = false;
  start(no_lens, {});  // the backend is told of a lens the camera lacks: its inquiries answer a syntax error
  ASSERT_TRUE(waitUntil(
      [&] {
        const LensCapabilities lens = backend_->capabilities().lens;
        return !lens.focus.feedback && !lens.iris.feedback;
      },
      WAIT));
  std::string warnings;
  for (const std::string& warning : backend_->takeWarnings())
  {
    warnings += warning + "\n";
  }
  EXPECT_NE(warnings.find("refuses the focus inquiries"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("refuses the iris inquiry"), std::string::npos) << warnings;
  EXPECT_TRUE(std::isnan(backend_->lensState().positionOf(FOCUS)));
  EXPECT_EQ(backend_->lensState().fault_count, 0u);  // an inquiry is no lens command
  const std::uint64_t device_faults = backend_->sample().fault_count;
  // No more lens inquiries, and the pose goes on.
  emulator_->received().clear();
  backend_->goTo({ 0.2, 0.1, 1.0 });
  EXPECT_TRUE(waitUntil(
      [&] {
        const PtzSample sample = backend_->sample();
        return sample.link_up && std::abs(sample.position[PAN] - 0.2) < 0.01 && !sample.moving;
      },
      WAIT));
  for (const ReceivedPacket& item : emulator_->received().items())
  {
    EXPECT_FALSE(item.packet.size() > 3 && item.packet[1] == 0x09 && item.packet[2] == 0x04 && item.packet[3] != 0x47)
        << visca::toHex(item.packet);
  }
  EXPECT_EQ(backend_->sample().fault_count, device_faults);
}

}  // namespace
