/**
 * \file
 * \brief ptz_teleop against the sim node, with its shipped Xbox 360 mapping: Joy messages become velocity goals only
 * with the dead-man button held, one goal per change; releasing it or a silent joystick stops the camera; Start goes
 * home and A goes to the first saved preset.
 */
#include <thread>

#include <actionlib_msgs/GoalID.h>
#include <sensor_msgs/Joy.h>

#include "ptz_action_server/PtzActionGoal.h"
#include "ptz_action_server/PtzPresetActionGoal.h"
#include "ptz_action_server/SavePreset.h"
#include "node_test.h"

namespace
{
// The Xbox 360 layout of config/teleop/xbox360.yaml.
constexpr int BUTTON_A = 0;
constexpr int BUTTON_LB = 4;  // the dead-man
constexpr int BUTTON_START = 7;
constexpr int AXIS_LEFT_X = 0;
constexpr int AXIS_RIGHT_Y = 4;

sensor_msgs::Joy makeJoy(std::initializer_list<std::pair<int, float>> axes, std::initializer_list<int> buttons)
{
  sensor_msgs::Joy joy;
  joy.axes.assign(8, 0.0f);
  joy.axes[2] = joy.axes[5] = 1.0f;  // the triggers at rest
  joy.buttons.assign(11, 0);
  for (const auto& [axis, value] : axes)
  {
    joy.axes[axis] = value;
  }
  for (int button : buttons)
  {
    joy.buttons[button] = 1;
  }
  return joy;
}

/// Plays a Joy message at 20 Hz, as a joystick driver with autorepeat does, until told otherwise or silenced.
class JoyPlayer
{
public:
  JoyPlayer() : publisher_(ros::NodeHandle().advertise<sensor_msgs::Joy>("/joy", 10)), thread_([this] { run(); })
  {
  }
  ~JoyPlayer()
  {
    running_ = false;
    thread_.join();
  }
  void play(const sensor_msgs::Joy& joy)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    joy_ = joy;
    playing_ = true;
  }
  void silence()
  {
    std::lock_guard<std::mutex> lock(mutex_);
    playing_ = false;
  }
  bool connected() const
  {
    return publisher_.getNumSubscribers() > 0;
  }

private:
  void run()
  {
    ros::WallRate rate(20.0);
    while (running_ && ros::ok())
    {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (playing_)
        {
          joy_.header.stamp = ros::Time::now();
          publisher_.publish(joy_);
        }
      }
      rate.sleep();
    }
  }

  ros::Publisher publisher_;
  std::mutex mutex_;
  sensor_msgs::Joy joy_;
  bool playing_ = false;
  std::atomic<bool> running_{ true };
  std::thread thread_;
};

/// Counts the goals and cancels that reach an action's topics.
template <class ActionGoal>
class GoalCounter
{
public:
  explicit GoalCounter(const std::string& action)
  {
    ros::NodeHandle node_handle;
    goals_ = node_handle.subscribe<ActionGoal>(action + "/goal", 100,
                                               [this](const typename ActionGoal::ConstPtr&) { ++goal_count; });
    cancels_ = node_handle.subscribe<actionlib_msgs::GoalID>(
        action + "/cancel", 100, [this](const actionlib_msgs::GoalID::ConstPtr&) { ++cancel_count; });
  }
  std::atomic<int> goal_count{ 0 };
  std::atomic<int> cancel_count{ 0 };

private:
  ros::Subscriber goals_;
  ros::Subscriber cancels_;
};
}  // namespace

class TeleopNodeTest : public NodeTest
{
protected:
  static void SetUpTestSuite()
  {
    NodeTest::SetUpTestSuite();
    player_ = new JoyPlayer();
    velocity_goals_ = new GoalCounter<ptz_action_server::PtzActionGoal>("move_ptz/velocity");
    preset_goals_ = new GoalCounter<ptz_action_server::PtzPresetActionGoal>("move_ptz/preset");
  }

  void SetUp() override
  {
    NodeTest::SetUp();
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(20.0);
    while (!player_->connected() && ros::WallTime::now() < deadline)
    {
      ros::WallDuration(0.01).sleep();
    }
    ASSERT_TRUE(player_->connected()) << "ptz_teleop does not listen to /joy";
    player_->silence();
    ASSERT_EQ(moveTo(0.0, 0.0, 1.0), State::SUCCEEDED);
  }

  void TearDown() override
  {
    player_->silence();
  }

  static bool waitForMode(int mode, double timeout = 10.0)
  {
    return observer_->waitFor([mode](const PtzState& state) { return state.mode == mode; }, timeout);
  }

  static inline JoyPlayer* player_ = nullptr;
  static inline GoalCounter<ptz_action_server::PtzActionGoal>* velocity_goals_ = nullptr;
  static inline GoalCounter<ptz_action_server::PtzPresetActionGoal>* preset_goals_ = nullptr;
};

TEST_F(TeleopNodeTest, NothingMovesWithoutTheDeadmanButton)
{
  const int goals = velocity_goals_->goal_count + preset_goals_->goal_count;
  observer_->clear();
  player_->play(makeJoy({ { AXIS_LEFT_X, 1.0f }, { AXIS_RIGHT_Y, 1.0f } }, { BUTTON_START, BUTTON_A }));
  ASSERT_TRUE(observer_->waitTicks(8));
  for (const PtzState& state : observer_->states())
  {
    EXPECT_EQ(state.mode, PtzState::MODE_IDLE);
    EXPECT_NEAR(state.pan, 0.0, 1e-4);
  }
  EXPECT_EQ(velocity_goals_->goal_count + preset_goals_->goal_count, goals);
}

TEST_F(TeleopNodeTest, TheDeadmanAndAStickMoveWithOneGoalAndReleasingStops)
{
  const int goals = velocity_goals_->goal_count;
  const int cancels = velocity_goals_->cancel_count;
  player_->play(makeJoy({ { AXIS_LEFT_X, 1.0f } }, { BUTTON_LB }));  // full left: pan left (negative)
  ASSERT_TRUE(waitForMode(PtzState::MODE_VELOCITY));
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.pan < -0.2; }, 10.0));
  EXPECT_EQ(velocity_goals_->goal_count, goals + 1) << "one goal for a stick held still at 20 Hz";

  player_->play(makeJoy({ { AXIS_LEFT_X, 1.0f } }, {}));  // dead-man released, stick still deflected
  ASSERT_TRUE(waitForMode(PtzState::MODE_IDLE));
  EXPECT_EQ(velocity_goals_->cancel_count, cancels + 1);
  const double rest = observer_->latest().pan;
  ASSERT_TRUE(observer_->waitTicks(5));
  EXPECT_NEAR(observer_->latest().pan, rest, 1e-4) << "the camera moved on after the release";
}

TEST_F(TeleopNodeTest, ASilentJoystickStopsTheCamera)
{
  const int cancels = velocity_goals_->cancel_count;
  player_->play(makeJoy({ { AXIS_RIGHT_Y, 1.0f } }, { BUTTON_LB }));  // zoom in
  ASSERT_TRUE(waitForMode(PtzState::MODE_VELOCITY));
  ASSERT_TRUE(observer_->waitFor([](const PtzState& state) { return state.zoom > 1.5; }, 10.0));
  player_->silence();  // the joystick is unplugged with the dead-man held
  ASSERT_TRUE(waitForMode(PtzState::MODE_IDLE, 5.0));
  EXPECT_EQ(velocity_goals_->cancel_count, cancels + 1);
}

TEST_F(TeleopNodeTest, StartGoesHomeAndAGoesToTheFirstSavedPreset)
{
  ASSERT_EQ(moveTo(0.4, 0.2, 1.0), State::SUCCEEDED);
  ptz_action_server::SavePreset save;
  save.request.name = "teleop_a";
  ASSERT_TRUE(ros::service::call("move_ptz/save_preset", save) && save.response.success) << save.response.message;
  ASSERT_EQ(moveTo(-0.3, -0.1, 1.0), State::SUCCEEDED);

  player_->play(makeJoy({}, { BUTTON_LB, BUTTON_START }));
  ASSERT_TRUE(observer_->waitFor(
      [](const PtzState& state) {
        return state.mode == PtzState::MODE_IDLE && std::abs(state.pan) < TOLERANCE && std::abs(state.tilt) < TOLERANCE;
      },
      GOAL_WAIT))
      << "not home";
  player_->play(makeJoy({}, { BUTTON_LB }));
  player_->play(makeJoy({}, { BUTTON_LB, BUTTON_A }));
  EXPECT_TRUE(observer_->waitFor(
      [](const PtzState& state) {
        return state.mode == PtzState::MODE_IDLE && std::abs(state.pan - 0.4) < TOLERANCE &&
               std::abs(state.tilt - 0.2) < TOLERANCE;
      },
      GOAL_WAIT))
      << "not at the first saved preset";
}
