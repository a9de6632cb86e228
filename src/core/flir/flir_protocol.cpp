#include "ptz_action_server/core/flir/flir_protocol.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
/// Longest exchange: a command like "PP-12345 " and a verbose reply.
constexpr std::size_t EXCHANGE_BYTES = 48;
}  // namespace

FlirProtocol::FlirProtocol(const FlirSettings& settings, DeviceSession& session)
  : settings_(settings)
  , session_(session)
  , channel_(
        session.context(), session.clock(), [&session](const std::string& bytes) { session.write(bytes); },
        replyTimeout(session.linkConfig(), settings.reply_timeout, EXCHANGE_BYTES),
        [this](const TransactionChannel::Request& lost) { onTimeout(lost); })
  , banner_timer_(session.context())
{
}

Capabilities FlirProtocol::capabilities() const
{
  Capabilities capabilities;
  capabilities.axes[ZOOM].present = false;
  capabilities.axes[ZOOM].range = AxisRange{ 1.0, 1.0 };
  return capabilities;
}

Capabilities FlirProtocol::unitCapabilities() const
{
  Capabilities capabilities = this->capabilities();
  AxisCapability& pan = capabilities.axes[PAN];
  // The unit's positive pan is counter-clockwise: its minimum is the contract's maximum.
  pan.range = AxisRange{ -limits_[1] * pan_resolution_, -limits_[0] * pan_resolution_ };
  pan.max_speed = std::min(settings_.pan_speed, speed_max_[0] * pan_resolution_);
  pan.acceleration = settings_.acceleration;
  AxisCapability& tilt = capabilities.axes[TILT];
  tilt.range = AxisRange{ limits_[2] * tilt_resolution_, limits_[3] * tilt_resolution_ };
  tilt.max_speed = std::min(settings_.tilt_speed, speed_max_[1] * tilt_resolution_);
  tilt.acceleration = settings_.acceleration;
  return capabilities;
}

void FlirProtocol::onConnected()
{
  channel_.reset();
  parser_.reset();
  ready_ = false;
  awaiting_banner_ = session_.linkConfig().kind == LinkKind::TCP;
  if (!awaiting_banner_)
  {
    queueSetup();
    return;
  }
  // An E-series unit greets every TCP connection with a banner and takes commands once it ends: wait for it, but not
  // forever (other firmware may not send one).
  banner_timer_.expires_after(toDuration(settings_.banner_timeout));
  banner_timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error && awaiting_banner_)
    {
      awaiting_banner_ = false;
      queueSetup();
    }
  });
}

void FlirProtocol::onDisconnected()
{
  channel_.reset();
  banner_timer_.cancel();
  ready_ = false;
}

void FlirProtocol::queueSetup()
{
  // Terse replies, no echo, position mode; then what the unit is: resolution, limits, top speeds.
  request(flir::command("FT"), SETUP);
  request(flir::command("ED"), SETUP);
  request(flir::command("CI"), SETUP);
  request(flir::command("PR"), PAN_RESOLUTION);
  request(flir::command("TR"), TILT_RESOLUTION);
  request(flir::command("PN"), PAN_MIN);
  request(flir::command("PX"), PAN_MAX);
  request(flir::command("TN"), TILT_MIN);
  request(flir::command("TX"), TILT_MAX);
  request(flir::command("PU"), PAN_SPEED_MAX);
  request(flir::command("TU"), TILT_SPEED_MAX);
}

void FlirProtocol::poll()
{
  if (ready_ && !channel_.polling())
  {
    for (const auto& query : { std::make_pair("PP", PAN_POSITION), std::make_pair("TP", TILT_POSITION) })
    {
      channel_.queue(TransactionChannel::Request{ flir::command(query.first), query.second, true,
                                                  session_.currentCommand(), true });
    }
  }
}

void FlirProtocol::request(const std::string& text, Tag tag)
{
  channel_.queue(TransactionChannel::Request{ text, tag, true, session_.currentCommand() });
}

void FlirProtocol::goTo(const AxisValues& position)
{
  if (!ready_)
  {
    return;
  }
  channel_.clearQueue();  // what the previous command had not sent yet
  // Every goal states its mode: a mode switch queued for an earlier goal may have been dropped with the queue.
  request(flir::command("CI"), COMMAND);
  const Capabilities limits = unitCapabilities();
  request(flir::command("PS", std::lround(limits.axes[PAN].max_speed / pan_resolution_)), COMMAND);
  request(flir::command("TS", std::lround(limits.axes[TILT].max_speed / tilt_resolution_)), COMMAND);
  request(flir::command("PP", std::lround(-position[PAN] / pan_resolution_)), COMMAND);
  request(flir::command("TP", std::lround(position[TILT] / tilt_resolution_)), COMMAND);
}

void FlirProtocol::moveAtVelocity(const AxisValues& velocity)
{
  if (!ready_)
  {
    return;
  }
  channel_.clearQueue();
  request(flir::command("CV"), COMMAND);
  request(flir::command("PS", std::lround(-velocity[PAN] / pan_resolution_)), COMMAND);
  request(flir::command("TS", std::lround(velocity[TILT] / tilt_resolution_)), COMMAND);
}

void FlirProtocol::stop()
{
  if (!session_.connected())
  {
    return;
  }
  // The halt goes out at once, ahead of anything queued; the unit decelerates to rest.
  channel_.clearQueue();
  channel_.sendUrgent(TransactionChannel::Request{ flir::command("H"), COMMAND, true, session_.currentCommand() });
}

void FlirProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  addCounts(values, { { "replies", counters_.replies },
                      { "device errors", counters_.errors },
                      { "limit hits", counters_.limit_hits },
                      { "unexpected text lines", counters_.unexpected_text } });
  channel_.diagnostics(values);
}

void FlirProtocol::onReceived(const std::uint8_t* data, std::size_t size)
{
  std::vector<flir::Reply> replies;
  parser_.feed(data, size, replies);
  for (const flir::Reply& reply : replies)
  {
    handleReply(reply);
  }
}

void FlirProtocol::handleReply(const flir::Reply& reply)
{
  if (reply.endsBanner() && awaiting_banner_)
  {
    awaiting_banner_ = false;
    banner_timer_.cancel();
    queueSetup();
    return;
  }
  if (reply.kind == flir::Reply::Kind::TEXT || reply.kind == flir::Reply::Kind::LIMIT)
  {
    ++(reply.kind == flir::Reply::Kind::TEXT ? counters_.unexpected_text : counters_.limit_hits);
    return;
  }
  const std::optional<TransactionChannel::Request> answered = channel_.complete();
  if (!answered)
  {
    return;  // late: the channel counts it
  }
  ++counters_.replies;
  session_.reportAlive();
  handleAnswer(*answered, reply);
}

void FlirProtocol::handleAnswer(const TransactionChannel::Request& request, const flir::Reply& reply)
{
  const Tag tag = static_cast<Tag>(request.tag);
  if (reply.kind == flir::Reply::Kind::ERROR)
  {
    ++counters_.errors;
    if (tag == COMMAND)
    {
      std::string sent = request.bytes;
      sent.erase(sent.find_last_not_of(' ') + 1);
      session_.reportFault("the FLIR PTU refused '" + sent + "': " + reply.text, request.command);
    }
    return;
  }
  const double value = reply.value;
  switch (tag)
  {
    case PAN_RESOLUTION:
      pan_resolution_ = arcSecondsToRadians(value);
      break;
    case TILT_RESOLUTION:
      tilt_resolution_ = arcSecondsToRadians(value);
      break;
    case PAN_MIN:
    case PAN_MAX:
    case TILT_MIN:
    case TILT_MAX:
      limits_[tag - PAN_MIN] = std::lround(value);
      break;
    case PAN_SPEED_MAX:
      speed_max_[0] = std::lround(value);
      break;
    case TILT_SPEED_MAX:
      speed_max_[1] = std::lround(value);
      if (pan_resolution_ > 0.0 && tilt_resolution_ > 0.0)
      {
        ready_ = true;
        session_.setCapabilities(unitCapabilities());
        session_.ready();
      }
      break;
    case PAN_POSITION:
      polled_pan_ = -value * pan_resolution_;
      break;
    case TILT_POSITION:
      session_.reportState(AxisValues{ { polled_pan_, value * tilt_resolution_, 1.0 } });
      break;
    case SETUP:
    case COMMAND:
      break;
  }
}

void FlirProtocol::onTimeout(const TransactionChannel::Request& lost)
{
  parser_.reset();
  if (!ready_ && lost.tag != COMMAND)
  {
    // A set-up answer went missing (a slow unit, a busy machine): ask again, and go on from there.
    channel_.retry(lost);
  }
}

std::unique_ptr<DeviceBackend> makeFlirBackend(const FlirConfig& config, std::shared_ptr<const Clock> clock)
{
  return makeDeviceBackend<FlirProtocol>(config.link, config.session, config.flir, std::move(clock));
}

}  // namespace ptz_action_server
