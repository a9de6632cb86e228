#include "ptz_action_server/emulators/flir_ptu_emulator.h"

#include <cctype>
#include <cmath>
#include <cstdlib>

#include "ptz_action_server/core/units.h"

// The unit on its line: power-up, banners, echo, commands as they arrive, and what it reports on its own (limit hits,
// the reset calibration). What it answers to each command is in flir_ptu_emulator_answers.cpp.

namespace ptz_action_server
{
namespace
{
constexpr std::size_t MAX_TOKEN = 32;
/// What this emulator prints at power-up on a serial line (the real D46 text is not published).
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
                                              [this] { onTick(); },
                                              [this] { greet(); },
                                              {} });
  powerUp();
}

FlirPtuEmulator::~FlirPtuEmulator()
{
  closePort();
}

void FlirPtuEmulator::powerUp()
{
  const TimePoint now = SteadyClock::now();
  echo_ = config_.banner;
  terse_ = !config_.banner;
  velocity_mode_ = false;
  limits_enforced_ = true;
  token_.clear();
  after_cr_ = false;
  calibration_.clear();
  velocity_ = { { 0, 0 } };
  for (Axis axis : { PAN, TILT })
  {
    const std::size_t index = axisIndex(axis);
    const AxisMotionLimits& motion = model_.config().axes[axis].motion;
    speed_[index] = std::lround(motion.max_speed / resolution_rad_);
    model_.setCruiseSpeed(axis, motion.max_speed, now);
    lower_speed_[index] = config_.lower_speed;
    base_speed_[index] = config_.base_speed;
    acceleration_[index] = std::lround(motion.acceleration / resolution_rad_);
  }
  if (config_.banner && config_.port.kind == DevicePortConfig::Kind::PTY)
  {
    port_->send(BANNER);  // lost unless a client has the port open now
  }
}

void FlirPtuEmulator::greet()
{
  std::lock_guard<std::mutex> lock(mutex_);
  token_.clear();
  after_cr_ = false;
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
  std::lock_guard<std::mutex> lock(mutex_);
  // Byte by byte, as the unit reads them: a command's echo and reply go out before the next command is read, and a
  // command takes effect for the ones after it (`ED` is still echoed, the command after it is not).
  std::string out;
  for (std::size_t index = 0; index < size && calibration_.empty(); ++index)
  {
    const char character = static_cast<char>(data[index]);
    if (echo_)
    {
      echo(character, out);
    }
    if (!isDelimiter(character))
    {
      if (token_.size() < MAX_TOKEN)
      {
        token_.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(character))));
      }
      continue;
    }
    if (token_.empty())
    {
      continue;
    }
    // This byte crossed the line (size - 1 - index) byte times before the chunk's last one.
    const TimePoint at = addSeconds(arrived_at, -(static_cast<double>(size - 1 - index) * byte_time));
    const std::string command = token_;
    token_.clear();
    if (!out.empty())
    {
      port_->send(out);  // the echo goes first: whatever the command says follows it
      out.clear();
    }
    const std::string answer = execute(command, at);
    if (!answer.empty())
    {
      port_->send(answer + "\r\n");
    }
  }
  if (!out.empty())
  {
    port_->send(out);
  }
}

void FlirPtuEmulator::echo(char character, std::string& out)
{
  if (character == '\r' || character == '\n')
  {
    if (!(character == '\n' && after_cr_))
    {
      out += "\r\n";
    }
  }
  else
  {
    out.push_back(character);
  }
  after_cr_ = character == '\r';
}

std::string FlirPtuEmulator::execute(const std::string& command, TimePoint at)
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
  received_.add(ReceivedCommand{ at, command });
  return valid_argument ? reply(letters, has_value, value, at) : "! Illegal argument";
}

void FlirPtuEmulator::startCalibration(TimePoint at)
{
  // Tilt first; each axis hits both its limits (a report each), then comes home.
  calibration_ = { { TILT, config_.tilt_max, "!T" }, { TILT, config_.tilt_min, "!T" }, { TILT, 0, "" },
                   { PAN, config_.pan_max, "!P" },   { PAN, config_.pan_min, "!P" },   { PAN, 0, "*\r\n" } };
  velocity_ = { { 0, 0 } };  // a velocity move ends; the control mode stays
  model_.stop(at);
  model_.goToAxis(TILT, toRadians(TILT, config_.tilt_max), at);
}

void FlirPtuEmulator::calibrate(TimePoint now, std::string& out)
{
  if (calibration_.empty() || model_.sample(now).moving)
  {
    return;
  }
  const CalibrationStep step = calibration_.front();
  if (std::abs(position(step.axis, now) - step.target) > 1)
  {
    return;  // not started yet (a lagging unit), or a stalled axis: the calibration never ends
  }
  out += step.report;
  calibration_.pop_front();
  if (!calibration_.empty())
  {
    const CalibrationStep& next = calibration_.front();
    model_.goToAxis(next.axis, toRadians(next.axis, next.target), now);
  }
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
    calibrate(now, reports);
    // A velocity move that runs into a limit stops there, and the unit says so.
    for (Axis axis : { PAN, TILT })
    {
      const std::size_t index = axisIndex(axis);
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
