#include "ptz_action_server/core/pantilt/pantilt_protocol.h"

#include <algorithm>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
using cr::pantilt::DecodeError;
using cr::pantilt::PanTilt;
using cr::pantilt::PanTiltCommand;
using cr::pantilt::PanTiltParam;
}  // namespace

PanTiltProtocol::PanTiltProtocol(const PanTiltSettings& settings, DeviceSession& session)
  : settings_(settings), session_(session)
{
}

Capabilities PanTiltProtocol::capabilities() const
{
  Capabilities capabilities;
  const double speed_share[] = { settings_.pan_speed / 100.0, settings_.tilt_speed / 100.0 };
  for (Axis axis : { PAN, TILT })
  {
    capabilities.axes[axis] = settings_.axes[axis];
    capabilities.axes[axis].max_speed *= speed_share[axis];
    // A position goal's speed is its motor-speed params, set before its move.
    capabilities.speed.control[axis] = SpeedControl::DEVICE;
    capabilities.speed.min_speed[axis] =
        std::min(MIN_SPEED_PERCENT / 100.0 * settings_.axes[axis].max_speed, capabilities.axes[axis].max_speed);
  }
  capabilities.axes[ZOOM] = absentAxis("a PanTilt controller has no zoom");
  capabilities.device_home = true;  // GO_TO_HOME
  return capabilities;
}

void PanTiltProtocol::onConnected()
{
  heard_ = false;
  slip_.reset();
  // The speeds first, then a state request: they reach the device in order, ahead of any goal's frames.
  sendSpeeds();
  sendStateRequest();
}

void PanTiltProtocol::onReceived(const std::uint8_t* data, std::size_t size)
{
  if (session_.carriesDatagrams())
  {
    handleFrame(data, size);
    return;
  }
  slip_.feed(data, size, [this](const std::uint8_t* frame, std::size_t length) { handleFrame(frame, length); });
  counters_.bad_framing.set(slip_.counts().bad_escapes + slip_.counts().overlong);
  session_.reportDropped(slip_.counts().dropped_bytes - dropped_reported_);
  dropped_reported_ = slip_.counts().dropped_bytes;
}

void PanTiltProtocol::handleFrame(const std::uint8_t* data, std::size_t size)
{
  DecodeError error = DecodeError::NONE;
  cr::pantilt::PanTiltParams params;
  // Longer than any params frame: a bad size, whatever its first bytes say.
  const bool oversized = size > static_cast<std::size_t>(cr::pantilt::MAX_PARAMS_FRAME_SIZE);
  if (oversized || !params.decode(data, static_cast<int>(size), settings_.format, &error))
  {
    session_.reportDropped(size);
    switch (oversized ? DecodeError::BAD_SIZE : error)
    {
      case DecodeError::BAD_HEADER:
        ++counters_.bad_header;
        break;
      case DecodeError::BAD_VERSION:
        ++counters_.bad_version;
        break;
      case DecodeError::BAD_MASK:
        ++counters_.bad_mask;
        break;
      case DecodeError::BAD_VALUE:
        ++counters_.bad_value;
        break;
      case DecodeError::FOREIGN_FORMAT:
        ++counters_.foreign_format_frames;
        if (!heard_)
        {
          // The device speaks another format: waiting for the start-up timeout would only hide why.
          session_.failStartup(formatText("it answers in another PanTilt wire format than the configured %s: set "
                                          "format to the device's (seed, v1.0 or v1.1)",
                                          cr::pantilt::toString(settings_.format)));
        }
        break;
      default:
        ++counters_.bad_size;
        break;
    }
    return;
  }
  ++counters_.frames_ok;
  heard_ = true;
  last_frame_at_ = session_.now();
  session_.ready();
  session_.reportState(AxisValues{ { toRadians(params.panAngle), toRadians(params.tiltAngle), 1.0 } });
}

void PanTiltProtocol::poll()
{
  // Ask for state while the device is quiet (at start, or silent): its periodic frames make this unnecessary.
  const TimePoint now = session_.now();
  const bool quiet = !heard_ || secondsBetween(last_frame_at_, now) >= settings_.state_request_period;
  if (quiet && secondsBetween(last_request_at_, now) >= settings_.state_request_period)
  {
    sendStateRequest();
  }
}

void PanTiltProtocol::goTo(const AxisValues& position)
{
  goToAtSpeed(position, AxisValues{});
}

void PanTiltProtocol::goToAtSpeed(const AxisValues& position, const AxisValues& speed)
{
  const double configured[] = { settings_.pan_speed, settings_.tilt_speed };
  double percent[2] = {};
  for (Axis axis : { PAN, TILT })
  {
    const double asked = 100.0 * speed[axis] / settings_.axes[axis].max_speed;
    percent[axis] = speed[axis] > 0.0 ?
                        std::clamp(asked, std::min(MIN_SPEED_PERCENT, configured[axis]), configured[axis]) :
                        configured[axis];
  }
  sendSpeeds(percent[PAN], percent[TILT]);
  if (cr::pantilt::hasCommandArguments(settings_.format))
  {
    sendCommand(PanTiltCommand::GO_TO_PAN_TILT_ANGLE, toDegrees(position[PAN]), toDegrees(position[TILT]));
    return;
  }
  sendSetParam(PanTiltParam::PAN_ANGLE, toDegrees(position[PAN]));
  sendSetParam(PanTiltParam::TILT_ANGLE, toDegrees(position[TILT]));
  sendCommand(PanTiltCommand::GO_TO_PAN_TILT_ANGLE);
}

void PanTiltProtocol::moveAtVelocity(const AxisValues& velocity)
{
  const double percent[] = { 100.0 * velocity[PAN] / settings_.axes[PAN].max_speed,
                             100.0 * velocity[TILT] / settings_.axes[TILT].max_speed };
  if (cr::pantilt::hasCommandArguments(settings_.format))
  {
    sendCommand(PanTiltCommand::MOVE_PAN_TILT, percent[PAN], percent[TILT]);
    return;
  }
  // The seed's format has no velocity command: move towards the limit at that speed. An axis at 0 holds where it is.
  const PtzSample current = session_.estimate();
  const PanTiltParam speed_param[] = { PanTiltParam::PAN_MOTOR_SPEED, PanTiltParam::TILT_MOTOR_SPEED };
  const PanTiltParam angle_param[] = { PanTiltParam::PAN_ANGLE, PanTiltParam::TILT_ANGLE };
  const double configured_speed[] = { settings_.pan_speed, settings_.tilt_speed };
  for (Axis axis : { PAN, TILT })
  {
    const AxisRange& range = settings_.axes[axis].range;
    const bool holds = velocity[axis] == 0.0;
    const double target = holds ? current.position[axis] : (velocity[axis] > 0.0 ? range.max : range.min);
    sendSetParam(speed_param[axis], holds ? configured_speed[axis] : std::min(100.0, std::abs(percent[axis])));
    sendSetParam(angle_param[axis], toDegrees(target));
  }
  sendCommand(PanTiltCommand::GO_TO_PAN_TILT_ANGLE);
}

void PanTiltProtocol::stop()
{
  sendCommand(PanTiltCommand::STOP);
}

void PanTiltProtocol::hold()
{
  // Whatever the device was doing belongs to a goal that has ended; the next position goal runs at the set speeds.
  sendCommand(PanTiltCommand::STOP);
  sendSpeeds();
}

void PanTiltProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("format", cr::pantilt::toString(settings_.format));
  addCounts(values, { { "frames ok", counters_.frames_ok },
                      { "dropped: bad size", counters_.bad_size },
                      { "dropped: bad header", counters_.bad_header },
                      { "dropped: bad version", counters_.bad_version },
                      { "dropped: bad mask", counters_.bad_mask },
                      { "dropped: bad value", counters_.bad_value },
                      { "dropped: foreign format", counters_.foreign_format_frames },
                      { "dropped: bad SLIP framing", counters_.bad_framing } });
}

void PanTiltProtocol::sendSetParam(PanTiltParam id, double value)
{
  std::uint8_t frame[cr::pantilt::SET_PARAM_SIZE];
  int size = 0;
  if (PanTilt::encodeSetParamCommand(frame, size, id, static_cast<float>(value), settings_.format))
  {
    send(frame, static_cast<std::size_t>(size));
  }
}

void PanTiltProtocol::sendCommand(PanTiltCommand id, double arg1, double arg2)
{
  std::uint8_t frame[cr::pantilt::MAX_COMMAND_SIZE];
  int size = 0;
  if (PanTilt::encodeCommand(frame, size, id, settings_.format, static_cast<float>(arg1), static_cast<float>(arg2)))
  {
    send(frame, static_cast<std::size_t>(size));
  }
}

void PanTiltProtocol::sendSpeeds()
{
  sendSpeeds(settings_.pan_speed, settings_.tilt_speed);
}

void PanTiltProtocol::sendSpeeds(double pan_percent, double tilt_percent)
{
  sendSetParam(PanTiltParam::PAN_MOTOR_SPEED, pan_percent);
  sendSetParam(PanTiltParam::TILT_MOTOR_SPEED, tilt_percent);
}

void PanTiltProtocol::sendStateRequest()
{
  // A params frame with an empty mask asks for the device's params and changes nothing.
  const cr::pantilt::PanTiltParamsMask empty = cr::pantilt::PanTiltParamsMask::none();
  std::uint8_t frame[cr::pantilt::PARAMS_HEADER_SIZE];
  int size = 0;
  cr::pantilt::PanTiltParams().encode(frame, sizeof(frame), size, &empty, settings_.format);
  last_request_at_ = session_.now();
  send(frame, static_cast<std::size_t>(size));
}

void PanTiltProtocol::send(const std::uint8_t* frame, std::size_t size)
{
  if (session_.carriesDatagrams())
  {
    session_.write(frame, size);  // a datagram is a frame
    return;
  }
  framed_.clear();  // keeps its capacity: no allocation once the first frames went out
  slip::encode(frame, size, framed_);
  session_.write(framed_.data(), framed_.size());
}

}  // namespace ptz_action_server
