// The operator's controls against the sim node: position_abs_speed, ~default_speed through dynamic_reconfigure and
// the latched controls topic, a preset's speed, and the cmd/velocity stream with its dead-man timeout. The speeds are
// judged on the device's own motion (joint_states: its positions and velocities at the device's stamps).
#include <atomic>
#include <cmath>
#include <thread>

#include <dynamic_reconfigure/DoubleParameter.h>
#include <dynamic_reconfigure/Reconfigure.h>

#include "node_test.h"
#include "ptz_action_server/PtzControls.h"
#include "ptz_action_server/PtzSpeedAction.h"
#include "ptz_action_server/SavePreset.h"
#include "ptz_action_server/SetPresetSpeed.h"
#include "ptz_action_server/PtzPresetAction.h"

namespace
{
using ptz_action_server::PtzControls;

/// The pan joint's samples from joint_states: stamp, position, velocity.
class PanLog
{
public:
  PanLog()
  {
    subscriber_ = node_handle_.subscribe("joint_states", 100, &PanLog::onJoints, this);
  }
  /// The fastest |velocity| and the time from the first sample past \p from to the first past \p to (pan rising).
  double fastest() const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    double fastest = 0.0;
    for (const Sample& sample : samples_)
    {
      fastest = std::max(fastest, std::abs(sample.velocity));
    }
    return fastest;
  }
  double secondsBetween(double from, double to) const
  {
    std::lock_guard<std::mutex> lock(mutex_);
    ros::Time start;
    for (const Sample& sample : samples_)
    {
      if (start.isZero() && sample.position >= from)
      {
        start = sample.stamp;
      }
      if (!start.isZero() && sample.position >= to)
      {
        return (sample.stamp - start).toSec();
      }
    }
    return -1.0;
  }
  void clear()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    samples_.clear();
  }

private:
  struct Sample
  {
    ros::Time stamp;
    double position;
    double velocity;
  };
  void onJoints(const sensor_msgs::JointState::ConstPtr& joints)
  {
    for (std::size_t index = 0; index < joints->name.size() && index < joints->position.size(); ++index)
    {
      if (joints->name[index].find("pan") != std::string::npos)
      {
        std::lock_guard<std::mutex> lock(mutex_);
        const double velocity = index < joints->velocity.size() ? joints->velocity[index] : 0.0;
        samples_.push_back({ joints->header.stamp, joints->position[index], velocity });
      }
    }
  }
  ros::NodeHandle node_handle_;
  ros::Subscriber subscriber_;
  mutable std::mutex mutex_;
  std::vector<Sample> samples_;
};

class SpeedNodeTest : public NodeTest
{
protected:
  void SetUp() override
  {
    NodeTest::SetUp();
    ASSERT_TRUE(setDefaultSpeed(1.0));
    ASSERT_EQ(moveTo(0.0, 0.0, 1.0), State::SUCCEEDED);
  }
  void TearDown() override
  {
    setDefaultSpeed(1.0);
  }
  /// Through dynamic_reconfigure's service, as `dynparam set` does.
  static bool setDefaultSpeed(double fraction)
  {
    dynamic_reconfigure::Reconfigure reconfigure;
    dynamic_reconfigure::DoubleParameter parameter;
    parameter.name = "default_speed";
    parameter.value = fraction;
    reconfigure.request.config.doubles.push_back(parameter);
    return ros::service::call("ptz_action_server/set_parameters", reconfigure);
  }
  static PtzControls::ConstPtr controls()
  {
    return ros::topic::waitForMessage<PtzControls>("controls", ros::Duration(10.0));
  }
  /// The sim's top pan speed, from the latched capabilities.
  static double topPanSpeed()
  {
    return capabilities_->pan.max_speed;
  }
};

TEST_F(SpeedNodeTest, ASlowGoalMovesTheDeviceAtItsSpeed)
{
  const PtzControls::ConstPtr shown = controls();
  ASSERT_TRUE(shown);
  EXPECT_EQ(shown->speed.pan.control, ptz_action_server::PtzAxisSpeed::DEVICE);  // the sim takes a speed itself
  EXPECT_DOUBLE_EQ(shown->speed.default_speed, 1.0);
  actionlib::SimpleActionClient<ptz_action_server::PtzSpeedAction> client("move_ptz/position_abs_speed", true);
  ASSERT_TRUE(client.waitForServer(ros::Duration(30.0)));
  PanLog log;
  ptz_action_server::PtzSpeedGoal goal;
  goal.pan = 0.6;
  goal.zoom = 1.0;
  goal.pan_speed = 0.3;  // rad/s
  std::atomic<int> feedback{ 0 };
  client.sendGoal(goal, {}, {}, [&](const ptz_action_server::PtzSpeedFeedbackConstPtr&) { ++feedback; });
  ASSERT_TRUE(client.waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(client.getState(), State::SUCCEEDED) << client.getState().getText();
  EXPECT_GT(feedback.load(), 5);  // 2 s of motion at 10 Hz, not the 0.4 s of the top speed
  EXPECT_LT(log.fastest(), 0.3 * 1.05);
  const double seconds = log.secondsBetween(0.1, 0.5);
  EXPECT_GT(seconds, 0.4 / 0.3 * 0.8);  // joint_states come at 10 Hz
  // ptz_state comes at 10 Hz: the state that shows the goal reached may follow its result.
  EXPECT_TRUE(observer_->waitFor([](const PtzState& state) { return std::abs(state.pan - 0.6) < 0.01; }, 5.0))
      << observer_->latest().pan;

  // A speed that is no speed is refused, and nothing moves.
  goal.pan = 0.0;
  goal.pan_speed = -1.0;
  client.sendGoal(goal);
  ASSERT_TRUE(client.waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(client.getState(), State::REJECTED);
  EXPECT_NE(client.getState().getText().find("pan speed"), std::string::npos) << client.getState().getText();
}

TEST_F(SpeedNodeTest, TheDefaultSpeedChangesAtRunTime)
{
  ASSERT_TRUE(setDefaultSpeed(0.2));
  ASSERT_TRUE(ros::topic::waitForMessage<PtzControls>("controls", ros::Duration(10.0)));
  const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(10.0);
  PtzControls::ConstPtr shown = controls();
  while (shown && shown->speed.default_speed != 0.2 && ros::WallTime::now() < deadline)
  {
    shown = controls();  // a new subscription gets the latest latched message
  }
  ASSERT_TRUE(shown);
  EXPECT_DOUBLE_EQ(shown->speed.default_speed, 0.2);
  PanLog log;
  ASSERT_EQ(moveTo(0.5, 0.0, 1.0), State::SUCCEEDED);
  EXPECT_LT(log.fastest(), 0.2 * topPanSpeed() * 1.05);
  EXPECT_GT(log.fastest(), 0.2 * topPanSpeed() * 0.5);

  // Refused values keep the one set.
  EXPECT_TRUE(setDefaultSpeed(7.0));  // dynamic_reconfigure clamps to the .cfg's range: 1
  ASSERT_TRUE(setDefaultSpeed(1.0));
  log.clear();
  ASSERT_EQ(moveTo(0.0, 0.0, 1.0), State::SUCCEEDED);
  EXPECT_GT(log.fastest(), 0.5 * topPanSpeed());
}

TEST_F(SpeedNodeTest, APresetRunsAtItsSpeed)
{
  ASSERT_EQ(moveTo(0.5, 0.1, 1.0), State::SUCCEEDED);
  ptz_action_server::SavePreset save;
  save.request.name = "slow_pan";
  ASSERT_TRUE(ros::service::call("move_ptz/save_preset", save));
  ASSERT_TRUE(save.response.success) << save.response.message;
  ptz_action_server::SetPresetSpeed speed;
  speed.request.name = "slow_pan";
  speed.request.speed = 0.1;
  ASSERT_TRUE(ros::service::call("move_ptz/set_preset_speed", speed));
  ASSERT_TRUE(speed.response.success) << speed.response.message;
  speed.request.name = "no_such_preset";
  ASSERT_TRUE(ros::service::call("move_ptz/set_preset_speed", speed));
  EXPECT_FALSE(speed.response.success);

  ASSERT_EQ(moveTo(0.0, 0.1, 1.0), State::SUCCEEDED);
  actionlib::SimpleActionClient<ptz_action_server::PtzPresetAction> preset("move_ptz/preset", true);
  ASSERT_TRUE(preset.waitForServer(ros::Duration(30.0)));
  PanLog log;
  ptz_action_server::PtzPresetGoal goal;
  goal.name = "slow_pan";
  preset.sendGoal(goal);
  ASSERT_TRUE(preset.waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(preset.getState(), State::SUCCEEDED) << preset.getState().getText();
  EXPECT_LT(log.fastest(), 0.1 * topPanSpeed() * 1.05);
  EXPECT_GT(log.secondsBetween(0.1, 0.4), 0.3 / (0.1 * topPanSpeed()) * 0.8);
}

/// Publishes \p velocity on cmd/velocity every 50 ms until stopped.
class VelocityStream
{
public:
  explicit VelocityStream(const ptz_action_server::PtzGoal& velocity)
  {
    publisher_ = node_handle_.advertise<ptz_action_server::PtzGoal>("cmd/velocity", 1);
    thread_ = std::thread([this, velocity] {
      while (running_)
      {
        publisher_.publish(velocity);
        ++published_;
        ros::WallDuration(0.05).sleep();
      }
    });
  }
  ~VelocityStream()
  {
    stop();
  }
  void stop()
  {
    running_ = false;
    if (thread_.joinable())
    {
      thread_.join();
    }
  }

private:
  ros::NodeHandle node_handle_;
  ros::Publisher publisher_;
  std::atomic<bool> running_{ true };
  std::atomic<int> published_{ 0 };
  std::thread thread_;
};

TEST_F(SpeedNodeTest, TheDeviceStopsWhenTheVelocityStreamStops)
{
  VelocityStream stream(makePtzGoal(0.3, 0.0, 0.0));
  ASSERT_TRUE(observer_->waitFor(
      [](const PtzState& state) { return state.pan > 0.2 && state.mode == PtzState::MODE_VELOCITY; }, GOAL_WAIT));
  stream.stop();
  const double at_last_message = observer_->latest().pan;
  // ~cmd_velocity/timeout (0.5 s) later the device decelerates to rest and the node is idle.
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.mode == PtzState::MODE_IDLE; }, GOAL_WAIT));
  ASSERT_TRUE(observer_->waitTicks(3));
  const double rest = observer_->latest().pan;
  EXPECT_LT(rest, at_last_message + 0.3 * 2.0);
  ASSERT_TRUE(observer_->waitTicks(3));
  EXPECT_EQ(observer_->latest().pan, rest);
}

TEST_F(SpeedNodeTest, AnActionGoalPreemptsTheVelocityStream)
{
  VelocityStream stream(makePtzGoal(-0.3, 0.0, 0.0));
  ASSERT_TRUE(observer_->waitFor(
      [](const PtzState& state) { return state.pan < -0.1 && state.mode == PtzState::MODE_VELOCITY; }, GOAL_WAIT));
  // The stream goes on, yet the goal takes the device and keeps it to the end.
  EXPECT_EQ(moveTo(0.4, 0.0, 1.0), State::SUCCEEDED) << absolute_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(5));
  EXPECT_NEAR(observer_->latest().pan, 0.4, 0.01);
  EXPECT_EQ(observer_->latest().mode, PtzState::MODE_IDLE);
  // A new velocity on the stream takes the device back, as a new velocity goal would.
  stream.stop();
  VelocityStream faster(makePtzGoal(0.4, 0.0, 0.0));
  ASSERT_TRUE(observer_->waitFor(
      [](const PtzState& state) { return state.pan > 0.5 && state.mode == PtzState::MODE_VELOCITY; }, GOAL_WAIT));
  faster.stop();
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.mode == PtzState::MODE_IDLE; }, GOAL_WAIT));
}

}  // namespace
