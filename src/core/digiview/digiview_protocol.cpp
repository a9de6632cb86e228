/**
 * \file
 * \brief What DigiView says to the digiview backend (half of DigiViewProtocol; digiview_aiming.cpp is what goals
 * send): subscriptions, the stream cut into messages, states, SYSTEM_STATUS and HALT, answers to SETs, diagnostics.
 */
#include "ptz_action_server/core/digiview/digiview_protocol.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <vector>

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
using namespace digiview;

constexpr double NARROWEST_FOV = 0.1;             ///< rad, DigiView's smallest field of view
constexpr std::uint32_t STATE_INTERVAL_MS = 100;  ///< every format takes it (1.2's minimum is 50 ms)
constexpr std::size_t MAX_PENDING_SETS = 64;
constexpr std::size_t MAX_BAD_IN_A_ROW = 3;  ///< stream: bad messages in a row that reopen the connection
constexpr double ZOOM_RATE = 2.0;            ///< X/s of velocity goals on zoom
/// Three missed states: DigiView may have restarted (over UDP nothing else tells): subscribe again.
constexpr double RESUBSCRIBE_AFTER = 3 * STATE_INTERVAL_MS / 1000.0;

bool sameCamera(const CameraId& a, const CameraId& b)
{
  return a.stream_name == b.stream_name && a.cam_id == b.cam_id;
}

/// What is subscribed: the view's state, and from 1.1 on SYSTEM_STATUS (which can say HALT).
std::vector<ParamType> subscribedParams(Format format)
{
  std::vector<ParamType> params{ ParamType::CAM_TARGETING, ParamType::CAM_OPTICS_AND_CONTROL };
  if (hasAppStatus(format))
  {
    params.push_back(ParamType::SYSTEM_STATUS);
  }
  return params;
}

}  // namespace

double DigiViewSettings::zoomMax() const
{
  return zoom_max > 0.0 ? zoom_max : fov_wide / NARROWEST_FOV;
}

std::string DigiViewSettings::angleUnitNotice(Format format, const std::string& setting)
{
  if (format != Format::V1_1)
  {
    return "";
  }
  return formatText("format \"1.1\" without %s is deprecated: 1.1 now sends angles and fov in degrees, as its own "
                    "documentation (docs.md at 305a8ab) gives them, where this package sent radians before; set %s to "
                    "\"degrees\" to keep this, or to \"radians\" for a DigiView that takes radians "
                    "(doc/backends/digiview.md)",
                    setting.c_str(), setting.c_str());
}

DigiViewProtocol::DigiViewProtocol(const DigiViewSettings& settings, DeviceSession& session)
  : settings_(settings)
  , session_(session)
  , velocity_timer_(session.context())
  , message_size_(layoutOf(settings.wire.format).size)
{
}

std::string DigiViewProtocol::deviceName() const
{
  return formatText("DigiView view '%s' camera %u", settings_.stream_name.c_str(), settings_.cam_id);
}

Capabilities DigiViewProtocol::capabilities() const
{
  // The same in every format, and nothing to learn from DigiView beyond its settings: a view goes to a commanded yaw,
  // pitch and field of view (absolute), the backend moves its target at a commanded rate (velocity), and the view's
  // CAM_TARGETING and CAM_OPTICS_AND_CONTROL reports say where it is (feedback; zoom as fov_wide / fov).
  Capabilities capabilities;
  capabilities.axes[PAN] = fullAxis({ -M_PI, M_PI }, settings_.slew_rate, settings_.acceleration);
  capabilities.axes[TILT] = fullAxis({ -M_PI / 2.0, M_PI / 2.0 }, settings_.slew_rate, settings_.acceleration);
  capabilities.axes[ZOOM] = fullAxis({ 1.0, settings_.zoomMax() }, ZOOM_RATE, 0.0);
  capabilities.relative_moves = true;  // CAM_TARGETING's euler_delta (the backend itself sends absolute targets)
  capabilities.device_presets = false;
  capabilities.device_home = false;
  return capabilities;
}

void DigiViewProtocol::onConnected()
{
  described_ = false;
  targeted_ = false;
  understood_ = false;
  halted_ = false;  // learnt again from this connection's SYSTEM_STATUS
  buffered_ = 0;
  bad_in_a_row_ = 0;
  opening_size_ = 0;
  pending_sets_.clear();
  subscribe();
}

void DigiViewProtocol::subscribe()
{
  heard_at_ = subscribed_at_ = session_.now();
  const Wire& wire = settings_.wire;
  send(packGet(wire, ParamType::VIDEO_OUTPUT, settings_.camera()));
  if (!hasAppStatus(wire.format))
  {
    send(packGet(wire, ParamType::SYSTEM_STATUS, settings_.camera()));  // once: it cannot say HALT
  }
  for (ParamType param : subscribedParams(wire.format))
  {
    if (!subscribesWithGet(wire.format))
    {
      send(packGet(wire, param, settings_.camera()));  // a 0.5 GET_INTERVAL is answered only by its reports
    }
    send(packInterval(wire, IntervalRequest{ param, settings_.camera(), STATE_INTERVAL_MS }));
  }
}

void DigiViewProtocol::poll()
{
  const TimePoint now = session_.now();
  const bool undescribed = !described_ && secondsBetween(subscribed_at_, now) > RESUBSCRIBE_AFTER;
  if (undescribed || secondsBetween(heard_at_, now) > RESUBSCRIBE_AFTER)
  {
    subscribe();
  }
}

void DigiViewProtocol::onDisconnected()
{
  velocity_timer_.cancel();
  pending_sets_.clear();
}

void DigiViewProtocol::onReceived(const std::uint8_t* data, std::size_t size)
{
  if (session_.carriesDatagrams())
  {
    handle(data, size);  // one message per datagram
    return;
  }
  // A stream: keep its first bytes (to tell a format mismatch), cut it into messages of the format's size.
  const std::size_t kept = std::min(size, opening_.size() - opening_size_);
  std::copy(data, data + kept, opening_.begin() + opening_size_);
  opening_size_ += kept;
  while (size > 0)
  {
    const std::size_t taken = std::min(size, message_size_ - buffered_);
    std::copy(data, data + taken, stream_buffer_.begin() + buffered_);
    buffered_ += taken;
    data += taken;
    size -= taken;
    if (buffered_ == message_size_)
    {
      buffered_ = 0;
      handle(stream_buffer_.data(), message_size_);
      if (!session_.connected())
      {
        return;  // out of step (or QUIT): the rest belongs to no connection
      }
    }
  }
}

void DigiViewProtocol::handle(const std::uint8_t* bytes, std::size_t size)
{
  Message message;
  bool unverified = false;
  const UnpackError error = Message::unpack(bytes, size, settings_.wire, message, &unverified);
  ++counters_.messages;
  if (error != UnpackError::NONE)
  {
    ++counters_.bad[static_cast<std::size_t>(error)];
    session_.reportDropped(size);
    // A stream of fixed-size messages has no mark to find the next one by: once bytes that were no message came (a
    // reply that never ended, noise), every later cut may be out of step. A run of bad messages reopens the
    // connection, whose first byte starts a message again.
    if (!session_.carriesDatagrams() && understood_ && ++bad_in_a_row_ >= MAX_BAD_IN_A_ROW)
    {
      session_.disconnect(formatText("DigiView stream out of step: %zu messages in a row did not unpack (last: %s)",
                                     bad_in_a_row_, toString(error)));
    }
    if (!understood_ && (error == UnpackError::BAD_SIZE || error == UnpackError::BAD_CHECKSUM))
    {
      checkOtherFormat(bytes, size);
    }
    return;
  }
  understood_ = true;
  bad_in_a_row_ = 0;
  if (unverified)
  {
    ++counters_.unverified;
  }
  switch (message.message_type)
  {
    case MessageType::CURRENT_PARAMETERS:
      handleState(message);
      return;
    case MessageType::ACKNOWLEDGEMENT:
    case MessageType::CHECKSUM_ERROR:
    case MessageType::DATA_ERROR:
    case MessageType::FORBIDDEN:
    case MessageType::UNKNOWN:
      handleAnswer(message);
      return;
    case MessageType::QUIT:
      session_.disconnect("DigiView sent QUIT");
      return;
    default:
      return;
  }
}

void DigiViewProtocol::checkOtherFormat(const std::uint8_t* bytes, std::size_t size)
{
  // A datagram is one message. On a stream, the connection's first bytes must be two messages of another size (one
  // could verify by chance). Formats of the same size (1.0, 1.1) read each other: nothing to tell.
  const bool datagrams = session_.carriesDatagrams();
  for (Format other : FORMATS)
  {
    const std::size_t other_size = layoutOf(other).size;
    const bool size_tried = std::any_of(std::begin(FORMATS), std::find(std::begin(FORMATS), std::end(FORMATS), other),
                                        [other_size](Format earlier) { return layoutOf(earlier).size == other_size; });
    if (other_size == message_size_ || size_tried)
    {
      continue;
    }
    const std::uint8_t* first = datagrams ? bytes : opening_.data();
    const std::size_t needed = datagrams ? other_size : 2 * other_size;
    if (datagrams ? size != other_size : opening_size_ < needed)
    {
      continue;
    }
    bool understood = true;
    for (std::size_t at = 0; at < needed && understood; at += other_size)
    {
      Message probe;
      understood = Message::unpack(first + at, other_size, Wire(other), probe) == UnpackError::NONE;
    }
    if (understood)
    {
      session_.failStartup(formatText("DigiView speaks format %s (%zu-byte messages), but format is set to \"%s\" "
                                      "(%zu-byte messages)",
                                      formatsOfSize(other_size).c_str(), other_size, toString(settings_.wire.format),
                                      message_size_));
      return;
    }
  }
}

void DigiViewProtocol::handleState(const Message& message)
{
  if (message.param_type == ParamType::VIDEO_OUTPUT)
  {
    VideoOutput output;
    if (unpackVideoOutput(message, output) == UnpackError::NONE && output.stream_name == settings_.stream_name)
    {
      num_user_views_ = output.num_user_views;
      described_ = settings_.cam_id < output.num_user_views;
      if (!described_)
      {
        session_.failStartup(formatText("stream '%s' has %u user view(s), so cam_id %u does not exist",
                                        settings_.stream_name.c_str(), output.num_user_views, settings_.cam_id));
      }
    }
  }
  else if (message.param_type == ParamType::SYSTEM_STATUS)
  {
    handleStatus(message);
    return;
  }
  else if (message.param_type == ParamType::CAM_TARGETING)
  {
    CamTargeting targeting;
    if (unpackTargeting(message, targeting) != UnpackError::NONE || !sameCamera(targeting.camera, settings_.camera()))
    {
      return;
    }
    reported_[PAN] = targeting.yaw;
    reported_[TILT] = targeting.pitch;
    targeted_ = true;
    heard_at_ = session_.now();
    ++counters_.states;
    session_.reportState(reported_);
  }
  else if (message.param_type == ParamType::CAM_OPTICS_AND_CONTROL)
  {
    CamOpticsAndControl optics;
    if (unpackOptics(message, optics) != UnpackError::NONE || !sameCamera(optics.camera, settings_.camera()) ||
        !(optics.fov > 0.0))
    {
      return;
    }
    reported_[ZOOM] = settings_.fov_wide / optics.fov;
    ++counters_.states;
    session_.reportState(reported_);
  }
  if (described_ && targeted_)
  {
    session_.ready();
  }
}

void DigiViewProtocol::handleStatus(const Message& message)
{
  SystemStatus status;
  if (unpackSystemStatus(message, status) != UnpackError::NONE)
  {
    return;
  }
  system_status_ = status.status;
  setHalted(hasAppStatus(settings_.wire.format) && status.status == APP_STATUS_HALT);
  if (halted_)
  {
    // A halted DigiView answers, whether or not it still reports a view that does not move: the link is there.
    session_.reportAlive();
  }
}

void DigiViewProtocol::setHalted(bool halted)
{
  if (halted == halted_)
  {
    return;
  }
  halted_ = halted;
  if (halted)
  {
    velocity_timer_.cancel();
    const std::string text = formatText("%s is halted (SYSTEM_STATUS HALT): its views do not turn until DigiView is "
                                        "set running again; goals are refused meanwhile",
                                        deviceName().c_str());
    session_.warn(text);
    session_.reportFault(text, session_.currentCommand());  // the goal in flight, if any, ends
  }
}

void DigiViewProtocol::handleAnswer(const Message& message)
{
  const auto set = std::find_if(pending_sets_.begin(), pending_sets_.end(),
                                [&message](const PendingSet& pending) { return pending.param == message.param_type; });
  const bool answers_a_set = set != pending_sets_.end();
  const std::uint64_t command = answers_a_set ? set->command : 0;
  if (answers_a_set)
  {
    pending_sets_.erase(set);
  }
  if (message.message_type == MessageType::ACKNOWLEDGEMENT)
  {
    ++counters_.acknowledged;
    return;
  }
  ++counters_.refused;
  if (answers_a_set)
  {
    session_.reportFault(formatText("DigiView refused SET %s: %s (%s)", toString(message.param_type),
                                    toString(message.message_type), describeError(message.message_type)),
                         command);
  }
}

void DigiViewProtocol::send(const Message& message)
{
  Message stamped = message;
  stamped.timestamp = static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
  if (message.message_type == MessageType::SET_PARAMETERS && session_.connected())
  {
    if (pending_sets_.size() >= MAX_PENDING_SETS)
    {
      pending_sets_.pop_front();  // never answered: forget the oldest
    }
    pending_sets_.push_back(PendingSet{ message.param_type, session_.currentCommand() });
  }
  const Bytes bytes = stamped.pack();  // the packers below made it in the configured format
  session_.write(bytes.data(), bytes.size());
}

void DigiViewProtocol::onClosing()
{
  velocity_timer_.cancel();
}

void DigiViewProtocol::shutdown()
{
  velocity_timer_.cancel();
  for (ParamType param : subscribedParams(settings_.wire.format))
  {
    send(packInterval(settings_.wire, IntervalRequest{ param, settings_.camera(), 0 }));
  }
  send(packBare(settings_.wire, MessageType::QUIT, ParamType::SYSTEM_STATUS));
}

void DigiViewProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("view", formatText("stream '%s' camera %u of %u", settings_.stream_name.c_str(), settings_.cam_id,
                                         num_user_views_.load()));
  values.emplace_back("format",
                      formatText("%s (%zu-byte messages), angles in %s, checksum %s", toString(settings_.wire.format),
                                 message_size_, toString(settings_.wire.angles), toString(settings_.wire.checksum)));
  const std::uint8_t status = system_status_;
  values.emplace_back("system status", formatText("%u (%s)%s", status, describeStatus(settings_.wire.format, status),
                                                  halted_ ? ": goals refused until it runs again" : ""));
  addCounts(values, { { "messages", counters_.messages },
                      { "states", counters_.states },
                      { "acknowledged", counters_.acknowledged },
                      { "refused", counters_.refused },
                      { "accepted with checksum 0", counters_.unverified } });
  for (std::size_t index = 1; index < counters_.bad.size(); ++index)
  {
    values.emplace_back(std::string("dropped: ") + toString(static_cast<UnpackError>(index)),
                        std::to_string(counters_.bad[index]));
  }
}

}  // namespace ptz_action_server
