/**
 * \file
 * \brief Focus and iris in the core: the check of a lens command against what a device has, the simulated lens, the
 * commander's velocity stream and dead-man (the devices' own words: test_visca_lens.cpp, test_pelco_d_lens.cpp).
 */
#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "ptz_action_server/core/lens.h"
#include "ptz_action_server/core/lens_commander.h"
#include "ptz_action_server/core/sim/sim_backend.h"
#include "ptz_action_server/core/sim/sim_lens_model.h"

using namespace ptz_action_server;

namespace
{
constexpr LensFunction FOCUS = LensFunction::FOCUS;
constexpr LensFunction IRIS = LensFunction::IRIS;

TEST(LensCheck, ADeviceWithoutFocusRefusesEveryFocusCommandAndSaysWhy)
{
  const LensCapabilities none;  // what every backend declares unless it drives a lens
  for (const LensCommand& command : { LensCommand::velocity(FOCUS, 0.5), LensCommand::position(FOCUS, 0.5),
                                      LensCommand::mode(FOCUS, true), LensCommand::onePush() })
  {
    EXPECT_EQ(checkLensCommand(none, command, "flir"), "the 'flir' backend drives no focus") << describe(command);
  }
  EXPECT_EQ(describeLens(none, IRIS, "flir"), "none (the 'flir' backend drives no iris)");
}

TEST(LensCheck, ValuesOutsideTheirRangesAreRefused)
{
  const LensCapabilities sim = simLensCapabilities(SimLensConfig());
  EXPECT_EQ(checkLensCommand(sim, LensCommand::velocity(FOCUS, 1.0), "sim"), "");
  EXPECT_EQ(checkLensCommand(sim, LensCommand::position(IRIS, 0.0), "sim"), "");
  EXPECT_NE(checkLensCommand(sim, LensCommand::velocity(FOCUS, 1.5), "sim"), "");
  EXPECT_NE(checkLensCommand(sim, LensCommand::velocity(IRIS, std::nan("")), "sim"), "");
  EXPECT_NE(checkLensCommand(sim, LensCommand::position(FOCUS, -0.1), "sim"), "");
  EXPECT_NE(checkLensCommand(sim, LensCommand::position(FOCUS, std::nan("")), "sim"), "");
}

TEST(SimLens, DrivesAtItsSpeedGoesToPositionsAndSettlesByItselfInAuto)
{
  SimLensConfig config;
  config.focus.travel_time = 2.0;  // end to end at full speed
  const TimePoint start{};
  SimLensModel lens(config, start);
  EXPECT_TRUE(lens.isAuto(FOCUS));
  EXPECT_DOUBLE_EQ(lens.position(FOCUS, addSeconds(start, 10.0)), config.focus.auto_value);
  const TimePoint t0 = addSeconds(start, 10.0);
  lens.setAuto(FOCUS, false, t0);
  lens.drive(FOCUS, -0.5, t0);  // near, half speed: a quarter of the range a second
  EXPECT_NEAR(lens.position(FOCUS, addSeconds(t0, 1.0)), config.focus.auto_value - 0.25, 1e-9);
  EXPECT_DOUBLE_EQ(lens.position(FOCUS, addSeconds(t0, 100.0)), 0.0);  // held at the near end
  lens.goTo(FOCUS, 0.9, addSeconds(t0, 100.0));
  EXPECT_TRUE(lens.moving(FOCUS, addSeconds(t0, 100.5)));
  EXPECT_DOUBLE_EQ(lens.position(FOCUS, addSeconds(t0, 103.0)), 0.9);
  EXPECT_FALSE(lens.isAuto(FOCUS));
}

TEST(LensCommander, AStreamSendsEachNewVelocityOnceAndStopsWhenItStops)
{
  auto clock = std::make_shared<ManualClock>();
  SimBackend backend(SimDeviceConfig::defaults(), clock);
  LensCommander commander(backend, backend.capabilities().lens, "sim", 0.5);
  EXPECT_EQ(commander.command(LensCommand::velocity(FOCUS, 1.0), clock->now()), "");
  EXPECT_EQ(backend.lensState().modeOf(FOCUS), LensMode::MANUAL);
  const double from = backend.lensState().positionOf(FOCUS);
  clock->advance(0.3);
  EXPECT_EQ(commander.command(LensCommand::velocity(FOCUS, 1.0), clock->now()), "");  // renewed
  EXPECT_TRUE(commander.expire(clock->now()).empty());
  clock->advance(0.3);
  EXPECT_TRUE(commander.expire(clock->now()).empty());  // 0.3 s since the renewal
  clock->advance(0.3);
  EXPECT_EQ(commander.expire(clock->now()), std::vector<LensFunction>{ FOCUS });
  EXPECT_EQ(commander.nextDeadline(), TimePoint::max());
  const double stopped_at = backend.lensState().positionOf(FOCUS);
  EXPECT_GT(stopped_at, from);  // it drove far (positive) for 0.9 s
  clock->advance(1.0);
  EXPECT_DOUBLE_EQ(backend.lensState().positionOf(FOCUS), stopped_at);  // and stays there
}

TEST(LensCommander, ARefusedCommandReachesNoDevice)
{
  auto clock = std::make_shared<ManualClock>();
  SimLensConfig no_iris;
  no_iris.iris.present = false;
  SimBackend backend(SimDeviceConfig::defaults(), clock, no_iris);
  LensCommander commander(backend, backend.capabilities().lens, "sim", 0.5);
  const std::string refusal = commander.command(LensCommand::position(IRIS, 0.2), clock->now());
  EXPECT_EQ(refusal, "the simulated lens is configured without iris");
  EXPECT_EQ(commander.nextDeadline(), TimePoint::max());
  EXPECT_EQ(backend.lensState().modeOf(IRIS), LensMode::UNKNOWN);
  EXPECT_NE(commander.command(LensCommand::velocity(FOCUS, 2.0), clock->now()), "");
  EXPECT_EQ(backend.lensState().modeOf(FOCUS), LensMode::AUTO);  // untouched
}

}  // namespace
