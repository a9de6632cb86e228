#include "ptz_action_server/emulators/flir_ptu_emulator.h"

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
constexpr std::size_t MAX_TOKEN = 32;
const char* const BANNER = "\r\nPan-Tilt Controller v3.4.3 (ptz_action_server emulator)\r\n"
                           "(C)2010-2024 FLIR Commercial Systems, Inc., All Rights Reserved\r\nInitializing...\r\n";
/// What an E-series unit sends on every TCP connection (published-wire-facts.md, section 3); the last line comes once
/// the unit is ready, more than 0.1 s later.
const char* const TCP_BANNER = "\r\n\r\n### PAN-TILT CONTROLLER\r\n"
                               "### v3.3.0, (C)2010-2011 FLIR Commercial Systems, Inc., All Rights Reserved\r\n";
const char* const TCP_BANNER_END = "Initializing...*\r\n";
constexpr double TCP_BANNER_DELAY = 0.15;

bool isDelimiter(char character)
{
  return character == ' ' || character == '\r' || character == '\n';
}

SimDeviceConfig modelConfig(const FlirPtuEmulatorConfig& config)
{
  const double resolution = arcSecondsToRadians(config.resolution);
  SimDeviceConfig model = SimDeviceConfig::defaults();
  // The unit's positive pan is counter-clockwise; the model's is the contract's clockwise.
  model.axes[PAN].range = AxisRange{ -config.pan_max * resolution, -config.pan_min * resolution };
  model.axes[PAN].motion = AxisMotionLimits{ config.pan_max_speed, config.acceleration, 0.0 };
  model.axes[PAN].resolution = resolution;
  model.axes[TILT].range = AxisRange{ config.tilt_min * resolution, config.tilt_max * resolution };
  model.axes[TILT].motion = AxisMotionLimits{ config.tilt_max_speed, config.acceleration, 0.0 };
  model.axes[TILT].resolution = resolution;
  model.axes[ZOOM].present = false;
  model.axes[ZOOM].range = AxisRange{ 1.0, 1.0 };
  model.axes[ZOOM].initial_position = 1.0;
  return model;
}
}  // namespace

FlirPtuEmulator::FlirPtuEmulator(const FlirPtuEmulatorConfig& config)
  : LineEmulator(modelConfig(config)), config_(config), resolution_rad_(arcSecondsToRadians(config.resolution))
{
  // Under the lock: the port's thread waits until the unit has powered up.
  std::lock_guard<std::mutex> lock(mutex_);
  openPort(config.port, DevicePort::Handlers{ [this](const std::uint8_t* data, std::size_t size, TimePoint at) {
                                               onBytes(data, size, at);
                                             },
                                              [this] { onTick(); }, [this] { greet(); } });
  powerUp();
}

FlirPtuEmulator::~FlirPtuEmulator()
{
  closePort();
}

void FlirPtuEmulator::powerUp()
{
  echo_ = config_.banner;
  terse_ = !config_.banner;
  velocity_mode_ = false;
  token_.clear();
  speed_ = { { std::lround(config_.pan_max_speed / resolution_rad_),
               std::lround(config_.tilt_max_speed / resolution_rad_) } };
  velocity_ = { { 0, 0 } };
  if (config_.banner && config_.port.kind == DevicePortConfig::Kind::PTY)
  {
    port_->send(BANNER);
  }
}

void FlirPtuEmulator::greet()
{
  std::lock_guard<std::mutex> lock(mutex_);
  token_.clear();
  if (!config_.banner)
  {
    return;
  }
  echo_ = true;
  terse_ = false;
  port_->send(TCP_BANNER);
  banner_ready_at_ = addSeconds(SteadyClock::now(), TCP_BANNER_DELAY);
  banner_pending_ = true;
}

void FlirPtuEmulator::onBytes(const std::uint8_t* data, std::size_t size, TimePoint arrived_at)
{
  const double byte_time = port_->byteTime();
  std::string echo;
  std::vector<std::pair<std::string, TimePoint>> commands;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    for (std::size_t index = 0; index < size; ++index)
    {
      const char character = static_cast<char>(data[index]);
      if (echo_)
      {
        echo.push_back(character);
      }
      if (isDelimiter(character))
      {
        if (!token_.empty())
        {
          // This byte crossed the line (size - 1 - index) byte times before the chunk's last one.
          commands.emplace_back(token_, addSeconds(arrived_at, -(static_cast<double>(size - 1 - index) * byte_time)));
          token_.clear();
        }
        continue;
      }
      if (token_.size() < MAX_TOKEN)
      {
        token_.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(character))));
      }
    }
  }
  if (!echo.empty())
  {
    port_->send(echo);
  }
  for (const auto& command : commands)
  {
    execute(command.first, command.second);
  }
}

void FlirPtuEmulator::execute(const std::string& command, TimePoint at)
{
  std::size_t letters_end = 0;
  while (letters_end < command.size() && std::isalpha(static_cast<unsigned char>(command[letters_end])))
  {
    ++letters_end;
  }
  const std::string letters = command.substr(0, letters_end);
  const std::string argument = command.substr(letters_end);
  long value = 0;
  bool has_value = false;
  bool valid_argument = true;
  if (!argument.empty())
  {
    char* end = nullptr;
    value = std::strtol(argument.c_str(), &end, 10);
    has_value = true;
    valid_argument = end != argument.c_str() && *end == '\0';
  }
  std::string answer;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    answer = valid_argument ? reply(letters, has_value, value, at) : "! Illegal argument";
  }
  received_.add(ReceivedCommand{ at, command });
  port_->send(answer + "\r\n");
}

long FlirPtuEmulator::position(Axis axis, TimePoint at)
{
  const double radians = model_.sample(at).position[axis];
  return std::lround((axis == PAN ? -radians : radians) / resolution_rad_);
}

double FlirPtuEmulator::toRadians(Axis axis, long position) const
{
  return (axis == PAN ? -position : position) * resolution_rad_;
}

std::string FlirPtuEmulator::reply(const std::string& letters, bool has_value, long value, TimePoint at)
{
  auto ok = [this](const char* verbose) { return terse_ ? std::string("*") : std::string("* ") + verbose; };
  auto number = [this](const char* name, const std::string& text) {
    return terse_ ? "* " + text : std::string("* Current ") + name + " is " + text;
  };
  const bool pan = !letters.empty() && letters[0] == 'P';
  const Axis axis = pan ? PAN : TILT;
  const std::size_t index = pan ? 0 : 1;
  const char* axis_name = pan ? "Pan" : "Tilt";
  const long min = pan ? config_.pan_min : config_.tilt_min;
  const long max = pan ? config_.pan_max : config_.tilt_max;
  const long speed_max = std::lround(model_.config().axes[axis].motion.max_speed / resolution_rad_);

  if (letters == "FT" || letters == "FV")
  {
    terse_ = letters == "FT";
    return ok("Terse feedback mode");
  }
  if (letters == "ED" || letters == "EE")
  {
    echo_ = letters == "EE";
    return ok("Echoing");
  }
  if (letters == "CI" || letters == "CV")
  {
    velocity_mode_ = letters == "CV";
    velocity_ = { { 0, 0 } };
    return ok(velocity_mode_ ? "Velocity control mode" : "Position control mode");
  }
  if (letters == "H" || letters == "HP" || letters == "HT")
  {
    for (Axis halted : { PAN, TILT })
    {
      if (letters == "H" || (letters == "HP") == (halted == PAN))
      {
        model_.moveAxisAtVelocity(halted, 0.0, at);
        velocity_[halted == PAN ? 0 : 1] = 0;
      }
    }
    return ok("Halting");
  }
  if (letters == "R")
  {
    model_.goTo(AxisValues{ { 0.0, 0.0, 1.0 } }, at);
    return ok("Resetting");
  }
  if (letters == "LE" || letters == "LD" || letters == "PA" || letters == "TA")
  {
    return ok("Accepted");  // soft limits and accelerations: accepted, not modelled
  }
  if (letters == "PR" || letters == "TR")
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%.4f", config_.resolution);
    return terse_ ? std::string("* ") + text : std::string("* ") + text + " seconds arc per position";
  }
  if (letters == "PN" || letters == "PX" || letters == "TN" || letters == "TX")
  {
    if (has_value)
    {
      return "! Limits are fixed";
    }
    return number(letters[1] == 'N' ? "minimum position" : "maximum position",
                  std::to_string(letters[1] == 'N' ? min : max));
  }
  if (letters == "PU" || letters == "TU")
  {
    return has_value ? "! Upper speed is fixed" : number("upper speed limit", std::to_string(speed_max));
  }
  if (letters == "PP" || letters == "TP" || letters == "PO" || letters == "TO")
  {
    if (!has_value)
    {
      return letters[1] == 'O' ? "! Illegal Command" :
                                 number(pan ? "Pan position" : "Tilt position", std::to_string(position(axis, at)));
    }
    const long target = letters[1] == 'O' ? position(axis, at) + value : value;
    if (target < min || target > max)
    {
      return std::string("! Maximum allowable ") + axis_name + " position exceeded";
    }
    model_.goToAxis(axis, toRadians(axis, target), at);
    return ok("Moving");
  }
  if (letters == "PS" || letters == "TS")
  {
    if (!has_value)
    {
      return number(pan ? "Pan speed" : "Tilt speed",
                    std::to_string(velocity_mode_ ? velocity_[index] : speed_[index]));
    }
    if (std::abs(value) > speed_max || (!velocity_mode_ && value <= 0))
    {
      return std::string("! Maximum allowable ") + axis_name + " speed exceeded";
    }
    if (velocity_mode_)
    {
      velocity_[index] = value;
      limit_reported_[index] = false;
      // Pan positions count counter-clockwise: a positive pan velocity turns the camera to the left.
      model_.moveAxisAtVelocity(axis, (pan ? -value : value) * resolution_rad_, at);
    }
    else
    {
      speed_[index] = value;
      model_.setCruiseSpeed(axis, value * resolution_rad_, at);
    }
    return ok("Speed set");
  }
  return "! Illegal Command";
}

void FlirPtuEmulator::onTick()
{
  std::string reports;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const TimePoint now = SteadyClock::now();
    if (banner_pending_ && now >= banner_ready_at_)
    {
      banner_pending_ = false;
      reports += TCP_BANNER_END;
    }
    // A velocity move that runs into a limit stops there, and the unit says so.
    for (Axis axis : { PAN, TILT })
    {
      const std::size_t index = axis == PAN ? 0 : 1;
      if (!velocity_mode_ || limit_reported_[index])
      {
        continue;
      }
      const long at = position(axis, now);
      const long min = axis == PAN ? config_.pan_min : config_.tilt_min;
      const long max = axis == PAN ? config_.pan_max : config_.tilt_max;
      if ((velocity_[index] > 0 && at >= max - 1) || (velocity_[index] < 0 && at <= min + 1))
      {
        limit_reported_[index] = true;
        reports += axis == PAN ? "!P\r\n" : "!T\r\n";
      }
    }
  }
  if (!reports.empty())
  {
    port_->send(reports);
  }
}

}  // namespace ptz_action_server
