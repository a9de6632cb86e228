/**
 * \file
 * \brief A halted DigiView (SYSTEM_STATUS HALT, formats 1.1 and 1.2), and the configuration line format "1.1" without
 * an angle unit starts with.
 */
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "digiview_test_devices.h"
#include "digiview_test_formats.h"
#include "startup_error.h"
#include "wait_until.h"

using namespace ptz_action_server;
using namespace ptz_action_server::digiview;
using namespace ptz_action_server::digiview_devices;

namespace
{
/// The formats whose SYSTEM_STATUS can say HALT (1.1, 1.2).
class DigiViewHalt : public ::testing::TestWithParam<Format>
{
};

const std::vector<Format> HALT_FORMATS{ Format::V1_1, Format::V1_2 };
}  // namespace

TEST_P(DigiViewHalt, AHaltedDigiViewThatReportsNoViewKeepsTheLinkAndRefusesGoals)
{
  PublishedDigiView digiview(GetParam());
  DeviceConfig<DigiViewProtocol> config = backendConfig(digiview.port(), GetParam());
  auto backend = makeDeviceBackend<DigiViewProtocol>(config);
  ASSERT_EQ(startupError(*backend), "");
  const DigiViewProtocol& protocol = backend->protocol<DigiViewProtocol>();
  EXPECT_FALSE(protocol.halted());
  const std::uint64_t losses = backend->sample().link_losses;

  digiview.setHalted(true);  // from now on it answers SYSTEM_STATUS (HALT) and nothing about the view
  ASSERT_TRUE(waitUntil([&] { return protocol.halted(); }, WAIT));
  // Three state timeouts without a word about the view: its status answers keep the link up.
  EXPECT_FALSE(waitUntil([&] { return !backend->sample().link_up || backend->sample().link_losses != losses; },
                         3 * config.session.state_timeout))
      << backend->lastLinkLoss();
  const std::uint64_t faults = backend->sample().fault_count;
  backend->goTo(AxisValues{ { 0.3, 0.1, 1.0 } });
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count > faults; }, WAIT));
  EXPECT_NE(backend->lastFault().find("not sent: DigiView view 'main' camera 0 is halted (SYSTEM_STATUS HALT)"),
            std::string::npos)
      << backend->lastFault();
  std::vector<DiagnosticValue> values;
  backend->diagnostics(values);
  const auto status = std::find_if(values.begin(), values.end(),
                                   [](const DiagnosticValue& value) { return value.first == "system status"; });
  ASSERT_NE(status, values.end());
  EXPECT_EQ(status->second, "4 (HALT): goals refused until it runs again");

  digiview.setHalted(false);
  EXPECT_TRUE(waitUntil([&] { return !protocol.halted(); }, WAIT));
  EXPECT_EQ(backend->sample().link_losses, losses);
}

TEST_P(DigiViewHalt, AGoalInFlightWhenDigiViewHaltsEndsAsAFaultAndGoalsWorkWhenItRunsAgain)
{
  DigiViewEmulator emulator(emulatorConfig(GetParam()));
  auto backend = makeDeviceBackend<DigiViewProtocol>(backendConfig(emulator.port(), GetParam()));
  ASSERT_EQ(startupError(*backend), "");
  const std::uint64_t faults = backend->sample().fault_count;
  backend->goTo(AxisValues{ { 1.5, 0.0, 1.0 } });  // 1.5 s at 1 rad/s
  ASSERT_TRUE(emulator.received().waitFor(
      [](const ReceivedMessage& item) {
        return item.message.message_type == MessageType::SET_PARAMETERS &&
               item.message.param_type == digiview::ParamType::CAM_TARGETING;
      },
      WAIT));
  emulator.setHalted(true);  // as a SET SYSTEM_STATUS HALT from DigiView's operator would
  ASSERT_TRUE(waitUntil([&] { return backend->sample().fault_count > faults; }, WAIT));
  EXPECT_NE(backend->lastFault().find("is halted (SYSTEM_STATUS HALT): its views do not turn until DigiView is set "
                                      "running again"),
            std::string::npos)
      << backend->lastFault();
  EXPECT_TRUE(backend->protocol<DigiViewProtocol>().halted());
  EXPECT_LT(emulator.view("main", 0).position[PAN], 1.4) << "the halted view went on turning";

  emulator.setHalted(false);
  ASSERT_TRUE(waitUntil([&] { return !backend->protocol<DigiViewProtocol>().halted(); }, WAIT));
  backend->goTo(AxisValues{ { -0.2, 0.1, 1.0 } });
  EXPECT_TRUE(waitUntil([&] { return std::abs(backend->sample().position[PAN] + 0.2) < 0.01; }, WAIT));
  EXPECT_TRUE(backend->sample().link_up);
}

INSTANTIATE_TEST_SUITE_P(Formats, DigiViewHalt, ::testing::ValuesIn(HALT_FORMATS), digiview_test::formatName);

TEST(DigiViewSettings, OneOneWithoutAnAngleUnitIsTheOnlyConfigurationThatIsTold)
{
  // 1.1 sent radians before this package followed its documentation (degrees): a YAML that names format 1.1 and no
  // unit starts with one deprecation line naming the setting. The others' units never changed.
  const std::string notice = DigiViewSettings::angleUnitNotice(Format::V1_1);
  EXPECT_NE(notice.find("deprecated"), std::string::npos) << notice;
  EXPECT_NE(notice.find("~digiview/angle_unit"), std::string::npos) << notice;
  EXPECT_NE(notice.find("\"radians\""), std::string::npos) << notice;
  for (Format format : { Format::V0_5, Format::V1_0, Format::V1_2 })
  {
    EXPECT_EQ(DigiViewSettings::angleUnitNotice(format), "") << toString(format);
  }
}
