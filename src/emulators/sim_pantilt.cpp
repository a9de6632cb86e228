#include "ptz_action_server/emulators/sim_pantilt.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/units.h"

namespace cr
{
namespace pantilt
{
namespace
{
using ptz_action_server::Axis;
using ptz_action_server::PAN;
using ptz_action_server::TILT;
using ptz_action_server::TimePoint;

constexpr double MAX_MOTOR_POSITION = 65535.0;
constexpr double MIN_SPEED_PERCENT = 0.1;  ///< a 0 % speed would never arrive: treated as the slowest speed

/// Half range in degrees of the PanTilt angle on \p axis: pan +-180, tilt +-90.
double halfRange(Axis axis)
{
  return axis == PAN ? 180.0 : 90.0;
}

bool validAngle(Axis axis, double value)
{
  return std::isfinite(value) && std::abs(value) <= halfRange(axis);
}

bool validPercent(double value)
{
  return std::isfinite(value) && value >= 0.0 && value <= 100.0;
}

bool validMotorPosition(double value)
{
  return std::isfinite(value) && value >= 0.0 && value <= MAX_MOTOR_POSITION;
}
}  // namespace

SimPanTilt::SimPanTilt(const ptz_action_server::SimDeviceConfig& config,
                       std::shared_ptr<const ptz_action_server::Clock> clock, WireFormat format)
  : clock_(std::move(clock)), format_(format), model_(config, clock_->now())
{
}

int SimPanTilt::angleToMotorPosition(Axis axis, double angle)
{
  const double half = halfRange(axis);
  return static_cast<int>(std::lround((std::clamp(angle, -half, half) + half) / (2.0 * half) * MAX_MOTOR_POSITION));
}

double SimPanTilt::motorPositionToAngle(Axis axis, double position)
{
  const double half = halfRange(axis);
  return position / MAX_MOTOR_POSITION * 2.0 * half - half;
}

bool SimPanTilt::setParam(PanTiltParam id, float value)
{
  std::lock_guard<std::mutex> lock(mutex_);
  return setParamLocked(id, value, clock_->now());
}

bool SimPanTilt::setParamLocked(PanTiltParam id, float value, TimePoint now)
{
  switch (id)
  {
    case PanTiltParam::PAN_ANGLE:
      return validAngle(PAN, value) && (target_pan_ = value, true);
    case PanTiltParam::TILT_ANGLE:
      return validAngle(TILT, value) && (target_tilt_ = value, true);
    case PanTiltParam::PAN_TILT_ANGLE:
      if (!validAngle(PAN, value))
      {
        return false;
      }
      target_pan_ = value;
      target_tilt_ = std::clamp<double>(value, -halfRange(TILT), halfRange(TILT));
      return true;
    case PanTiltParam::PAN_MOTOR_POSITION:
      return validMotorPosition(value) && (target_pan_ = motorPositionToAngle(PAN, value), true);
    case PanTiltParam::TILT_MOTOR_POSITION:
      return validMotorPosition(value) && (target_tilt_ = motorPositionToAngle(TILT, value), true);
    case PanTiltParam::PAN_TILT_MOTOR_POSITION:
      if (!validMotorPosition(value))
      {
        return false;
      }
      target_pan_ = motorPositionToAngle(PAN, value);
      target_tilt_ = motorPositionToAngle(TILT, value);
      return true;
    case PanTiltParam::PAN_MOTOR_SPEED:
      return validPercent(value) && (setSpeed(PAN, value, now), true);
    case PanTiltParam::TILT_MOTOR_SPEED:
      return validPercent(value) && (setSpeed(TILT, value, now), true);
    case PanTiltParam::PAN_TILT_MOTOR_SPEED:
      if (!validPercent(value))
      {
        return false;
      }
      setSpeed(PAN, value, now);
      setSpeed(TILT, value, now);
      return true;
    case PanTiltParam::CUSTOM_1:
    case PanTiltParam::CUSTOM_2:
    case PanTiltParam::CUSTOM_3:
      custom_[static_cast<int>(id) - static_cast<int>(PanTiltParam::CUSTOM_1)] = value;
      return true;
    case PanTiltParam::IS_CONNECTED:
    case PanTiltParam::IS_OPEN:
      return false;  // read only
  }
  return false;
}

void SimPanTilt::setSpeed(Axis axis, float percent, TimePoint now)
{
  (axis == PAN ? pan_speed_ : tilt_speed_) = percent;
  const double share = std::max<double>(percent, MIN_SPEED_PERCENT) / 100.0;
  model_.setCruiseSpeed(axis, share * model_.config().axes[axis].motion.max_speed, now);
}

float SimPanTilt::getParam(PanTiltParam id) const
{
  PanTiltParams params;
  getParams(params);
  switch (id)
  {
    case PanTiltParam::PAN_MOTOR_POSITION:
      return static_cast<float>(params.panMotorPosition);
    case PanTiltParam::TILT_MOTOR_POSITION:
      return static_cast<float>(params.tiltMotorPosition);
    case PanTiltParam::PAN_ANGLE:
      return params.panAngle;
    case PanTiltParam::TILT_ANGLE:
      return params.tiltAngle;
    case PanTiltParam::PAN_TILT_MOTOR_POSITION:
      return static_cast<float>(params.panTiltMotorPosition);
    case PanTiltParam::PAN_TILT_ANGLE:
      return params.panTiltAngle;
    case PanTiltParam::PAN_MOTOR_SPEED:
      return params.panMotorSpeed;
    case PanTiltParam::TILT_MOTOR_SPEED:
      return params.tiltMotorSpeed;
    case PanTiltParam::PAN_TILT_MOTOR_SPEED:
      return params.panTiltMotorSpeed;
    case PanTiltParam::IS_CONNECTED:
      return params.isConnected ? 1.0f : 0.0f;
    case PanTiltParam::IS_OPEN:
      return params.isOpen ? 1.0f : 0.0f;
    case PanTiltParam::CUSTOM_1:
      return params.custom1;
    case PanTiltParam::CUSTOM_2:
      return params.custom2;
    case PanTiltParam::CUSTOM_3:
      return params.custom3;
  }
  return -1.0f;
}

void SimPanTilt::getParams(PanTiltParams& params) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  fillParams(params, clock_->now());
}

void SimPanTilt::fillParams(PanTiltParams& params, TimePoint now) const
{
  const ptz_action_server::PtzSample sample = model_.sample(now);
  params.panAngle = static_cast<float>(ptz_action_server::toDegrees(sample.position[PAN]));
  params.tiltAngle = static_cast<float>(ptz_action_server::toDegrees(sample.position[TILT]));
  params.panMotorPosition = angleToMotorPosition(PAN, params.panAngle);
  params.tiltMotorPosition = angleToMotorPosition(TILT, params.tiltAngle);
  // The seed gives the combined fields no meaning of their own: they report the pan axis.
  params.panTiltMotorPosition = params.panMotorPosition;
  params.panTiltAngle = params.panAngle;
  params.panMotorSpeed = pan_speed_;
  params.tiltMotorSpeed = tilt_speed_;
  params.panTiltMotorSpeed = pan_speed_;
  params.isConnected = true;
  params.isOpen = true;
  params.custom1 = custom_[0];
  params.custom2 = custom_[1];
  params.custom3 = custom_[2];
}

void SimPanTilt::goToAngles(bool pan, bool tilt, TimePoint now)
{
  if (pan)
  {
    model_.goToAxis(PAN, ptz_action_server::toRadians(target_pan_), now);
  }
  if (tilt)
  {
    model_.goToAxis(TILT, ptz_action_server::toRadians(target_tilt_), now);
  }
}

bool SimPanTilt::executeCommand(PanTiltCommand id, float arg1, float arg2)
{
  std::lock_guard<std::mutex> lock(mutex_);
  const TimePoint now = clock_->now();
  const bool with_arguments = hasCommandArguments(format_);
  auto max_speed = [this](Axis axis) { return model_.config().axes[axis].motion.max_speed; };
  switch (id)
  {
    case PanTiltCommand::RESTART:
      model_.stop(now);
      setSpeed(PAN, 100.0f, now);
      setSpeed(TILT, 100.0f, now);
      return true;
    case PanTiltCommand::STOP:
      model_.stop(now);
      return true;
    case PanTiltCommand::GO_TO_HOME:
      target_pan_ = 0.0;
      target_tilt_ = 0.0;
      goToAngles(true, true, now);
      return true;
    case PanTiltCommand::GO_TO_PAN_ANGLE:
    case PanTiltCommand::GO_TO_TILT_ANGLE:
    case PanTiltCommand::GO_TO_PAN_TILT_ANGLE: {
      const bool pan = id != PanTiltCommand::GO_TO_TILT_ANGLE;
      const bool tilt = id != PanTiltCommand::GO_TO_PAN_ANGLE;
      if (with_arguments)
      {
        // v1.x: the first argument is the first axis' angle, the second (pan-tilt only) the tilt angle.
        const float tilt_value = id == PanTiltCommand::GO_TO_PAN_TILT_ANGLE ? arg2 : arg1;
        if ((pan && !setParamLocked(PanTiltParam::PAN_ANGLE, arg1, now)) ||
            (tilt && !setParamLocked(PanTiltParam::TILT_ANGLE, tilt_value, now)))
        {
          return false;
        }
      }
      goToAngles(pan, tilt, now);
      return true;
    }
    case PanTiltCommand::GO_TO_PAN_POSITION:
    case PanTiltCommand::GO_TO_TILT_POSITION:
    case PanTiltCommand::GO_TO_PAN_TILT_POSITION: {
      const bool pan = id != PanTiltCommand::GO_TO_TILT_POSITION;
      const bool tilt = id != PanTiltCommand::GO_TO_PAN_POSITION;
      if (with_arguments)
      {
        const float tilt_value = id == PanTiltCommand::GO_TO_PAN_TILT_POSITION ? arg2 : arg1;
        if ((pan && !setParamLocked(PanTiltParam::PAN_MOTOR_POSITION, arg1, now)) ||
            (tilt && !setParamLocked(PanTiltParam::TILT_MOTOR_POSITION, tilt_value, now)))
        {
          return false;
        }
      }
      goToAngles(pan, tilt, now);
      return true;
    }
    case PanTiltCommand::MOVE_PAN:
    case PanTiltCommand::MOVE_TILT:
    case PanTiltCommand::MOVE_PAN_TILT: {
      if (!with_arguments)
      {
        return false;
      }
      const float tilt_speed = id == PanTiltCommand::MOVE_PAN_TILT ? arg2 : arg1;
      const bool pan = id != PanTiltCommand::MOVE_TILT;
      const bool tilt = id != PanTiltCommand::MOVE_PAN;
      if ((pan && !(std::isfinite(arg1) && std::abs(arg1) <= 100.0f)) ||
          (tilt && !(std::isfinite(tilt_speed) && std::abs(tilt_speed) <= 100.0f)))
      {
        return false;
      }
      if (pan)
      {
        model_.moveAxisAtVelocity(PAN, arg1 / 100.0 * max_speed(PAN), now);
      }
      if (tilt)
      {
        model_.moveAxisAtVelocity(TILT, tilt_speed / 100.0 * max_speed(TILT), now);
      }
      return true;
    }
  }
  return false;
}

bool SimPanTilt::decodeAndExecuteCommand(const std::uint8_t* data, int size)
{
  PanTiltParam param{};
  PanTiltCommand command{};
  float value = 0.0f;
  float second = 0.0f;
  switch (decodeCommand(data, size, param, command, value, format_, &second))
  {
    case 0:
      return executeCommand(command, value, second);
    case 1:
      return setParam(param, value);
    default:
      return false;
  }
}

ptz_action_server::PtzSample SimPanTilt::sample() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return model_.sample(clock_->now());
}

void SimPanTilt::setFaults(const ptz_action_server::SimFaults& faults)
{
  std::lock_guard<std::mutex> lock(mutex_);
  model_.setFaults(faults, clock_->now());
}

}  // namespace pantilt
}  // namespace cr
