/**
 * \file
 * \brief A slow position goal on each protocol's emulator: the speed reaches the device that takes one (the emulator
 * records it and moves at it), and the node shapes the motion of the others; judged on the device's own motion.
 */
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "harness/device_harness.h"
#include "ptz_action_server/core/speed_shaping_backend.h"
#include "wait_until.h"

namespace ptz_action_server
{
namespace
{
/// Each protocol's first harness, by plugin name.
const HarnessEntry* firstHarness(const std::string& plugin)
{
  for (const HarnessEntry& entry : allHarnesses())
  {
    if (entry.plugin == plugin && entry.start)
    {
      return &entry;
    }
  }
  return nullptr;
}

/// The device's stamp when its pan first got \p share of the way from \p from to \p to.
TimePoint passed(const std::vector<PtzSample>& samples, double from, double to, double share)
{
  const double mark = from + share * (to - from);
  for (const PtzSample& sample : samples)
  {
    if ((to - from) * (sample.position[PAN] - mark) >= 0.0)
    {
      return sample.stamp;
    }
  }
  return TimePoint::max();
}

/// How each protocol's device takes a position goal's speed (doc/operator-controls.md, "Per device"): DEVICE where
/// its absolute move carries one (PanTilt: the motor-speed params before the move), NODE where the node shapes it
/// (MAVLink: the managers in the field do not read a rate beside an angle as a speed, doc/backends/mavlink_gimbal.md).
SpeedControl expectedControl(const std::string& plugin)
{
  // The emulated ONVIF camera lists GenericSpeedSpace: the speed goes with AbsoluteMove's Speed.
  const bool device =
      plugin == "visca" || plugin == "axis" || plugin == "flir" || plugin == "pantilt" || plugin == "onvif";
  return device ? SpeedControl::DEVICE : SpeedControl::NODE;
}

class MoveSpeedDevices : public ::testing::TestWithParam<std::string>
{
};

TEST_P(MoveSpeedDevices, ASlowGoalMovesTheDeviceAtItsSpeed)
{
  const HarnessEntry* entry = firstHarness(GetParam());
  ASSERT_NE(entry, nullptr) << "no harness for " << GetParam();
  const std::unique_ptr<DeviceHarness> harness = entry->start("");
  // Shaped by the node where the device takes no speed, as the node runs it; unchanged where it takes one.
  auto backend = std::make_shared<SpeedShapingBackend>(std::shared_ptr<PtzBackend>(harness->makeBackend()));
  backend->start();
  ASSERT_TRUE(waitUntil([&] { return backend->sample().link_up && harness->startupReceived(); }, 20.0));
  const Capabilities capabilities = backend->capabilities();
  const AxisCapability& pan = capabilities.axes[PAN];
  if (!pan.present || !pan.absolute || !pan.feedback)
  {
    GTEST_SKIP() << GetParam() << " takes no pan position goals here";
  }
  const SpeedControl control = capabilities.speed.control[PAN];
  ASSERT_EQ(control, expectedControl(GetParam())) << static_cast<int>(control);
  const PtzSample start = backend->sample();
  const double from = harness->deviceState().position[PAN];
  const double to = std::clamp(from + 0.4, pan.range.min + 0.05, pan.range.max - 0.05);
  const double speed = std::max(0.25 * pan.max_speed, 2.0 * capabilities.speed.min_speed[PAN]);
  AxisValues target = start.position;
  target[PAN] = to;
  harness->clearCommands();
  backend->goToAtSpeed(target, { { speed, 0.0, 0.0 } });

  std::vector<PtzSample> motion;  // the emulator's own state, on its own clock
  ASSERT_TRUE(waitUntil(
      [&] {
        motion.push_back(harness->deviceState());
        return std::abs(motion.back().position[PAN] - to) < 0.01 && !backend->shaping();
      },
      30.0 + 8.0 * std::abs(to - from) / speed));
  double commanded = speed;
  if (control == SpeedControl::DEVICE)
  {
    // The emulator read a speed with the move, the device's nearest step to the goal's.
    double recorded = 0.0;
    for (const ClassifiedCommand& command : harness->commands())
    {
      recorded =
          command.kind == ClassifiedCommand::Kind::MOVE && command.pan_speed > 0.0 ? command.pan_speed : recorded;
    }
    ASSERT_GT(recorded, 0.0) << "no speed reached the device";
    EXPECT_NEAR(recorded, speed, 0.35 * speed);
    EXPECT_FALSE(backend->shaping());
    commanded = recorded;
  }
  // From a fifth to four fifths of the way, the device moved at about the speed: not at its own top speed.
  const double seconds = secondsBetween(passed(motion, from, to, 0.2), passed(motion, from, to, 0.8));
  const double average = 0.6 * std::abs(to - from) / seconds;
  EXPECT_LT(average, commanded * 1.3) << "the device outran the goal's speed (its own is " << pan.max_speed << ")";
  EXPECT_GT(average, commanded * 0.3);
}

INSTANTIATE_TEST_SUITE_P(Protocols, MoveSpeedDevices,
                         ::testing::Values("visca", "pelco_d", "axis", "onvif", "flir", "mavlink_gimbal", "pantilt",
                                           "digiview"),
                         [](const ::testing::TestParamInfo<std::string>& info) { return info.param; });

}  // namespace
}  // namespace ptz_action_server
