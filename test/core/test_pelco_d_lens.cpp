/**
 * \file
 * \brief Pelco-D focus and iris: the standard command's lens bits, and the commands reaching the emulator over a real
 * pseudo-terminal: what it received, what its lens did, a drive left running, a camera without iris refusing.
 */
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "line_test_support.h"
#include "wait_until.h"

#include "ptz_action_server/core/lens_commander.h"
#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"

using namespace ptz_action_server;

namespace
{
constexpr double WAIT = LINE_TEST_WAIT;
constexpr LensFunction FOCUS = LensFunction::FOCUS;
constexpr LensFunction IRIS = LensFunction::IRIS;

TEST(LensCheck, WhatTheDeviceLacksIsNamedWithItsLimitation)
{
  PelcoSettings settings;
  const LensCapabilities pelco = pelcoLens(settings);
  EXPECT_EQ(checkLensCommand(pelco, LensCommand::velocity(FOCUS, -1.0), "pelco_d"), "");
  const std::string refusal = checkLensCommand(pelco, LensCommand::position(FOCUS, 0.3), "pelco_d");
  EXPECT_NE(refusal.find("takes no focus position"), std::string::npos) << refusal;
  EXPECT_NE(refusal.find("Pelco-D drives it at the camera's own speed"), std::string::npos) << refusal;
  settings.iris = false;
  EXPECT_EQ(checkLensCommand(pelcoLens(settings), LensCommand::velocity(IRIS, 1.0), "pelco_d"), "pelco_d/iris is "
                                                                                                "false: this camera "
                                                                                                "has no iris to drive");
}

// Pelco-D's standard command: focus far is command 2's bit 7; focus near, iris open and close command 1's bits 0..2.
TEST(PelcoLens, LensBitsJoinTheMovementCommand)
{
  const auto hex = [](const pelco::Frame& frame) {
    const pelco::Bytes bytes = pelco::encode(frame);
    return hexText(bytes.data(), bytes.size());
  };
  EXPECT_EQ(hex(pelco::withLens(pelco::stop(1), 1, 0)), "FF 01 00 80 00 00 81");
  EXPECT_EQ(hex(pelco::withLens(pelco::stop(1), -1, 0)), "FF 01 01 00 00 00 02");
  EXPECT_EQ(hex(pelco::withLens(pelco::stop(1), 0, 1)), "FF 01 02 00 00 00 03");
  EXPECT_EQ(hex(pelco::withLens(pelco::stop(1), 0, -1)), "FF 01 04 00 00 00 05");
  // Beside a pan right at 0x20 (the spec's golden frame FF 01 00 02 20 00 23): the drive goes on.
  EXPECT_EQ(hex(pelco::withLens(pelco::move(1, 0x20, 0, 0), 1, -1)), "FF 01 04 82 20 00 A7");
  EXPECT_EQ(hex(pelco::withLens(pelco::withLens(pelco::move(1, 0x20, 0, 0), 1, -1), 0, 0)), "FF 01 00 02 20 00 23");
}

class PelcoLensTest : public ::testing::Test
{
protected:
  void SetUp() override
  {
    PelcoDEmulatorConfig emulator_config;
    emulator_config.port.link = uniqueLink("pelco_lens");
    emulator_config.lens.iris.present = false;  // a camera without iris control
    emulator_ = std::make_unique<PelcoDEmulator>(emulator_config);
    DeviceConfig<PelcoProtocol> config;
    config.link = serialLink(emulator_config.port.link, 9600);
    config.session.state_timeout = LINE_TEST_STATE_TIMEOUT;
    config.settings.iris = false;
    backend_ = makeDeviceBackend<PelcoProtocol>(config);
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT));
    commander_ = std::make_unique<LensCommander>(*backend_, backend_->capabilities().lens, "pelco_d", 0.5);
  }

  bool received(const std::string& hex) const
  {
    return emulator_->received().waitFor(
        [&hex](const ReceivedFrame& item) {
          const pelco::Bytes bytes = pelco::encode(item.frame);
          return hexText(bytes.data(), bytes.size()) == hex;
        },
        WAIT);
  }

  std::unique_ptr<PelcoDEmulator> emulator_;
  std::unique_ptr<DeviceBackend> backend_;
  std::unique_ptr<LensCommander> commander_;
};

TEST_F(PelcoLensTest, FocusFarAndNearAreTheMovementCommandsBits)
{
  const LensCapabilities lens = backend_->capabilities().lens;
  EXPECT_TRUE(lens.focus.present && lens.focus.velocity);
  EXPECT_FALSE(lens.focus.absolute || lens.focus.auto_mode || lens.focus.feedback);
  const double from = emulator_->lensState().positionOf(FOCUS);
  ASSERT_EQ(commander_->command(LensCommand::velocity(FOCUS, 0.3), SteadyClock::now()), "");
  ASSERT_TRUE(received("FF 01 00 80 00 00 81"));
  ASSERT_TRUE(waitUntil([&] { return emulator_->lensState().positionOf(FOCUS) > from + 0.05; }, WAIT));
  ASSERT_EQ(commander_->command(LensCommand::velocity(FOCUS, -0.3), SteadyClock::now()), "");
  ASSERT_TRUE(received("FF 01 01 00 00 00 02"));
  // The stream stops: the dead-man sends the movement command without lens bits, and the focus stays.
  emulator_->received().clear();
  ASSERT_TRUE(waitUntil([&] { return !commander_->expire(SteadyClock::now()).empty(); }, WAIT));
  ASSERT_TRUE(received("FF 01 00 00 00 00 01"));
  double stopped = -1.0;
  ASSERT_TRUE(waitUntil(
      [&] {
        const double before = emulator_->lensState().positionOf(FOCUS);
        const std::size_t seen = emulator_->received().items().size();
        emulator_->received().waitForCount(seen + 2, WAIT);  // some polls later
        stopped = emulator_->lensState().positionOf(FOCUS);
        return stopped == before;
      },
      WAIT));
  EXPECT_GT(stopped, 0.0);  // stopped on the way, not at the near end
}

TEST_F(PelcoLensTest, AFocusDriveLeavesAPanDriveRunning)
{
  backend_->moveAtVelocity({ 0.5, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return emulator_->sample().velocity[PAN] > 0.4; }, WAIT));
  ASSERT_EQ(commander_->command(LensCommand::velocity(FOCUS, 1.0), SteadyClock::now()), "");
  ASSERT_TRUE(emulator_->received().waitFor(
      [](const ReceivedFrame& item) { return (item.frame.command2 & (pelco::FOCUS_FAR | pelco::RIGHT)) == 0x82; },
      WAIT));
  EXPECT_GT(emulator_->sample().velocity[PAN], 0.4);
  backend_->stop();
}

TEST_F(PelcoLensTest, NoIrisIsRefusedAndNothingIsSent)
{
  emulator_->received().clear();
  const std::string refusal = commander_->command(LensCommand::velocity(IRIS, 1.0), SteadyClock::now());
  EXPECT_EQ(refusal, "pelco_d/iris is false: this camera has no iris to drive");
  ASSERT_TRUE(emulator_->received().waitForCount(6, WAIT));
  for (const ReceivedFrame& item : emulator_->received().items())
  {
    EXPECT_EQ(item.frame.command1, 0);  // queries only: no lens bit
    EXPECT_TRUE(item.frame.command2 == pelco::QUERY_PAN || item.frame.command2 == pelco::QUERY_TILT ||
                item.frame.command2 == pelco::QUERY_ZOOM);
  }
}
}  // namespace
