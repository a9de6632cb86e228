#include "ptz_action_server/core/flir/flir_protocol.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
/// Longest exchange: a command like "PR " with its echo and a verbose reply ("* 185.1428 seconds arc per Pan
/// position"), or "PP-12345 " and its answer.
constexpr std::size_t FLIR_EXCHANGE_BYTES = 64;
/// Positions of a sane unit: beyond this a "limit" is a misread (a D46 has +-3090, resolutions of a few arc-seconds).
constexpr double MAX_POSITIONS = 1e8;
}  // namespace

FlirProtocol::FlirProtocol(const FlirSettings& settings, DeviceSession& session)
  : settings_(settings)
  , session_(session)
  , reply_timeout_(replyTimeout(session.linkConfig(), settings.reply_timeout, FLIR_EXCHANGE_BYTES))
  , channel_(
        session, [&session](const std::string& bytes) { session.write(bytes); }, reply_timeout_,
        [this](const TransactionChannel::Request& lost) { onTimeout(lost); })
  , wait_timer_(session.context())
{
}

Capabilities FlirProtocol::capabilities() const
{
  Capabilities capabilities;
  for (Axis axis : { PAN, TILT })
  {
    // `PP` / `TP` go to a position and report it; `CV` with signed `PS` / `TS` moves at a speed.
    AxisCapability& moved = capabilities.axes[axis];
    moved.present = true;
    moved.absolute = true;
    moved.velocity = true;
    moved.feedback = true;
    // A position goal's `PS` / `TS` (in CI mode the speed of the move): one position a second at the slowest.
    capabilities.speed.control[axis] = SpeedControl::DEVICE;
    capabilities.speed.min_speed[axis] = axis == PAN ? pan_resolution_ : tilt_resolution_;
  }
  AxisCapability& zoom = capabilities.axes[ZOOM];
  zoom.present = false;
  zoom.absolute = false;
  zoom.velocity = false;
  zoom.feedback = false;
  zoom.range = AxisRange{ 1.0, 1.0 };
  zoom.limitation = "a FLIR PTU has no zoom";
  capabilities.relative_moves = true;  // `PO` / `TO` (the node's relative goals go to positions all the same)
  capabilities.device_presets = false;
  capabilities.device_home = false;
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
  parser_.reset();
  round_.broken();
  ready_ = false;
  // An E-series unit greets every TCP connection with a banner and takes commands once it ends. On a serial line, the
  // unit may still be saying something (a banner, the answer to a request of the last connection): let it finish.
  setUpAfter(session_.linkConfig().kind == LinkKind::TCP ? Wait::BANNER_END : Wait::QUIET);
}

void FlirProtocol::onDisconnected()
{
  channel_.reset();
  wait_timer_.cancel();
  waiting_ = Wait::NOTHING;
  ready_ = false;
}

void FlirProtocol::setUpAfter(Wait wait)
{
  channel_.reset();
  waiting_ = wait;
  last_bytes_at_ = session_.now();
  wait_deadline_ = addSeconds(last_bytes_at_, settings_.banner_timeout);
  armWaitTimer();
}

void FlirProtocol::onClosing()
{
  waiting_ = Wait::NOTHING;
  wait_timer_.cancel();
  channel_.close();
}

void FlirProtocol::armWaitTimer()
{
  TimePoint due = wait_deadline_;
  if (waiting_ == Wait::QUIET)
  {
    due = std::min(due, addSeconds(last_bytes_at_, channel_.replyDeadline()));
  }
  wait_timer_.expires_after(toDuration(std::max(0.0, secondsBetween(session_.now(), due))));
  wait_timer_.async_wait([this](const boost::system::error_code& error) {
    if (error || waiting_ == Wait::NOTHING || session_.closing())
    {
      return;
    }
    const TimePoint now = session_.now();
    const bool quiet = waiting_ == Wait::QUIET && secondsBetween(last_bytes_at_, now) >= channel_.replyDeadline();
    if (quiet || now >= wait_deadline_)
    {
      // Other firmware may send no banner, or never fall quiet: the set-up goes out anyway, and retries.
      waiting_ = Wait::NOTHING;
      queueSetup();
      return;
    }
    armWaitTimer();  // the unit spoke meanwhile
  });
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
  goToAtSpeed(position, AxisValues{});
}

void FlirProtocol::goToAtSpeed(const AxisValues& position, const AxisValues& speed)
{
  if (!ready_)
  {
    return;
  }
  channel_.clearQueue();  // what the previous command had not sent yet
  // Every goal states its mode: a mode switch queued for an earlier goal may have been dropped with the queue.
  request(flir::command("CI"), COMMAND);
  const Capabilities limits = unitCapabilities();
  const auto positions_a_second = [&](Axis axis, double resolution) {
    const double top = limits.axes[axis].max_speed;
    return std::max(1L, std::lround((speed[axis] > 0.0 ? std::min(speed[axis], top) : top) / resolution));
  };
  request(flir::command("PS", positions_a_second(PAN, pan_resolution_)), COMMAND);
  request(flir::command("TS", positions_a_second(TILT, tilt_resolution_)), COMMAND);
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
                      { "banner lines", counters_.banner_lines },
                      { "restarts", counters_.restarts },
                      { "resets", counters_.resets },
                      { "unusable replies", counters_.unusable_replies },
                      { "unexpected text lines", counters_.unexpected_text } });
  channel_.diagnostics(values);
}

void FlirProtocol::onReceived(const std::uint8_t* data, std::size_t size)
{
  last_bytes_at_ = session_.now();
  std::vector<flir::Reply> replies;
  const std::uint64_t dropped_before = parser_.droppedBytes();
  parser_.feed(data, size, replies);
  session_.reportDropped(parser_.droppedBytes() - dropped_before);
  for (const flir::Reply& reply : replies)
  {
    if (!session_.connected())
    {
      return;  // a restart dropped this connection: the rest belongs to no one
    }
    handleReply(reply);
  }
}

void FlirProtocol::handleReply(const flir::Reply& reply)
{
  switch (reply.kind)
  {
    case flir::Reply::Kind::LIMIT:
      ++counters_.limit_hits;  // whenever a limit is hit: never the answer to a request
      return;
    case flir::Reply::Kind::BANNER:
      handleBanner(reply);
      return;
    case flir::Reply::Kind::RESET:
      handleReset(reply);
      return;
    case flir::Reply::Kind::TEXT:
      ++counters_.unexpected_text;
      return;
    case flir::Reply::Kind::ACK:
    case flir::Reply::Kind::VALUE:
    case flir::Reply::Kind::ERROR:
      break;
  }
  const std::optional<TransactionChannel::Request> answered = channel_.complete();
  if (!answered)
  {
    return;  // late, or nothing asked: the channel counts it
  }
  ++counters_.replies;
  session_.reportAlive();
  handleAnswer(*answered, reply);
}

void FlirProtocol::handleBanner(const flir::Reply& reply)
{
  ++counters_.banner_lines;
  if (ready_)
  {
    // A power cycle: the unit forgot the goal, terse mode, echo off and its speeds. Whatever it was asked is lost.
    ++counters_.restarts;
    session_.disconnect("the FLIR PTU restarted (it sent its start-up banner)");
    return;
  }
  // The unit (re)started during the set-up: what was on the wire is lost. Start again once it has finished talking.
  setUpAfter(reply.endsBanner() ? Wait::QUIET : Wait::BANNER_END);
}

void FlirProtocol::handleReset(const flir::Reply& reply)
{
  ++counters_.resets;
  // Someone reset the unit (a driver's `R`): it ran each axis to both its limits and home, reading nothing meanwhile.
  // Its `*` acknowledges the reset, not what this backend asked last. The goal is lost, and a unit may be back in its
  // power-up modes (echo, verbose): set it up afresh.
  if (ready_)
  {
    session_.disconnect("the FLIR PTU was reset (it answered " + reply.text + " after its calibration)");
    return;
  }
  setUpAfter(Wait::QUIET);
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
      return;
    }
  }
  if (tag == SETUP || tag == COMMAND)
  {
    return;  // acknowledged (a verbose acknowledgement may carry a number)
  }
  if (reply.kind != flir::Reply::Kind::VALUE || !std::isfinite(reply.value) || std::abs(reply.value) > MAX_POSITIONS)
  {
    unusable();
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
      if (!plausible())
      {
        unusable();
        break;
      }
      ready_ = true;
      session_.setCapabilities(unitCapabilities());
      session_.ready();
      break;
    case PAN_POSITION:
      polled_pan_ = -value * pan_resolution_;
      round_.answered(0);
      break;
    case TILT_POSITION:
      if (round_.answered(1))
      {
        session_.reportState(AxisValues{ { polled_pan_, value * tilt_resolution_, 1.0 } });
      }
      break;
    case SETUP:
    case COMMAND:
      break;
  }
}

bool FlirProtocol::plausible() const
{
  return pan_resolution_ > 0.0 && tilt_resolution_ > 0.0 && limits_[0] < limits_[1] && limits_[2] < limits_[3] &&
         speed_max_[0] > 0 && speed_max_[1] > 0;
}

void FlirProtocol::unusable()
{
  ++counters_.unusable_replies;
  round_.broken();  // a TP that follows has no pan to go with it
  if (!ready_)
  {
    // The answers are out of step with the questions (something the unit said before was taken for one): start again
    // once the line is quiet.
    setUpAfter(Wait::QUIET);
  }
}

void FlirProtocol::onTimeout(const TransactionChannel::Request& lost)
{
  const std::uint64_t dropped_before = parser_.droppedBytes();
  parser_.dropPartialReply();  // the limit reports of a calibration still under way stay
  round_.broken();
  session_.reportDropped(parser_.droppedBytes() - dropped_before);
  if (!ready_ && lost.tag != COMMAND)
  {
    // A set-up answer went missing (a slow unit, a busy machine): ask again, and go on from there.
    channel_.retry(lost);
  }
}

}  // namespace ptz_action_server
