#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <vector>

#include "ptz_action_server/core/goal/move_speed.h"
#include "ptz_action_server/core/sim/sim_backend.h"
#include "ptz_action_server/core/speed_shaping_backend.h"
#include "wait_until.h"

using namespace ptz_action_server;

namespace
{
Capabilities deviceLimits()
{
  Capabilities limits = SimDeviceConfig::defaults().capabilities();  // pan 1.5, tilt 1.0 rad/s, zoom 8 X/s
  limits.speed.min_speed = { { 0.05, 0.05, 0.0 } };
  return limits;
}

/// The sim seen as a device that takes no speed with its moves: the node has to shape them.
class SpeedlessBackend : public ForwardingBackend
{
public:
  using ForwardingBackend::ForwardingBackend;
  Capabilities capabilities() const override
  {
    Capabilities capabilities = inner().capabilities();
    capabilities.speed = MoveSpeedCapability{};
    return capabilities;
  }
  void goToAtSpeed(const AxisValues& position, const AxisValues&) override
  {
    inner().goTo(position);
  }
};

/// The first stamp at which the pan of \p samples reaches \p pan (they rise).
TimePoint reached(const std::vector<PtzSample>& samples, double pan)
{
  for (const PtzSample& sample : samples)
  {
    if (sample.position[PAN] >= pan)
    {
      return sample.stamp;
    }
  }
  return TimePoint::max();
}
}  // namespace

TEST(ResolveSpeed, AFractionOfEachAxisTopSpeed)
{
  const ResolvedSpeed resolved = resolveSpeed({ 0.5, {} }, FULL_SPEED, deviceLimits());
  ASSERT_TRUE(resolved.accepted);
  EXPECT_DOUBLE_EQ(resolved.speed[PAN], 0.75);
  EXPECT_DOUBLE_EQ(resolved.speed[TILT], 0.5);
  EXPECT_DOUBLE_EQ(resolved.speed[ZOOM], 4.0);
  EXPECT_TRUE(resolved.message.empty()) << resolved.message;
}

TEST(ResolveSpeed, NoSpeedIsTheOperatorsDefaultAndTheTopSpeedIsTheDevicesOwn)
{
  EXPECT_DOUBLE_EQ(resolveSpeed({}, 0.2, deviceLimits()).speed[PAN], 0.3);
  const ResolvedSpeed full = resolveSpeed({}, FULL_SPEED, deviceLimits());
  EXPECT_FALSE(asksSpeed(full.speed));  // a goal as before speeds existed: goTo()
}

TEST(ResolveSpeed, RatesOverrideTheFractionAndAreClampedOrRaisedWithANote)
{
  const ResolvedSpeed fast = resolveSpeed({ 0.5, { { 9.0, 0.2, 0.0 } } }, FULL_SPEED, deviceLimits());
  ASSERT_TRUE(fast.accepted);
  EXPECT_DOUBLE_EQ(fast.speed[PAN], 0.0);  // clamped to the top: the device's own speed
  EXPECT_DOUBLE_EQ(fast.speed[TILT], 0.2);
  EXPECT_DOUBLE_EQ(fast.speed[ZOOM], 4.0);
  EXPECT_NE(fast.message.find("pan speed 9 rad/s clamped"), std::string::npos) << fast.message;
  const ResolvedSpeed slow = resolveSpeed({ 0.0, { { 0.01, 0.0, 0.0 } } }, FULL_SPEED, deviceLimits());
  EXPECT_DOUBLE_EQ(slow.speed[PAN], 0.05);
  EXPECT_NE(slow.message.find("raised to the device's slowest"), std::string::npos) << slow.message;
}

TEST(ResolveSpeed, RefusesWhatIsNoSpeed)
{
  EXPECT_FALSE(resolveSpeed({ std::nan(""), {} }, FULL_SPEED, deviceLimits()).accepted);
  EXPECT_FALSE(resolveSpeed({ -0.5, {} }, FULL_SPEED, deviceLimits()).accepted);
  const ResolvedSpeed negative = resolveSpeed({ 0.0, { { 0.0, -1.0, 0.0 } } }, FULL_SPEED, deviceLimits());
  EXPECT_FALSE(negative.accepted);
  EXPECT_NE(negative.message.find("tilt speed"), std::string::npos) << negative.message;
  EXPECT_FALSE(checkDefaultSpeed(0.0).empty());
  EXPECT_FALSE(checkDefaultSpeed(1.5).empty());
  EXPECT_TRUE(checkDefaultSpeed(0.3).empty());
}

TEST(ResolveSpeed, AnAxisAtItsOwnSpeedGetsNone)
{
  Capabilities limits = deviceLimits();
  limits.speed.control[ZOOM] = SpeedControl::OWN;
  EXPECT_DOUBLE_EQ(resolveSpeed({ 0.5, {} }, FULL_SPEED, limits).speed[ZOOM], 0.0);
}

TEST(SimSpeed, APositionMoveCruisesAtItsSpeedOnTheDevicesClock)
{
  const auto clock = std::make_shared<ManualClock>();
  SimBackend backend(SimDeviceConfig::defaults(), clock);
  backend.start();
  EXPECT_EQ(backend.capabilities().speed.control[PAN], SpeedControl::DEVICE);
  backend.goToAtSpeed({ 1.0, 0.0, 1.0 }, { { 0.25, 0.0, 0.0 } });
  clock->advance(2.0);
  EXPECT_NEAR(backend.sample().velocity[PAN], 0.25, 1e-9);  // cruising, not at its 1.5 rad/s
  // 1 rad at 0.25 rad/s: 4 s and the short ramps (3 rad/s^2), not the 0.7 s of the top speed.
  clock->advance(1.8);
  EXPECT_TRUE(backend.sample().moving);
  clock->advance(0.4);
  EXPECT_FALSE(backend.sample().moving);
  EXPECT_NEAR(backend.sample().position[PAN], 1.0, 1e-3);
  // The next move without a speed runs at the top speed again.
  backend.goTo({ 0.0, 0.0, 1.0 });
  clock->advance(0.6);  // past the 0.5 s ramp
  EXPECT_NEAR(std::abs(backend.sample().velocity[PAN]), 1.5, 1e-9);
}

TEST(SpeedShaping, PassesTheSpeedToABackendThatAppliesIt)
{
  auto sim = std::make_shared<SimBackend>(SimDeviceConfig::defaults(), std::make_shared<ManualClock>());
  SpeedShapingBackend shaping(sim);
  shaping.start();
  EXPECT_EQ(shaping.capabilities().speed.control[PAN], SpeedControl::DEVICE);
  shaping.goToAtSpeed({ 1.0, 0.0, 1.0 }, { { 0.25, 0.0, 0.0 } });
  EXPECT_FALSE(shaping.shaping());
}

TEST(SpeedShaping, StreamsASlowMoveOnADeviceThatTakesNoSpeed)
{
  auto device = std::make_shared<SpeedlessBackend>(std::make_shared<SimBackend>(SimDeviceConfig::defaults()));
  SpeedShapingBackend shaping(device, 0.05);
  shaping.start();
  const Capabilities capabilities = shaping.capabilities();
  EXPECT_EQ(capabilities.speed.control[PAN], SpeedControl::NODE);
  EXPECT_NEAR(capabilities.speed.min_speed[PAN], SpeedShapingBackend::MIN_SHAPED_SHARE * 1.5, 1e-12);

  constexpr double SPEED = 0.3;  // rad/s, a fifth of the device's 1.5
  shaping.goToAtSpeed({ 0.6, 0.0, 1.0 }, { { SPEED, 0.0, 0.0 } });
  EXPECT_TRUE(shaping.shaping());
  std::vector<PtzSample> samples;
  ASSERT_TRUE(waitUntil(
      [&] {
        samples.push_back(shaping.sample());
        return !shaping.shaping() && !samples.back().moving && samples.back().position[PAN] > 0.59;
      },
      30.0));
  // The device's own stamps: from 0.1 to 0.5 rad it went at the goal's speed on average, not its own 1.5 rad/s.
  const double seconds = secondsBetween(reached(samples, 0.1), reached(samples, 0.5));
  // No upper bound: on a busy machine the stream's steps may come late, which is wall-clock speed, not behaviour.
  EXPECT_GT(seconds, 0.4 / SPEED * 0.75) << "the device outran the shaped speed";
  std::vector<DiagnosticValue> values;
  shaping.diagnostics(values);
  bool counted = false;
  for (const DiagnosticValue& value : values)
  {
    counted = counted || (value.first == "speed: moves shaped by the node" && value.second == "1");
  }
  EXPECT_TRUE(counted);
}

TEST(SpeedShaping, AnotherCommandEndsTheStream)
{
  auto device = std::make_shared<SpeedlessBackend>(std::make_shared<SimBackend>(SimDeviceConfig::defaults()));
  SpeedShapingBackend shaping(device, 0.05);
  shaping.start();
  shaping.goToAtSpeed({ 2.0, 0.0, 1.0 }, { { 0.1, 0.0, 0.0 } });
  ASSERT_TRUE(shaping.shaping());
  shaping.stop();
  EXPECT_FALSE(shaping.shaping());
  ASSERT_TRUE(waitUntil([&] { return !shaping.sample().moving; }, 10.0));
  const double rest = shaping.sample().position[PAN];
  EXPECT_LT(rest, 1.0);  // stopped on the way, not sent on to the target
  // Nothing more is streamed after the stop: the device stays where it came to rest.
  EXPECT_FALSE(waitUntil([&] { return shaping.sample().position[PAN] > rest + 0.01; }, 0.3));
}
