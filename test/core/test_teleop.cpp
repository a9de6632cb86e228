/**
 * \file
 * \brief The joystick teleop's mapping: dead-man, deadband and scaling, goals only on change, presets on a press,
 * stops on release and on a stale joystick.
 */
#include <gtest/gtest.h>

#include "ptz_action_server/core/teleop/teleop.h"

namespace ptz_action_server
{
namespace
{
using Type = TeleopCommand::Type;

constexpr int DEADMAN = 4;
constexpr int HOME = 6;
constexpr int ZOOM_IN = 5;
constexpr int ZOOM_OUT = 7;

TeleopConfig testConfig()
{
  TeleopConfig config;
  config.deadman_button = DEADMAN;
  config.pan = { 0, -1.0 };
  config.tilt = { 1, 0.5 };
  config.zoom = { -1, 0.0 };
  config.zoom_in_button = ZOOM_IN;
  config.zoom_out_button = ZOOM_OUT;
  config.zoom_button_speed = 3.0;
  config.deadband = 0.2;
  config.step = 0.1;
  config.home_button = HOME;
  config.preset_buttons = { 0, 1, 2 };
  config.preset_names = { "", "door" };
  return config;
}

/// A gamepad with 8 axes and 11 buttons: sticks at \p pan_axis, \p tilt_axis; \p held buttons down.
JoyInput joy(float pan_axis, float tilt_axis, std::initializer_list<int> held)
{
  JoyInput input;
  input.axes.assign(8, 0.0f);
  input.buttons.assign(11, 0);
  input.axes[0] = pan_axis;
  input.axes[1] = tilt_axis;
  for (int button : held)
  {
    input.buttons[button] = 1;
  }
  return input;
}

class TeleopTest : public ::testing::Test
{
protected:
  std::vector<TeleopCommand> send(const JoyInput& input)
  {
    return controller_.onJoy(input, clock_.now());
  }
  void advance(double seconds)
  {
    clock_.advance(seconds);
  }

  ManualClock clock_;
  TeleopController controller_{ testConfig() };
};

TEST_F(TeleopTest, NothingMovesWithoutTheDeadmanButton)
{
  EXPECT_TRUE(send(joy(1.0f, 1.0f, {})).empty());
  EXPECT_TRUE(send(joy(-1.0f, 0.5f, { HOME, 0, ZOOM_IN })).empty());
  EXPECT_TRUE(controller_.onTick(clock_.now()).empty());
}

TEST_F(TeleopTest, SticksScaleWithDeadbandAndTheDeadmanHeld)
{
  const auto commands = send(joy(1.0f, -0.6f, { DEADMAN }));
  ASSERT_EQ(commands.size(), 1u);
  EXPECT_EQ(commands[0].type, Type::VELOCITY);
  EXPECT_DOUBLE_EQ(commands[0].velocity[PAN], -1.0);  // stick left: pan left (negative)
  // |-0.6| past a 0.2 deadband is half way: 0.5 of 0.5 rad/s, downwards.
  EXPECT_DOUBLE_EQ(commands[0].velocity[TILT], -0.25);
  EXPECT_DOUBLE_EQ(commands[0].velocity[ZOOM], 0.0);
  EXPECT_EQ(controller_.velocityOf(joy(0.19f, -0.15f, { DEADMAN })), AxisValues{}) << "inside the deadband";
}

TEST_F(TeleopTest, AGoalOnlyWhenTheVelocityChanges)
{
  ASSERT_EQ(send(joy(0.6f, 0.0f, { DEADMAN })).size(), 1u);
  EXPECT_TRUE(send(joy(0.6f, 0.0f, { DEADMAN })).empty()) << "the same deflection again";
  EXPECT_TRUE(send(joy(0.61f, 0.0f, { DEADMAN })).empty()) << "jitter below the step";
  const auto changed = send(joy(0.9f, 0.0f, { DEADMAN }));
  ASSERT_EQ(changed.size(), 1u);
  EXPECT_EQ(changed[0].type, Type::VELOCITY);
}

TEST_F(TeleopTest, ReleasingTheDeadmanOrTheSticksStops)
{
  ASSERT_EQ(send(joy(0.6f, 0.0f, { DEADMAN })).size(), 1u);
  const auto released = send(joy(0.6f, 0.0f, {}));
  ASSERT_EQ(released.size(), 1u);
  EXPECT_EQ(released[0].type, Type::STOP);
  EXPECT_TRUE(send(joy(0.6f, 0.0f, {})).empty()) << "one stop is enough";

  ASSERT_EQ(send(joy(0.6f, 0.0f, { DEADMAN })).size(), 1u);
  const auto centred = send(joy(0.0f, 0.0f, { DEADMAN }));
  ASSERT_EQ(centred.size(), 1u);
  EXPECT_EQ(centred[0].type, Type::STOP);
}

TEST_F(TeleopTest, AStaleJoystickStopsOnce)
{
  ASSERT_EQ(send(joy(0.0f, 0.8f, { DEADMAN })).size(), 1u);
  advance(0.4);
  EXPECT_TRUE(controller_.onTick(clock_.now()).empty());
  advance(0.2);
  const auto stale = controller_.onTick(clock_.now());
  ASSERT_EQ(stale.size(), 1u);
  EXPECT_EQ(stale[0].type, Type::STOP);
  advance(1.0);
  EXPECT_TRUE(controller_.onTick(clock_.now()).empty());
}

TEST_F(TeleopTest, ZoomButtonsAndPresetsOnAPress)
{
  const auto zoom = send(joy(0.0f, 0.0f, { DEADMAN, ZOOM_OUT }));
  ASSERT_EQ(zoom.size(), 1u);
  EXPECT_DOUBLE_EQ(zoom[0].velocity[ZOOM], -3.0);

  const auto home = send(joy(0.0f, 0.0f, { DEADMAN, HOME }));
  ASSERT_EQ(home.size(), 1u);
  EXPECT_EQ(home[0].type, Type::PRESET);
  EXPECT_EQ(home[0].name, "home");
  EXPECT_TRUE(send(joy(0.0f, 0.0f, { DEADMAN, HOME })).empty()) << "held, not pressed again";

  const auto first = send(joy(0.0f, 0.0f, { DEADMAN, 0 }));
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].name, "");
  EXPECT_EQ(first[0].preset_index, 0);
  const auto named = send(joy(0.0f, 0.0f, { DEADMAN, 1 }));
  ASSERT_EQ(named.size(), 1u);
  EXPECT_EQ(named[0].name, "door");

  // Releasing the dead-man stops a preset goal too; a press without it does nothing.
  const auto released = send(joy(0.0f, 0.0f, {}));
  ASSERT_EQ(released.size(), 1u);
  EXPECT_EQ(released[0].type, Type::STOP);
  EXPECT_TRUE(send(joy(0.0f, 0.0f, { 2 })).empty());
}

TEST_F(TeleopTest, SpeedLimitsClampAndAnAxisWithoutSpeedStaysStill)
{
  controller_.setSpeedLimits({ { 0.4, 0.5, 0.0 } });
  const AxisValues velocity = controller_.velocityOf(joy(-1.0f, 1.0f, { DEADMAN, ZOOM_IN }));
  EXPECT_DOUBLE_EQ(velocity[PAN], 0.4);
  EXPECT_DOUBLE_EQ(velocity[TILT], 0.5);
  EXPECT_DOUBLE_EQ(velocity[ZOOM], 0.0);
}

TEST(TeleopConfigTest, ADeadmanButtonIsRequired)
{
  TeleopConfig config;
  EXPECT_EQ(config.check(), "");
  config.deadman_button = -1;
  EXPECT_NE(config.check().find("dead-man"), std::string::npos);
  config = TeleopConfig();
  config.deadband = 1.0;
  EXPECT_NE(config.check(), "");
}

}  // namespace
}  // namespace ptz_action_server
