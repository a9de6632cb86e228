#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"

#include <algorithm>
#include <limits>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
/// A query and its reply: two frames.
constexpr std::size_t PELCO_EXCHANGE_BYTES = 2 * pelco::FRAME_SIZE;
/// The speed byte of the set-position check's probe: a quarter of the top speed, toward the target.
constexpr int PROBE_SPEED = 0x10;
/// What the check counts as movement: a tenth of a degree (ten position units), a hundredth of the zoom range.
constexpr double MOVED_DEGREES = 0.1;
constexpr double MOVED_ZOOM_SHARE = 0.01;

/// A speed (rad/s, X/s) as a Pelco speed byte 1..0x3F, signed; 0 stays 0.
int speedByte(double speed, double max_speed)
{
  if (speed == 0.0 || !(max_speed > 0.0))
  {
    return 0;
  }
  const int magnitude = std::clamp(static_cast<int>(std::lround(std::abs(speed) / max_speed * pelco::MAX_SPEED)), 1,
                                   static_cast<int>(pelco::MAX_SPEED));
  return speed > 0.0 ? magnitude : -magnitude;
}

int direction(double value)
{
  return value > 0.0 ? 1 : (value < 0.0 ? -1 : 0);
}

pelco::SetPositionCheck::Config checkConfig(const PelcoSettings& settings)
{
  pelco::SetPositionCheck::Config config;
  config.wait = settings.set_position_wait;
  config.moved[PAN] = config.moved[TILT] = toRadians(MOVED_DEGREES);
  const AxisRange& zoom = settings.axes[ZOOM].range;
  config.moved[ZOOM] = MOVED_ZOOM_SHARE * (zoom.max - zoom.min);
  return config;
}

/// The goal's fault and the warning when the check finds a device that ignores set-position.
const char* const IGNORES_SET_POSITION = "this Pelco-D camera ignores set-position (0x4B, 0x4D, 0x4F): it stayed "
                                         "where it was, and a speed command moved it; position goals are steered "
                                         "on speed commands and its position queries from the next goal on (set "
                                         "pelco_d/set_position: false to say so from the start)";
}  // namespace

std::uint16_t PelcoSettings::zoomToPosition(double zoom) const
{
  const AxisRange& range = axes[ZOOM].range;
  const double share =
      range.max > range.min ? (std::clamp(zoom, range.min, range.max) - range.min) / (range.max - range.min) : 0.0;
  return static_cast<std::uint16_t>(std::lround(share * zoom_position_max));
}

double PelcoSettings::positionToZoom(std::uint16_t position) const
{
  const AxisRange& range = axes[ZOOM].range;
  const double share = zoom_position_max > 0 ? std::min(1.0, double(position) / zoom_position_max) : 0.0;
  return range.min + share * (range.max - range.min);
}

PelcoProtocol::PelcoProtocol(const PelcoSettings& settings, DeviceSession& session)
  : settings_(settings)
  , session_(session)
  , channel_(
        session, [&session](const std::string& bytes) { session.write(bytes); },
        replyTimeout(session.linkConfig(), settings.reply_timeout, PELCO_EXCHANGE_BYTES),
        [this](const TransactionChannel::Request&) {
          parser_.reset();
          round_.broken();
        })
  , parser_(settings.address, settings.general_reply)
  , round_(settings.axes[ZOOM].present ? 3 : 2)
  , set_position_check_(checkConfig(settings))
{
  motion_ = pelco::stop(settings_.address);
}

std::string PelcoProtocol::deviceName() const
{
  return "a Pelco-D device (address " + std::to_string(settings_.address) + ")";
}

Capabilities PelcoProtocol::capabilities() const
{
  Capabilities capabilities;
  capabilities.axes = settings_.axes;
  if (settings_.turbo_byte != 0)
  {
    capabilities.axes[PAN].max_speed = std::max(settings_.axes[PAN].max_speed, settings_.turbo_speed);
  }
  if (!takesSetPosition())
  {
    // It moves at a speed and answers the position queries: the node steers its position goals on them.
    const bool configured = settings_.set_position == PelcoSetPosition::NO;
    for (AxisCapability& axis : capabilities.axes)
    {
      axis.absolute = false;
      axis.limitation = configured ? "pelco_d/set_position is false: this camera takes no set-position (0x4B, 0x4D, "
                                     "0x4F)" :
                                     "this Pelco-D camera ignores set-position (0x4B, 0x4D, 0x4F)";
      axis.remedy = configured ? "" : "set pelco_d/set_position: false to say so from the start";
    }
  }
  capabilities.lens = pelcoLens(settings_);
  if (!capabilities.axes[ZOOM].present)
  {
    capabilities.axes[ZOOM] = absentAxis("this Pelco-D device is configured without zoom");
    capabilities.axes[ZOOM].remedy = "set pelco_d/zoom/present if it has one";
  }
  capabilities.device_presets = true;  // set, clear and go to preset (0x03, 0x05, 0x07)
  return capabilities;
}

void PelcoProtocol::onConnected()
{
  channel_.reset();
  parser_.reset();
  round_.broken();
}

void PelcoProtocol::onDisconnected()
{
  channel_.reset();
  set_position_check_.cancel();
}

void PelcoProtocol::poll()
{
  if (channel_.polling())
  {
    return;  // goal commands first; the position when the line is free
  }
  queueFrame(pelco::withValue(settings_.address, pelco::QUERY_PAN, 0), QUERY_PAN);
  queueFrame(pelco::withValue(settings_.address, pelco::QUERY_TILT, 0), QUERY_TILT);
  if (settings_.axes[ZOOM].present)
  {
    queueFrame(pelco::withValue(settings_.address, pelco::QUERY_ZOOM, 0), QUERY_ZOOM);
  }
}

void PelcoProtocol::goTo(const AxisValues& position)
{
  if (!session_.connected())
  {
    return;
  }
  channel_.clearQueue();  // what the previous command had not sent yet
  if (set_position_check_.probing())
  {
    // The probe's speed would go on: a set-position may not end it.
    queueFrame(pelco::stop(settings_.address), COMMAND);
  }
  set_position_check_.cancel();
  motion_ = pelco::stop(settings_.address);  // a lens command from now on goes with no drive
  const bool zoom = settings_.axes[ZOOM].present && !std::isnan(position[ZOOM]);
  if (!takesSetPosition())
  {
    // The node steers such a device on speed commands; a caller that did not is told why nothing moves.
    if (!std::isnan(position[PAN]) || !std::isnan(position[TILT]) || zoom)
    {
      session_.reportFault("not sent: " + capabilities().axes[PAN].limitation, session_.currentCommand());
    }
    return;
  }
  const std::uint8_t address = settings_.address;
  if (!std::isnan(position[PAN]))
  {
    queueFrame(pelco::withValue(address, pelco::SET_PAN, pelco::encodePan(toDegrees(position[PAN]))), COMMAND);
  }
  if (!std::isnan(position[TILT]))
  {
    queueFrame(pelco::withValue(address, pelco::SET_TILT,
                                pelco::encodeTilt(toDegrees(position[TILT]), settings_.tilt_encoding)),
               COMMAND);
  }
  if (zoom)
  {
    queueFrame(pelco::withValue(address, pelco::SET_ZOOM, settings_.zoomToPosition(position[ZOOM])), COMMAND);
  }
  // Only from rest: a device still moving at a speed would seem to obey a set-position it ignores.
  if (settings_.set_position == PelcoSetPosition::AUTO && !session_.estimate().moving)
  {
    AxisValues target = position;
    target[ZOOM] = zoom ? position[ZOOM] : std::numeric_limits<double>::quiet_NaN();
    if (set_position_check_.begin(reported_, target, session_.now()))
    {
      checked_command_ = session_.currentCommand();
    }
  }
}

void PelcoProtocol::moveAtVelocity(const AxisValues& velocity)
{
  if (!session_.connected())
  {
    return;
  }
  channel_.clearQueue();  // what the previous command had not sent yet
  set_position_check_.cancel();
  const int zoom = settings_.axes[ZOOM].present ? direction(velocity[ZOOM]) : 0;
  // Turbo is one speed, not a range: the byte nearest the speed asked, so that a device steered on its speeds never
  // turns twice as fast as asked (speeds between the 0x3F speed and the midpoint go at the 0x3F speed).
  const bool turbo = settings_.turbo_byte != 0 &&
                     std::abs(velocity[PAN]) > 0.5 * (settings_.axes[PAN].max_speed + settings_.turbo_speed);
  const int pan = turbo ? (velocity[PAN] > 0.0 ? pelco::MAX_SPEED + 1 : -(pelco::MAX_SPEED + 1)) :
                          speedByte(velocity[PAN], settings_.axes[PAN].max_speed);
  motion_ = pelco::move(settings_.address, pan, speedByte(velocity[TILT], settings_.axes[TILT].max_speed), zoom,
                        settings_.turbo_byte);
  queueFrame(pelco::withLens(motion_, focus_drive_, iris_drive_), COMMAND);
}

void PelcoProtocol::stop()
{
  if (!session_.connected())
  {
    return;
  }
  set_position_check_.cancel();
  stopNow();
}

void PelcoProtocol::stopNow()
{
  channel_.clearQueue();  // what the previous command had not sent yet
  motion_ = pelco::stop(settings_.address);
  focus_drive_ = iris_drive_ = 0;  // the all-zero frame stops the lens too
  const pelco::Bytes bytes = pelco::encode(motion_);
  channel_.sendUrgent(TransactionChannel::Request{ std::string(bytes.begin(), bytes.end()), COMMAND,
                                                   settings_.general_reply, session_.currentCommand() });
}

void PelcoProtocol::queueFrame(const pelco::Frame& frame, Tag tag)
{
  const pelco::Bytes bytes = pelco::encode(frame);
  const bool expects_reply = tag != COMMAND || settings_.general_reply;
  channel_.queue(TransactionChannel::Request{ std::string(bytes.begin(), bytes.end()), tag, expects_reply,
                                              session_.currentCommand(), tag != COMMAND });
}

void PelcoProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  addCounts(values, { { "address", settings_.address },
                      { "frames", counters_.frames },
                      { "dropped: bad checksum or partial", counters_.bad_checksum },
                      { "dropped: bytes outside frames", counters_.skipped_bytes },
                      { "dropped: other address", counters_.wrong_address },
                      { "unexpected frames", counters_.unexpected_frames } });
  channel_.diagnostics(values);
}

void PelcoProtocol::onReceived(const std::uint8_t* data, std::size_t size)
{
  events_.clear();
  parser_.feed(data, size, events_);
  for (const pelco::FrameParser::Event& event : events_)
  {
    handle(event);
  }
  updateParserCounters();
}

void PelcoProtocol::updateParserCounters()
{
  const pelco::ParserCounters& parsed = parser_.counters();
  counters_.frames.set(parsed.frames + parsed.general_replies);
  counters_.bad_checksum.set(parsed.bad_checksum);
  counters_.skipped_bytes.set(parsed.skipped_bytes);
  counters_.wrong_address.set(parsed.wrong_address);
  const std::uint64_t dropped = parsed.skipped_bytes + parsed.bad_checksum;  // a bad checksum costs its 0xFF
  session_.reportDropped(dropped - dropped_reported_);
  dropped_reported_ = dropped;
}

void PelcoProtocol::handle(const pelco::FrameParser::Event& event)
{
  const std::uint8_t reply = event.frame.command2;
  const bool query_reply =
      !event.general_reply && (reply == pelco::PAN_REPLY || reply == pelco::TILT_REPLY || reply == pelco::ZOOM_REPLY);
  if (!event.general_reply && !query_reply)
  {
    ++counters_.unexpected_frames;
    return;
  }
  // The reply to the request on the wire if it is its kind of reply; otherwise the late reply of one before it (a pan
  // answer while the tilt query waits), dropped, and the request on the wire waits for its own.
  const auto can_answer = [&event, reply](const TransactionChannel::Request& on_wire) {
    if (event.general_reply)
    {
      return on_wire.tag == COMMAND;
    }
    const int expected_reply = on_wire.tag == QUERY_PAN  ? pelco::PAN_REPLY :
                               on_wire.tag == QUERY_TILT ? pelco::TILT_REPLY :
                               on_wire.tag == QUERY_ZOOM ? pelco::ZOOM_REPLY :
                                                           -1;
    return reply == expected_reply;
  };
  const std::optional<TransactionChannel::Request> answered = channel_.complete(can_answer);
  if (!answered)
  {
    return;  // late: the channel counts it
  }
  session_.ready();  // the device answers: that is all Pelco-D has to say about itself
  session_.reportAlive();
  if (event.general_reply)
  {
    return;
  }
  const std::uint16_t value = event.frame.value();
  std::size_t index = 0;
  switch (answered->tag)
  {
    case QUERY_PAN:
      polled_[PAN] = toRadians(pelco::decodePan(value));
      break;
    case QUERY_TILT:
      polled_[TILT] = toRadians(pelco::decodeTilt(value, settings_.tilt_encoding));
      index = 1;
      break;
    case QUERY_ZOOM:
      polled_[ZOOM] = settings_.positionToZoom(value);
      index = 2;
      break;
    default:
      return;
  }
  // A state only from a whole round, never with an axis left from before a lost reply (a silence).
  if (round_.answered(index))
  {
    reported_ = polled_;
    session_.reportState(polled_);
    checkSetPosition();
  }
}

void PelcoProtocol::checkSetPosition()
{
  switch (set_position_check_.update(reported_, session_.now()))
  {
    case pelco::SetPositionCheck::Step::PROBE: {
      // The target's direction on each axis it has to move (turbo never: a probe is slow).
      const std::array<int, AXIS_COUNT>& toward = set_position_check_.directions();
      queueFrame(pelco::move(settings_.address, toward[PAN] * PROBE_SPEED, toward[TILT] * PROBE_SPEED,
                             settings_.axes[ZOOM].present ? toward[ZOOM] : 0),
                 COMMAND);
      break;
    }
    case pelco::SetPositionCheck::Step::IGNORED:
      stopNow();
      setPositionIgnored();
      break;
    case pelco::SetPositionCheck::Step::STUCK:
      stopNow();  // it does not move at a speed either: the goal stalls as on any device
      break;
    default:
      break;
  }
}

void PelcoProtocol::setPositionIgnored()
{
  set_position_ignored_ = true;
  session_.setCapabilities(capabilities());
  session_.warn(IGNORES_SET_POSITION);
  session_.reportFault(IGNORES_SET_POSITION, checked_command_);
}

}  // namespace ptz_action_server
