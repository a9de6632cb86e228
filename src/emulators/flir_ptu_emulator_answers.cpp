#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "ptz_action_server/emulators/flir_ptu_emulator.h"

// What the emulated FLIR PTU answers to each command. Published texts (published-wire-facts.md, section 3) where there
// are some: terse `* 185.1428` and verbose `* 185.1428 seconds arc per Pan position`, `* Current pan position is 0`,
// `* Pan acceleration is 2000 positions/sec^2`, `* ASCII terse mode`, and the errors `! Motor speed cannot be less than
// 31 pos/sec`, `! Pan speed cannot exceed 2902 positions/sec`, `! Maximum allowable Pan position is 3090`. The other
// verbose texts, the `C` and `E` answers and the minimum-position error are this emulator's own words.

namespace ptz_action_server
{
namespace
{
const char* const ACK = "*";

/// `* <value>` when terse, `* <before><value><after>` when verbose.
std::string valueReply(bool terse, const std::string& value, const std::string& before, const std::string& after = "")
{
  return terse ? "* " + value : "* " + before + value + after;
}

std::string tooFast(const std::string& axis_name, long speed_max)
{
  return "! " + axis_name + " speed cannot exceed " + std::to_string(speed_max) + " positions/sec";
}

std::string tooSlow(long lower_speed)
{
  return "! Motor speed cannot be less than " + std::to_string(lower_speed) + " pos/sec";
}
}  // namespace

std::string FlirPtuEmulator::reply(const std::string& letters, bool has_value, long value, TimePoint at)
{
  if (letters == "FT" || letters == "FV")
  {
    terse_ = letters == "FT";
    return ACK;
  }
  if (letters == "F")
  {
    return std::string("* ASCII ") + (terse_ ? "terse" : "verbose") + " mode";
  }
  if (letters == "ED" || letters == "EE")
  {
    echo_ = letters == "EE";
    return ACK;
  }
  if (letters == "E")
  {
    return echo_ ? "* Echoing" : "* Not echoing";
  }
  if (letters == "CI" || letters == "CV")
  {
    velocity_mode_ = letters == "CV";
    velocity_ = { { 0, 0 } };
    return ACK;
  }
  if (letters == "C")
  {
    // The published driver reads the mode from the third character: 'i' independent (position), 'p' pure velocity.
    const char* mode = velocity_mode_ ? "pure velocity" : "independent";
    return valueReply(terse_, mode, "Control mode is ");
  }
  if (letters == "LE" || letters == "LD")
  {
    limits_enforced_ = letters == "LE";
    return ACK;
  }
  if (letters == "R" || letters == "RE")
  {
    if (letters == "R" && config_.reset_as_power_up)
    {
      powerUp();  // a unit that restarts: its banner, and the power-up modes
    }
    // Terse or verbose, echo, the control mode and the speeds stay as they were: the published drivers read the 9
    // bytes `!T!T!P!P*` and go on without `FT` / `ED`.
    startCalibration(at);
    return "";  // `!T!T!P!P*` once calibrated
  }
  if (letters == "H" || letters == "HP" || letters == "HT")
  {
    for (Axis halted : { PAN, TILT })
    {
      if (letters == "H" || (letters == "HP") == (halted == PAN))
      {
        model_.moveAxisAtVelocity(halted, 0.0, at);
        velocity_[axisIndex(halted)] = 0;
      }
    }
    return ACK;
  }
  if (letters.size() == 2 && (letters[0] == 'P' || letters[0] == 'T'))
  {
    const bool motion = letters[1] == 'P' || letters[1] == 'O' || letters[1] == 'S';
    return motion ? replyToMotion(letters, has_value, value, at) : replyToAxisSetting(letters, has_value, value, at);
  }
  return "! Illegal Command";
}

std::string FlirPtuEmulator::replyToAxisSetting(const std::string& letters, bool has_value, long value, TimePoint)
{
  const bool pan = letters[0] == 'P';
  const Axis axis = pan ? PAN : TILT;
  const std::size_t index = axisIndex(axis);
  const std::string name = pan ? "Pan" : "Tilt";
  const long speed_max = std::lround(model_.config().axes[axis].motion.max_speed / resolution_rad_);
  switch (letters[1])
  {
    case 'R': {
      if (has_value)
      {
        return "! Illegal argument";
      }
      char text[32];
      std::snprintf(text, sizeof(text), "%.4f", config_.resolution);
      return valueReply(terse_, text, "", " seconds arc per " + name + " position");
    }
    case 'N':
    case 'X': {
      if (has_value)
      {
        return "! Limits are fixed";
      }
      const bool minimum = letters[1] == 'N';
      const long limit =
          pan ? (minimum ? config_.pan_min : config_.pan_max) : (minimum ? config_.tilt_min : config_.tilt_max);
      return valueReply(terse_, std::to_string(limit), (minimum ? "Minimum " : "Maximum ") + name + " position is ");
    }
    case 'U':
      return has_value ?
                 "! Upper speed is fixed" :
                 valueReply(terse_, std::to_string(speed_max), "Maximum " + name + " speed is ", " positions/sec");
    case 'L':
      if (!has_value)
      {
        return valueReply(terse_, std::to_string(lower_speed_[index]), "Minimum " + name + " speed is ",
                          " positions/sec");
      }
      if (value < config_.lower_speed)
      {
        return tooSlow(config_.lower_speed);
      }
      if (value > speed_max)
      {
        return tooFast(name, speed_max);
      }
      lower_speed_[index] = value;
      return ACK;
    case 'B':
      if (!has_value)
      {
        return valueReply(terse_, std::to_string(base_speed_[index]), name + " base speed is ", " positions/sec");
      }
      if (value < lower_speed_[index])
      {
        return tooSlow(lower_speed_[index]);
      }
      if (value > speed_max)
      {
        return tooFast(name, speed_max);
      }
      base_speed_[index] = value;  // answered, not modelled
      return ACK;
    case 'A':
      if (!has_value)
      {
        return valueReply(terse_, std::to_string(acceleration_[index]), name + " acceleration is ", " positions/sec^2");
      }
      if (value <= 0)
      {
        return "! Illegal argument";
      }
      acceleration_[index] = value;  // answered, not modelled
      return ACK;
    default:
      return "! Illegal Command";
  }
}

std::string FlirPtuEmulator::replyToMotion(const std::string& letters, bool has_value, long value, TimePoint at)
{
  const bool pan = letters[0] == 'P';
  const Axis axis = pan ? PAN : TILT;
  const std::size_t index = axisIndex(axis);
  const std::string name = pan ? "Pan" : "Tilt";
  const std::string lower_name = pan ? "pan" : "tilt";
  const long speed_max = std::lround(model_.config().axes[axis].motion.max_speed / resolution_rad_);
  if (letters[1] == 'S')
  {
    if (!has_value)
    {
      const long speed = velocity_mode_ ? velocity_[index] : speed_[index];
      return valueReply(terse_, std::to_string(speed), "Current " + lower_name + " speed is ", " positions/sec");
    }
    if (std::abs(value) > speed_max)
    {
      return tooFast(name, speed_max);
    }
    if (velocity_mode_)
    {
      velocity_[index] = value;
      limit_reported_[index] = false;
      // Pan positions count counter-clockwise: a positive pan velocity turns the camera to the left.
      model_.moveAxisAtVelocity(axis, (pan ? -value : value) * resolution_rad_, at);
      return ACK;
    }
    if (value < lower_speed_[index])
    {
      return tooSlow(lower_speed_[index]);
    }
    speed_[index] = value;
    model_.setCruiseSpeed(axis, value * resolution_rad_, at);
    return ACK;
  }
  if (!has_value)
  {
    return letters[1] == 'O' ?
               "! Illegal Command" :
               valueReply(terse_, std::to_string(position(axis, at)), "Current " + lower_name + " position is ");
  }
  const long target = letters[1] == 'O' ? position(axis, at) + value : value;
  const long min = pan ? config_.pan_min : config_.tilt_min;
  const long max = pan ? config_.pan_max : config_.tilt_max;
  if (limits_enforced_ && target > max)
  {
    return "! Maximum allowable " + name + " position is " + std::to_string(max);
  }
  if (limits_enforced_ && target < min)
  {
    return "! Minimum allowable " + name + " position is " + std::to_string(min);
  }
  model_.goToAxis(axis, toRadians(axis, target), at);  // without enforced limits, the mechanical stop clamps it
  return ACK;
}

}  // namespace ptz_action_server
