/**
 * \file
 * \brief The backend contract suite: goals, preemption, cancel, velocity, refusals, and the axes a device has or lacks
 * (the fixture: device_contract.h).
 */
#include "device_contract.h"

namespace ptz_action_server
{
namespace
{
TEST_P(DeviceContract, AGoalArrivesAsTheProtocolsCommandsAndIsReached)
{
  harness_->clearCommands();
  const AxisValues target = device_->goal(0.5, -0.2);
  backend_->goTo(target);
  ASSERT_TRUE(waitForRest(target)) << "pan " << backend_->sample().position[PAN] << ", tilt "
                                   << backend_->sample().position[TILT] << "; sent " << describe(harness_->commands());
  // A loss (a busy machine starving the I/O threads) adds the recovery's hold: say so if the commands differ.
  SCOPED_TRACE("link losses: " + std::to_string(backend_->sample().link_losses) +
               ", the last: " + backend_->lastLinkLoss() +
               "; impossible states: " + std::to_string(backend_->session().counters().impossible_states.value()));
  device_->expectGoalCommands(harness_->commands(), target);
  // The signs held end to end: the device itself is where the contract says.
  EXPECT_NEAR(harness_->deviceState().position[PAN], target[PAN], 2e-3);
  EXPECT_NEAR(harness_->deviceState().position[TILT], target[TILT], 2e-3);
  EXPECT_EQ(backend_->sample().fault_count, 0u);
}

TEST_P(DeviceContract, ANewGoalRetargetsTheMovingDeviceWithoutAStop)
{
  backend_->goTo(device_->goal(2.0, 0.0));
  ASSERT_TRUE(waitUntil([&] { return harness_->deviceState().position[PAN] > 0.5; }, WAIT));
  harness_->clearCommands();
  const AxisValues second = device_->goal(2.5, 0.0);
  backend_->goTo(second);
  // Until well before it brakes for the new target, the device never slows down as a stop would make it.
  double slowest = 1e9;
  ASSERT_TRUE(waitUntil(
      [&] {
        const PtzSample state = harness_->deviceState();
        slowest = std::min(slowest, state.velocity[PAN]);
        return state.position[PAN] > 1.5;
      },
      WAIT));
  EXPECT_GT(slowest, 0.3) << "the device slowed to " << slowest << " rad/s";
  ASSERT_TRUE(waitForRest(second));
  for (const ClassifiedCommand& command : harness_->commands())
  {
    EXPECT_NE(command.kind, ClassifiedCommand::Kind::STOP) << describe(harness_->commands());
  }
}

TEST_P(DeviceContract, CancelDeceleratesTheDeviceToRest)
{
  const AxisValues far = startLongGoal();
  harness_->clearCommands();
  const double at_cancel = harness_->deviceState().position[PAN];
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return device_->holds(harness_->commands(), far) > 0; }, WAIT))
      << describe(harness_->commands());
  ASSERT_TRUE(waitUntil([&] { return !harness_->deviceState().moving; }, WAIT));
  const double stopped = harness_->deviceState().position[PAN];
  EXPECT_GT(stopped, at_cancel);       // it braked on: it did not jump back,
  EXPECT_LT(stopped, far[PAN] - 0.2);  // and it did not go on to the target
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, WAIT));
}

TEST_P(DeviceContract, AVelocityGoalMovesAtTheRateUntilStopped)
{
  backend_->moveAtVelocity({ 0.3, 0.0, 0.0 });
  ASSERT_TRUE(waitUntil([&] { return std::abs(harness_->deviceState().velocity[PAN] - 0.3) < 0.05; }, WAIT))
      << harness_->deviceState().velocity[PAN];
  ASSERT_TRUE(waitUntil([&] { return std::abs(backend_->sample().velocity[PAN] - 0.3) < 0.08; }, WAIT))
      << backend_->sample().velocity[PAN];
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !harness_->deviceState().moving && !backend_->sample().moving; }, WAIT));
}

TEST_P(DeviceContract, ARefusedCommandAbortsTheGoalWithTheDevicesWords)
{
  AxisValues refused{};
  const std::string words = device_->prepareRefusal(refused);
  if (words.empty())
  {
    GTEST_SKIP() << "this protocol has no error replies";
  }
  GoalMonitor monitor = monitorFor(refused);
  backend_->goTo(refused);
  const GoalVerdict verdict = superviseUntilFinal(monitor);
  EXPECT_EQ(verdict.phase, GoalPhase::ABORTED) << verdict.reason;
  EXPECT_TRUE(verdict.device_fault) << verdict.reason;
  EXPECT_NE(backend_->lastFault().find(words), std::string::npos) << backend_->lastFault();
}

TEST_P(DeviceContract, ADeviceThatIgnoresAnAxisNeverGetsASucceededForIt)
{
  const Capabilities capabilities = backend_->capabilities();
  // An axis the device lacks (or cannot report): a goal that asks it to move is refused, naming it; but a zoom it
  // lacks is ignored (the seed's rule: ZoomOfADeviceWithoutZoomIsIgnored).
  for (Axis axis : ALL_AXES)
  {
    const AxisCapability& capability = capabilities.axes[axis];
    if (axis == ZOOM && !capability.present)
    {
      continue;
    }
    if (!capability.present || !capability.feedback || !capability.absolute)
    {
      AxisValues target = device_->goal(0.2, 0.1);
      target[axis] = axis == ZOOM ? 4.0 : 0.3;
      const std::string end = runGoalToItsEnd(*backend_, target, 1.0);
      EXPECT_EQ(end.rfind("REJECTED: ", 0), 0u) << axisName(axis) << ": " << end;
      EXPECT_NE(end.find(std::string(axisName(axis)) + " goals are not supported"), std::string::npos) << end;
    }
  }
  // An axis the device has but silently ignores: never reported reached.
  std::vector<Axis> axes = { PAN };
  if (capabilities.axes[ZOOM].present && capabilities.axes[ZOOM].feedback && capabilities.axes[ZOOM].absolute)
  {
    axes.push_back(ZOOM);
  }
  for (Axis axis : axes)
  {
    device_->ignoreAxis(axis, true);
    const PtzSample before = backend_->sample();
    AxisValues target = device_->goal(before.position[PAN] + 0.4, before.position[TILT]);
    if (axis == ZOOM)
    {
      target[ZOOM] = before.position[ZOOM] < 2.0 ? 3.0 : 1.0;
    }
    const std::string end = runGoalToItsEnd(*backend_, target, 1.0);
    EXPECT_EQ(end.rfind("ABORTED: stalled: " + std::string(axisName(axis)), 0), 0u) << axisName(axis) << ": " << end;
    device_->ignoreAxis(axis, false);
    EXPECT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, WAIT));
  }
}

TEST_P(DeviceContract, ZoomOfADeviceWithoutZoomIsIgnored)
{
  const AxisCapability zoom = backend_->capabilities().axes[ZOOM];
  if (zoom.present)
  {
    GTEST_SKIP() << "this device has a zoom";
  }
  // The seed: "if the camera does not support zoom (e.g. the Flir D46 PTU), the zoom field is ignored". A goal with
  // zoom 2 is judged on pan and tilt, and its text says the zoom was ignored, in the device's words.
  AxisValues target = device_->goal(0.5, 0.1);
  target[ZOOM] = 2.0;
  const std::string end = runGoalToItsEnd(*backend_, target, 1.0);
  EXPECT_EQ(end.rfind("SUCCEEDED: ", 0), 0u) << end;
  const std::string words = zoom.limitation.empty() ? "the device has no zoom" : zoom.limitation;
  EXPECT_NE(end.find("zoom 2.0000 X ignored: " + words), std::string::npos) << end;
  const double tolerance = GoalMonitorConfig().tolerance[PAN] + 1e-3;  // what SUCCEEDED vouches for
  EXPECT_NEAR(harness_->deviceState().position[PAN], target[PAN], tolerance);
  EXPECT_NEAR(harness_->deviceState().position[TILT], target[TILT], tolerance);
}

INSTANTIATE_TEST_SUITE_P(Devices, DeviceContract, ::testing::ValuesIn(allDeviceFixtures()),
                         [](const ::testing::TestParamInfo<FixtureMaker>& info) { return info.param.name; });

}  // namespace
}  // namespace ptz_action_server
