#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"

#include <algorithm>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
/// A query and its reply: two frames.
constexpr std::size_t PELCO_EXCHANGE_BYTES = 2 * pelco::FRAME_SIZE;

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
{
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
  if (!capabilities.axes[ZOOM].present)
  {
    capabilities.axes[ZOOM] = absentAxis("this Pelco-D device is configured without zoom");
    capabilities.axes[ZOOM].remedy = "set serial/pelco/zoom/present if it has one";
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
  const std::uint8_t address = settings_.address;
  queueFrame(pelco::withValue(address, pelco::SET_PAN, pelco::encodePan(toDegrees(position[PAN]))), COMMAND);
  queueFrame(
      pelco::withValue(address, pelco::SET_TILT, pelco::encodeTilt(toDegrees(position[TILT]), settings_.tilt_encoding)),
      COMMAND);
  if (settings_.axes[ZOOM].present)
  {
    queueFrame(pelco::withValue(address, pelco::SET_ZOOM, settings_.zoomToPosition(position[ZOOM])), COMMAND);
  }
}

void PelcoProtocol::moveAtVelocity(const AxisValues& velocity)
{
  if (!session_.connected())
  {
    return;
  }
  channel_.clearQueue();  // what the previous command had not sent yet
  const int zoom = settings_.axes[ZOOM].present ? direction(velocity[ZOOM]) : 0;
  // Faster than the speed at 0x3F: only turbo goes faster (speedByte returns more than 0x3F, move() sends the byte).
  const bool turbo = settings_.turbo_byte != 0 && std::abs(velocity[PAN]) > settings_.axes[PAN].max_speed;
  const int pan = turbo ? (velocity[PAN] > 0.0 ? pelco::MAX_SPEED + 1 : -(pelco::MAX_SPEED + 1)) :
                          speedByte(velocity[PAN], settings_.axes[PAN].max_speed);
  queueFrame(pelco::move(settings_.address, pan, speedByte(velocity[TILT], settings_.axes[TILT].max_speed), zoom,
                         settings_.turbo_byte),
             COMMAND);
}

void PelcoProtocol::stop()
{
  if (!session_.connected())
  {
    return;
  }
  channel_.clearQueue();  // what the previous command had not sent yet
  const pelco::Bytes bytes = pelco::encode(pelco::stop(settings_.address));
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
    session_.reportState(polled_);
  }
}

}  // namespace ptz_action_server
