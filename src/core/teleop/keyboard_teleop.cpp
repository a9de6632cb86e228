#include "ptz_action_server/core/teleop/keyboard_teleop.h"

namespace ptz_action_server
{
std::vector<KeyPress> KeyDecoder::feed(const std::string& bytes)
{
  std::vector<KeyPress> keys;
  for (const char byte : bytes)
  {
    if (!pending_.empty())
    {
      pending_ += byte;
      if (pending_.size() == 2)
      {
        if (byte != '[' && byte != 'O')
        {
          pending_.clear();  // not a cursor key: ESC and this byte are dropped
        }
        continue;
      }
      if (pending_[1] == '[' && byte >= 0x20 && byte <= 0x3f)
      {
        continue;  // a control sequence's parameters (ESC [ 1 ; 5 A, ESC [ 2 ~): up to its final byte
      }
      const bool plain = pending_.size() == 3;  // ESC [ A or ESC O A, without parameters
      pending_.clear();
      if (!plain)
      {
        continue;  // a modified or other key: ignored
      }
      switch (byte)
      {
        case 'A':
          keys.push_back({ TeleopKey::UP });
          break;
        case 'B':
          keys.push_back({ TeleopKey::DOWN });
          break;
        case 'C':
          keys.push_back({ TeleopKey::RIGHT });
          break;
        case 'D':
          keys.push_back({ TeleopKey::LEFT });
          break;
        default:
          break;
      }
      continue;
    }
    switch (byte)
    {
      case '\x1b':
        pending_ = byte;
        break;
      case '+':
      case '=':
        keys.push_back({ TeleopKey::ZOOM_IN });
        break;
      case '-':
      case '_':
        keys.push_back({ TeleopKey::ZOOM_OUT });
        break;
      case 'h':
      case 'H':
        keys.push_back({ TeleopKey::HOME });
        break;
      case ' ':
        keys.push_back({ TeleopKey::STOP });
        break;
      case 'q':
      case 'Q':
        keys.push_back({ TeleopKey::QUIT });
        break;
      default:
        if (byte >= '1' && byte <= '9')
        {
          keys.push_back({ TeleopKey::PRESET, byte - '1' });
        }
        break;
    }
  }
  return keys;
}

KeyboardTeleop::KeyboardTeleop(const KeyboardTeleopConfig& config) : config_(config)
{
}

TeleopConfig KeyboardTeleop::teleopConfig() const
{
  TeleopConfig teleop;
  teleop.deadman_button = DEADMAN;
  teleop.pan = { 0, -config_.pan_speed };  // axis +1 is the left arrow: pan left, negative
  teleop.tilt = { 1, config_.tilt_speed };
  teleop.zoom = { 2, config_.zoom_speed };
  teleop.zoom_in_button = -1;
  teleop.zoom_out_button = -1;
  teleop.deadband = 0.0;
  teleop.step = 0.0;
  teleop.home_button = HOME;
  teleop.preset_buttons.clear();
  for (int index = 0; index < PRESETS; ++index)
  {
    teleop.preset_buttons.push_back(FIRST_PRESET + index);
  }
  teleop.stale_timeout = 1e9;  // the keys' joystick never goes quiet: input() is polled
  return teleop;
}

void KeyboardTeleop::press(const KeyPress& press, TimePoint now)
{
  switch (press.key)
  {
    case TeleopKey::LEFT:
    case TeleopKey::RIGHT:
    case TeleopKey::UP:
    case TeleopKey::DOWN:
    case TeleopKey::ZOOM_IN:
    case TeleopKey::ZOOM_OUT:
      moving_ = true;
      moving_key_ = press.key;
      last_seen_ = now;
      break;
    case TeleopKey::HOME:
      moving_ = false;
      button_ = HOME;
      break;
    case TeleopKey::PRESET:
      moving_ = false;
      button_ = press.preset >= 0 && press.preset < PRESETS ? FIRST_PRESET + press.preset : -1;
      break;
    case TeleopKey::STOP:
      moving_ = false;
      stop_ = true;
      break;
    case TeleopKey::QUIT:
      break;
  }
}

JoyInput KeyboardTeleop::input(TimePoint now)
{
  JoyInput input;
  input.axes.assign(3, 0.0f);
  input.buttons.assign(FIRST_PRESET + PRESETS, 0);
  input.buttons[DEADMAN] = stop_ ? 0 : 1;
  stop_ = false;
  if (button_ >= 0)
  {
    input.buttons[button_] = 1;
    button_ = -1;
  }
  if (moving_ && secondsBetween(last_seen_, now) > config_.key_timeout)
  {
    moving_ = false;
  }
  if (moving_)
  {
    switch (moving_key_)
    {
      case TeleopKey::LEFT:
        input.axes[0] = 1.0f;
        break;
      case TeleopKey::RIGHT:
        input.axes[0] = -1.0f;
        break;
      case TeleopKey::UP:
        input.axes[1] = 1.0f;
        break;
      case TeleopKey::DOWN:
        input.axes[1] = -1.0f;
        break;
      case TeleopKey::ZOOM_IN:
        input.axes[2] = 1.0f;
        break;
      case TeleopKey::ZOOM_OUT:
        input.axes[2] = -1.0f;
        break;
      default:
        break;
    }
  }
  return input;
}

}  // namespace ptz_action_server
