/**
 * \file
 * \brief `ptz_move teleop`'s keys: decoding a terminal's bytes, and the keys played as a joystick through the
 * TeleopController (held keys move, a quiet key stops, space stops, h and digits go to presets).
 */
#include <gtest/gtest.h>

#include "ptz_action_server/core/teleop/keyboard_teleop.h"

namespace ptz_action_server
{
namespace
{
using Type = TeleopCommand::Type;

std::vector<TeleopKey> keysOf(const std::vector<KeyPress>& presses)
{
  std::vector<TeleopKey> keys;
  for (const KeyPress& press : presses)
  {
    keys.push_back(press.key);
  }
  return keys;
}

TEST(KeyDecoderTest, ArrowsInBothFormsEvenSplitAcrossReads)
{
  KeyDecoder decoder;
  EXPECT_EQ(keysOf(decoder.feed("\x1b[A\x1bOB\x1b[C")),
            (std::vector<TeleopKey>{ TeleopKey::UP, TeleopKey::DOWN, TeleopKey::RIGHT }));
  EXPECT_TRUE(decoder.feed("\x1b").empty());
  EXPECT_TRUE(decoder.feed("[").empty());
  EXPECT_EQ(keysOf(decoder.feed("D")), (std::vector<TeleopKey>{ TeleopKey::LEFT }));
}

TEST(KeyDecoderTest, LettersDigitsAndWhatIsIgnored)
{
  KeyDecoder decoder;
  const auto keys = decoder.feed("+-h 7qx0");
  EXPECT_EQ(keysOf(keys), (std::vector<TeleopKey>{ TeleopKey::ZOOM_IN, TeleopKey::ZOOM_OUT, TeleopKey::HOME,
                                                   TeleopKey::STOP, TeleopKey::PRESET, TeleopKey::QUIT }));
  EXPECT_EQ(keys[4].preset, 6);
  // Ctrl-Right and Insert carry parameters: their digits are no presets.
  EXPECT_TRUE(decoder.feed("\x1b[1;5C\x1b[2~").empty());
}

class KeyboardTeleopTest : public ::testing::Test
{
protected:
  std::vector<TeleopCommand> key(TeleopKey pressed, int preset = -1)
  {
    keyboard_.press({ pressed, preset }, clock_.now());
    return frame();
  }
  std::vector<TeleopCommand> frame()
  {
    return controller_.onJoy(keyboard_.input(clock_.now()), clock_.now());
  }

  ManualClock clock_;
  KeyboardTeleop keyboard_{ KeyboardTeleopConfig() };
  TeleopController controller_{ keyboard_.teleopConfig() };
};

TEST_F(KeyboardTeleopTest, AHeldArrowMovesOnceAndStopsWhenItIsNoLongerRepeated)
{
  const auto left = key(TeleopKey::LEFT);
  ASSERT_EQ(left.size(), 1u);
  EXPECT_EQ(left[0].type, Type::VELOCITY);
  EXPECT_DOUBLE_EQ(left[0].velocity[PAN], -0.5);
  for (int repeat = 0; repeat < 10; ++repeat)
  {
    clock_.advance(0.04);
    EXPECT_TRUE(key(TeleopKey::LEFT).empty()) << "a repeat changes nothing";
  }
  clock_.advance(0.5);
  EXPECT_TRUE(frame().empty());
  clock_.advance(0.3);
  const auto released = frame();
  ASSERT_EQ(released.size(), 1u);
  EXPECT_EQ(released[0].type, Type::STOP);
}

TEST_F(KeyboardTeleopTest, SpaceStopsAndPresetsArePressedOnce)
{
  ASSERT_EQ(key(TeleopKey::ZOOM_IN).size(), 1u);
  const auto stop = key(TeleopKey::STOP);
  ASSERT_EQ(stop.size(), 1u);
  EXPECT_EQ(stop[0].type, Type::STOP);
  EXPECT_TRUE(frame().empty());

  const auto home = key(TeleopKey::HOME);
  ASSERT_EQ(home.size(), 1u);
  EXPECT_EQ(home[0].name, "home");
  EXPECT_TRUE(frame().empty()) << "the preset goal goes on";
  const auto third = key(TeleopKey::PRESET, 2);
  ASSERT_EQ(third.size(), 1u);
  EXPECT_EQ(third[0].preset_index, 2);
  const auto stopped = key(TeleopKey::STOP);
  ASSERT_EQ(stopped.size(), 1u) << "space stops a preset goal too";
}

}  // namespace
}  // namespace ptz_action_server
