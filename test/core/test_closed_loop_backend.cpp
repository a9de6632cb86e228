#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <memory>
#include <thread>

#include "goal_supervisor_fixture.h"
#include "ptz_action_server/core/closed_loop_backend.h"
#include "ptz_action_server/core/goal/goal_monitor.h"
#include "ptz_action_server/core/onvif/onvif_protocol.h"
#include "ptz_action_server/core/sim/sim_backend.h"
#include "ptz_action_server/core/timed_steering.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"
#include "wait_until.h"

using namespace ptz_action_server;

namespace
{
constexpr double WAIT = 20.0;  ///< s: generous, for a loaded machine

/**
 * A camera that only moves at a speed (ContinuousMove only) and is polled for its position every 50 ms, as a
 * DeviceSession polls one: the simulated device underneath, its pan and tilt declared without `absolute`, and every
 * goTo() that reaches it counted (a real camera of the kind would refuse it).
 */
class ContinuousOnlyCamera : public ForwardingBackend
{
public:
  explicit ContinuousOnlyCamera(bool absolute = false)
    : ForwardingBackend(std::make_shared<SimBackend>(SimDeviceConfig::defaults())), absolute_(absolute)
  {
  }
  ~ContinuousOnlyCamera() override
  {
    running_ = false;
    if (poller_.joinable())
    {
      poller_.join();
    }
  }
  Capabilities capabilities() const override
  {
    Capabilities capabilities = inner().capabilities();
    for (Axis axis : ALL_AXES)
    {
      capabilities.axes[axis].absolute = absolute_;
      capabilities.axes[axis].limitation = absolute_ ? "" : "this camera takes no AbsoluteMove";
    }
    return capabilities;
  }
  bool setSampleListener(SampleListener listener) override
  {
    listener_ = std::move(listener);
    return true;
  }
  void start() override
  {
    inner().start();
    poller_ = std::thread([this] {
      while (running_)
      {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        if (listener_)  // as a DeviceSession: after each report, and when the link is lost
        {
          listener_();
        }
      }
    });
  }
  void goTo(const AxisValues& position) override
  {
    ++positions_;
    if (absolute_)
    {
      inner().goTo(position);
    }
  }
  void moveAtVelocity(const AxisValues& velocity) override
  {
    ++velocities_;
    inner().moveAtVelocity(velocity);
  }
  void stop() override
  {
    ++stops_;
    inner().stop();
  }
  SimBackend& device()
  {
    return static_cast<SimBackend&>(inner());
  }

  std::atomic<int> positions_{ 0 };
  std::atomic<int> velocities_{ 0 };
  std::atomic<int> stops_{ 0 };

private:
  const bool absolute_;
  SampleListener listener_;
  std::atomic<bool> running_{ true };
  std::thread poller_;
};

class ClosedLoopBackendTest : public ::testing::Test
{
protected:
  void startWith(bool absolute)
  {
    camera_ = std::make_shared<ContinuousOnlyCamera>(absolute);
    backend_ = std::make_unique<ClosedLoopBackend>(camera_, config_);
    ASSERT_TRUE(backend_->setSampleListener([this] { ++reports_; }));
    backend_->start();
  }

  bool restsAt(const AxisValues& target, double slack) const
  {
    const PtzSample sample = backend_->sample();
    return !sample.moving && std::abs(sample.position[PAN] - target[PAN]) <= slack &&
           std::abs(sample.position[TILT] - target[TILT]) <= slack;
  }

  ClosedLoopConfig config_;
  std::shared_ptr<ContinuousOnlyCamera> camera_;
  std::unique_ptr<ClosedLoopBackend> backend_;
  std::atomic<int> reports_{ 0 };
};
}  // namespace

TEST_F(ClosedLoopBackendTest, APositionGoalIsReachedThroughSpeedsAloneAndJudgedAsOnAnyDevice)
{
  startWith(false);
  EXPECT_TRUE(backend_->steers());
  const Capabilities capabilities = backend_->capabilities();
  EXPECT_TRUE(capabilities.axes[PAN].absolute);
  EXPECT_TRUE(capabilities.axes[TILT].absolute);
  EXPECT_TRUE(capabilities.axes[PAN].limitation.empty()) << capabilities.axes[PAN].limitation;

  const AxisValues target{ { 0.8, -0.3, std::nan("") } };
  backend_->goTo(target);
  // Within the node's default tolerance (0.005 rad), at rest, and never through an absolute move.
  ASSERT_TRUE(waitUntil([&] { return restsAt(target, GoalMonitorConfig().tolerance[PAN]); }, WAIT))
      << "pan " << backend_->sample().position[PAN] << ", tilt " << backend_->sample().position[TILT];
  EXPECT_EQ(camera_->positions_, 0);
  EXPECT_GT(camera_->velocities_, 0);
  EXPECT_GE(camera_->stops_, 1);
  EXPECT_GT(reports_, 0);  // the node's listener still hears every report
}

TEST_F(ClosedLoopBackendTest, TheZoomANaNLeavesAloneIsNotDriven)
{
  startWith(false);
  const double zoom_before = backend_->sample().position[ZOOM];
  backend_->goTo({ { -0.4, 0.2, std::nan("") } });
  ASSERT_TRUE(waitUntil([&] { return restsAt({ { -0.4, 0.2, 0.0 } }, 0.005); }, WAIT));
  EXPECT_DOUBLE_EQ(backend_->sample().position[ZOOM], zoom_before);
}

TEST_F(ClosedLoopBackendTest, AStopEndsTheSteeringAndTheDeviceStaysWhereItStopped)
{
  startWith(false);
  backend_->goTo({ { 2.5, 0.0, std::nan("") } });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().position[PAN] > 0.5; }, WAIT));
  backend_->stop();
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().moving; }, WAIT));
  const int commands = camera_->velocities_;
  const double stopped_at = backend_->sample().position[PAN];
  // Several reports later nothing has been commanded and the device has not moved on towards 2.5 rad.
  const int reports = reports_;
  ASSERT_TRUE(waitUntil([&] { return reports_ > reports + 5; }, WAIT));
  EXPECT_EQ(camera_->velocities_, commands);
  EXPECT_DOUBLE_EQ(backend_->sample().position[PAN], stopped_at);
  EXPECT_LT(stopped_at, 2.0);
}

TEST_F(ClosedLoopBackendTest, ALostLinkEndsTheSteeringForGood)
{
  startWith(false);
  backend_->goTo({ { 2.5, 0.0, std::nan("") } });
  ASSERT_TRUE(waitUntil([&] { return backend_->sample().position[PAN] > 0.5; }, WAIT));
  camera_->device().setFaults(SimFaults(), true);  // the device falls silent
  ASSERT_TRUE(waitUntil([&] { return !backend_->sample().link_up; }, WAIT));
  const int reports = reports_;
  camera_->device().setFaults(SimFaults(), false);  // and answers again
  ASSERT_TRUE(waitUntil([&] { return reports_ > reports + 5; }, WAIT));
  // The steering step that saw the link down ended the goal: nothing resumes it when the device is back.
  const int commands = camera_->velocities_;
  const int more_reports = reports_;
  ASSERT_TRUE(waitUntil([&] { return reports_ > more_reports + 5; }, WAIT));
  EXPECT_EQ(camera_->velocities_, commands);
}

TEST_F(ClosedLoopBackendTest, ADeviceThatGoesToPositionsItselfPassesThrough)
{
  startWith(true);
  EXPECT_FALSE(backend_->steers());
  backend_->goTo({ { 0.3, 0.1, 2.0 } });
  EXPECT_EQ(camera_->positions_, 1);
  ASSERT_TRUE(waitUntil([&] { return restsAt({ { 0.3, 0.1, 2.0 } }, 0.002); }, WAIT));
  EXPECT_EQ(camera_->velocities_, 0);
}

// ---------------------------------------------------------------- a real continuous-only camera

namespace
{
/// An ONVIF camera of the field that only takes ContinuousMove (emulated, over HTTP on 127.0.0.1), its backend
/// wrapped as the node wraps every device, and the node's goal supervisor on top.
class ClosedLoopOnvif : public ::testing::Test
{
protected:
  void start(const std::string& mode)
  {
    start(std::vector<std::string>{ mode });
  }
  /// The camera in \p modes, the node's goals judged with \p config (and steered to half its tolerance).
  void start(const std::vector<std::string>& modes, const GoalMonitorConfig& goal_config = GoalMonitorConfig())
  {
    goal_config_ = goal_config;
    OnvifCameraEmulatorConfig camera;
    for (const std::string& mode : modes)
    {
      ASSERT_TRUE(camera.applyMode(mode)) << mode;
    }
    camera_ = std::make_unique<OnvifCameraEmulator>(camera);
    DeviceConfig<OnvifProtocol> config;
    config.link.port = camera_->port();
    config.link.http.username = config.settings.username = camera.username;
    config.link.http.password = config.settings.password = camera.password;
    config.session.state_timeout = 1.0;
    device_ = std::shared_ptr<PtzBackend>(makeDeviceBackend<OnvifProtocol>(config));
    backend_ = withClosedLoop(device_, goal_config.tolerance);
    backend_->setSampleListener([] {});
    backend_->start();
  }

  /// Runs a position goal as the node would, to its end; returns "SUCCEEDED: ..." or the like.
  std::string run(const AxisValues& target)
  {
    return goal_supervisor_test::runGoalToItsEnd(
        backend_, goal_supervisor_test::positionGoal(target[PAN], target[TILT], target[ZOOM]), goal_config_, WAIT);
  }

  std::size_t absoluteMoves() const
  {
    std::size_t count = 0;
    for (const HttpExchange& exchange : camera_->server().received().items())
    {
      count += exchange.body.find("AbsoluteMove") != std::string::npos;
    }
    return count;
  }

  /// How often the pan's ContinuousMoves turned the other way (a swing about the target turns at each pass).
  int panTurns() const
  {
    int turns = 0;
    double last = 0.0;
    for (const HttpExchange& exchange : camera_->server().received().items())
    {
      const std::size_t at = exchange.body.find("<tptz:Velocity><tt:PanTilt x=\"");
      if (at == std::string::npos)
      {
        continue;
      }
      const double x = std::stod(exchange.body.substr(at + 30));
      turns += x * last < 0.0 ? 1 : 0;
      last = x != 0.0 ? x : last;
    }
    return turns;
  }

  GoalMonitorConfig goal_config_;
  std::unique_ptr<OnvifCameraEmulator> camera_;
  std::shared_ptr<PtzBackend> device_;
  std::shared_ptr<PtzBackend> backend_;
};
}  // namespace

TEST_F(ClosedLoopOnvif, AContinuousOnlyCameraReachesPositionGoalsOnItsStatusAndNeverGetsAnAbsoluteMove)
{
  start("continuous-only");
  ASSERT_FALSE(device_->capabilities().axes[PAN].absolute);
  EXPECT_TRUE(backend_->capabilities().axes[PAN].absolute);  // made up for by the steering
  // Zoom 0: this camera has no zoom position space, and the goal leaves it alone.
  const std::string first = run({ { 0.6, -0.2, 0.0 } });
  EXPECT_EQ(first.rfind("SUCCEEDED: reached pan 0.", 0), 0u) << first;
  EXPECT_NEAR(camera_->sample().position[PAN], 0.6, GoalMonitorConfig().tolerance[PAN]);
  EXPECT_NEAR(camera_->sample().position[TILT], -0.2, GoalMonitorConfig().tolerance[TILT]);
  const std::string second = run({ { -0.3, 0.1, 0.0 } });
  EXPECT_EQ(second.rfind("SUCCEEDED: reached pan -0.", 0), 0u) << second;
  EXPECT_NEAR(camera_->sample().position[PAN], -0.3, GoalMonitorConfig().tolerance[PAN]);
  EXPECT_EQ(absoluteMoves(), 0u);
}

TEST_F(ClosedLoopOnvif, ACameraThatRefusesTheAbsoluteMoveItListedIsSteeredFromItsNextGoalOn)
{
  start("refuse-absolute-move");
  const std::string first = run({ { 0.5, 0.0, 1.0 } });
  EXPECT_EQ(first.rfind("ABORTED: device fault: the ONVIF camera refused AbsoluteMove", 0), 0u) << first;
  // Its answer told the truth about it: the next goal is steered on its status, and reached.
  const std::string second = run({ { 0.5, 0.0, 1.0 } });
  EXPECT_EQ(second.rfind("SUCCEEDED: reached pan 0.", 0), 0u) << second;
  EXPECT_NEAR(camera_->sample().position[PAN], 0.5, GoalMonitorConfig().tolerance[PAN]);
  EXPECT_EQ(absoluteMoves(), 1u);
}

TEST_F(ClosedLoopOnvif, ACameraThatAnswersAbsoluteMoveAndNeverMovesIsNamedThenSteeredFromItsNextGoalOn)
{
  start("absolute-never-moves");
  const std::string first = run({ { 0.5, 0.0, 1.0 } });
  EXPECT_EQ(
      first.rfind("ABORTED: device fault: the ONVIF camera answered AbsoluteMove but did not move its pan-tilt", 0), 0u)
      << first;
  EXPECT_EQ(absoluteMoves(), 1u);
  // Its status told the truth about it: the next goal is steered on its status, and reached, never SUCCEEDED before.
  const std::string second = run({ { 0.5, 0.0, 1.0 } });
  EXPECT_EQ(second.rfind("SUCCEEDED: reached pan 0.", 0), 0u) << second;
  EXPECT_NEAR(camera_->sample().position[PAN], 0.5, GoalMonitorConfig().tolerance[PAN]);
  EXPECT_EQ(absoluteMoves(), 1u);
}

TEST_F(ClosedLoopOnvif, ACameraWhoseSpeedIgnoresTheMagnitudeReachesItsGoalsWithoutSwingingAboutThem)
{
  // A camera with one speed (0.75 rad/s pan) covers 0.075 rad between two statuses: a tolerance of 0.01 rad asks
  // stops timed to 13 ms. Steering on speeds alone swings it about each target, pass after pass.
  GoalMonitorConfig config;
  config.tolerance = { { 0.01, 0.01, 0.05 } };
  start({ "continuous-only", "speed-ignores-magnitude" }, config);
  int turns = 0;
  for (const AxisValues& target : { AxisValues{ { 0.6, -0.2, 0.0 } }, AxisValues{ { -0.3, 0.1, 0.0 } },
                                    AxisValues{ { -0.25, 0.1, 0.0 } }, AxisValues{ { 0.4, 0.3, 0.0 } } })
  {
    camera_->server().received().clear();
    const std::string end = run(target);
    EXPECT_EQ(end.rfind("SUCCEEDED: reached pan ", 0), 0u) << end;
    EXPECT_NEAR(camera_->sample().position[PAN], target[PAN], config.tolerance[PAN]);
    EXPECT_NEAR(camera_->sample().position[TILT], target[TILT], config.tolerance[TILT]);
    turns += panTurns();
  }
  // Learnt on the way to the first target: at most a turn or two there, while it learns how far it coasts.
  EXPECT_LE(turns, 3);
  const std::vector<std::string> told = backend_->takeWarnings();
  ASSERT_FALSE(told.empty());
  EXPECT_NE(std::find_if(told.begin(), told.end(),
                         [](const std::string& text) {
                           return text.rfind("the pan moves at one speed (0.7", 0) == 0 &&
                                  text.find(" rad/s) whatever the speed it is given: position goals steer it by timed "
                                            "moves at that speed") != std::string::npos;
                         }),
            told.end())
      << told[0];
}

// ---------------------------------------------------------------- TimedSteering, on reports written by hand

namespace
{
const TimePoint T0(std::chrono::seconds(50));
TimePoint at(double seconds)
{
  return addSeconds(T0, seconds);
}
}  // namespace

TEST(TimedSteering, AnAxisThatMovesAtTheSpeedItIsGivenIsNeverTakenForOneAtOneSpeed)
{
  TimedSteering axis(0.0025, 3.0);
  axis.startGoal(1.0);
  // Slowing down towards the target as it is told, a poll behind (it brakes towards each lower speed, never past it).
  double position = 0.0;
  double speed = 1.5;
  for (int report = 0; report < 60; ++report)
  {
    axis.observe(at(0.1 * report), position);
    const double commanded = std::max(0.03, std::min(1.5, 2.0 * (1.0 - position)));
    axis.commanded(commanded, at(0.1 * report));
    speed = std::max(commanded, speed - 0.3);  // 3 rad/s^2 for 0.1 s
    position = std::min(1.0, position + speed * 0.1);
  }
  EXPECT_FALSE(axis.fixedSpeed());
}

TEST(TimedSteering, AnAxisAtOneSpeedIsLearntAndGetsATimedMoveNearItsTarget)
{
  TimedSteering axis(0.005, 3.0);
  axis.startGoal(0.5);
  // Commanded lower and lower, it goes on at 0.75 rad/s.
  const double commanded[] = { 0.6, 0.3, 0.15 };
  for (int report = 0; report < 3; ++report)
  {
    axis.observe(at(0.1 * report), 0.075 * report);
    EXPECT_FALSE(axis.fixedSpeed()) << report;
    axis.commanded(commanded[report], at(0.1 * report));
  }
  axis.observe(at(0.3), 0.225);
  ASSERT_TRUE(axis.fixedSpeed());
  EXPECT_NEAR(axis.speed(), 0.75, 1e-9);
  // 0.275 rad from the target, more than a report and a half at its speed plus its coast: it moves on, untimed.
  TimedSteering::Step step = axis.step(0.1);
  EXPECT_NEAR(step.speed, 0.75, 1e-9);
  EXPECT_LT(step.stop_after, 0.0);
  axis.commanded(step.speed, at(0.3));
  axis.observe(at(0.4), 0.3);
  axis.observe(at(0.5), 0.375);
  // 0.125 rad: a timed move, stopped when its speed has covered the distance less the coast it is thought to have
  // (0.75^2 / (2 x 3) = 0.09375 rad before it has learnt its own).
  step = axis.step(0.1);
  EXPECT_NEAR(step.speed, 0.75, 1e-9);
  EXPECT_NEAR(step.stop_after, (0.125 - 0.09375) / 0.75, 1e-6);
  EXPECT_TRUE(axis.busy());
  EXPECT_NEAR(axis.step(0.1).speed, 0.75, 1e-9);  // until the timer stops it
  axis.timedStopDone();
  axis.observe(at(0.6), 0.44);
  EXPECT_EQ(axis.step(0.1).speed, 0.0);  // coasting
  axis.observe(at(0.7), 0.45);
  EXPECT_EQ(axis.step(0.1).speed, 0.0);
  axis.observe(at(0.8), 0.45);
  // At rest 0.05 short: it went 0.075 rad, 0.03125 of it its speed's over the move: it coasts 0.04375 rad. The next
  // timed move covers the rest less that.
  step = axis.step(0.1);
  EXPECT_NEAR(axis.coast(), 0.075 - 0.03125, 1e-9);
  EXPECT_NEAR(step.stop_after, (0.05 - axis.coast()) / 0.75, 1e-9);
}

TEST(TimedSteering, ItGivesUpWhereAnotherMoveCouldOnlyTakeItFarther)
{
  TimedSteering axis(0.005, 3.0);
  axis.startGoal(0.5);
  const double commanded[] = { 0.3, 0.15, 0.1 };
  for (int report = 0; report < 3; ++report)
  {
    axis.observe(at(0.1 * report), 0.075 * report);
    axis.commanded(commanded[report], at(0.1 * report));
  }
  axis.observe(at(0.3), 0.45);
  ASSERT_TRUE(axis.fixedSpeed());
  // A timed move of nothing (it is nearer than its guessed coast) that goes 0.06 rad: past the target by 0.01.
  TimedSteering::Step step = axis.step(0.1);
  EXPECT_EQ(step.stop_after, 0.0);
  axis.timedStopDone();
  axis.observe(at(0.4), 0.51);
  axis.step(0.1);
  axis.observe(at(0.5), 0.51);
  step = axis.step(0.1);
  // 0.01 rad away, its smallest move 0.06: another would take it farther.
  EXPECT_TRUE(step.gave_up);
  EXPECT_EQ(step.speed, 0.0);
}
