#include "ptz_action_server/core/visca/visca_protocol.h"

#include <algorithm>
#include <cmath>

#include "visca_protocol_internal.h"

namespace ptz_action_server
{
namespace
{
/// The longest exchange: an absolute pan-tilt command in 5 + 5 nibbles (17 bytes) and its ACK (3).
constexpr std::size_t VISCA_EXCHANGE_BYTES = 20;
/// Inquiries without any answer, after which a command tells whether the camera answers at all.
constexpr std::uint32_t INQUIRIES_BEFORE_PROBE = 3;
/// Sequence resets without answer after which the set-up goes on without one.
constexpr std::uint32_t RESETS_BEFORE_GOING_ON = 2;
/// Requests numbered above the highest answered, unanswered in a row, after which the numbers are cut. One: only a
/// camera that does not echo the numbers is cut, and such a camera does not check them (cutting them costs nothing).
constexpr std::uint32_t TIMEOUTS_BEFORE_CYCLE = 1;
}  // namespace

ViscaProtocol::ViscaProtocol(const ViscaSettings& settings, DeviceSession& session)
  : settings_(settings)
  , serial_(session.linkConfig().kind == LinkKind::SERIAL)
  , any_reply_address_(settings.any_reply_address.value_or(!serial_))
  , session_(session)
  , channel_(
        session, [this](const std::string& bytes) { write(bytes); },
        replyTimeout(session.linkConfig(), settings.reply_timeout, VISCA_EXCHANGE_BYTES),
        [this](const TransactionChannel::Request& lost) { onReplyTimeout(lost); })
  , feedback_(settings.inquiries)
  , variable_zoom_(settings.zoom_drive != ViscaZoomDrive::STANDARD)
  , sequence_cycle_(settings.sequence_cycle)
  , focus_polled_(settings.inquiries && settings.lens.focus && settings.lens.poll_period > 0.0)
  , iris_polled_(settings.inquiries && settings.lens.iris && settings.lens.poll_period > 0.0)
  , round_(settings.model.has_zoom ? 2 : 1)
{
}

std::string ViscaProtocol::deviceName() const
{
  return "a VISCA camera (address " + std::to_string(settings_.address) + ", " + settings_.model.name + ")";
}

Capabilities ViscaProtocol::capabilities() const
{
  Capabilities capabilities;
  capabilities.axes = settings_.model.capabilities();
  if (!feedback_)
  {
    for (AxisCapability& axis : capabilities.axes)
    {
      if (axis.present)
      {
        axis.absolute = false;
        axis.feedback = false;
        axis.limitation = "this VISCA camera answers no inquiries: it reports no position";
        axis.remedy.clear();
      }
    }
    capabilities.axes[ZOOM].widest_view = capabilities.axes[ZOOM].present;  // zoom direct 0000 is the wide end
  }
  capabilities.relative_moves = true;  // 8x 01 06 03
  for (Axis axis : { PAN, TILT })  // the absolute move's speed bytes VV, WW, 1 the slowest; the zoom direct has none
  {
    capabilities.speed.control[axis] = SpeedControl::DEVICE;
    capabilities.speed.min_speed[axis] = settings_.model.speedOfByte(axis, 1);
  }
  capabilities.device_presets = true;  // memory set / recall (8x 01 04 3F)
  capabilities.device_home = true;     // 8x 01 06 04
  capabilities.lens = settings_.lens.capabilities(feedback_ && focus_polled_, feedback_ && iris_polled_);
  return capabilities;
}

void ViscaProtocol::onConnected()
{
  // A camera that was away may have restarted in its own modes: the next manual lens command sets manual again.
  for (LensFunction function : ALL_LENS_FUNCTIONS)
  {
    session_.lens().setMode(function, LensMode::UNKNOWN);
  }
  channel_.reset();
  splitter_.reset();
  sockets_.fill(std::nullopt);
  round_.broken();
  sequence_ = 0;
  wire_sequences_.clear();
  overdue_sequences_.clear();
  inquiry_timeouts_ = 0;  // inquiry_answers_ stays: a camera that once answered an inquiry answers them
  probe_answered_ = false;
  reset_timeouts_ = 0;
  highest_answered_ = 0;
  timeouts_beyond_ = 0;
  replies_echo_sequence_ = true;
  const visca::ViscaModel& model = settings_.model;
  keep_alive_ =
      visca::panTiltDrive(settings_.address, model.axes[PAN].max_speed_byte, model.axes[TILT].max_speed_byte, 0, 0);
  kept_alive_at_ = TimePoint{};
  queueSetup();
}

void ViscaProtocol::onDisconnected()
{
  channel_.reset();
  wire_sequences_.clear();
  round_.broken();
  set_up_ = false;
}

void ViscaProtocol::queueSetup()
{
  set_up_ = false;
  if (serial_)
  {
    queuePacket(visca::addressSet(), ADDRESS_SET);
    queuePacket(visca::ifClear(), IF_CLEAR);
  }
  else if (settings_.framing == ViscaFraming::SONY_IP)
  {
    // A control payload (its first byte below 0x80), which write() sends as a control message.
    channel_.queue(TransactionChannel::Request{ std::string(1, char(visca::CONTROL_RESET)), SEQUENCE_RESET });
  }
  else
  {
    setUpDone();  // raw VISCA over a network: the inquiries are the handshake
  }
}

void ViscaProtocol::setUpDone()
{
  set_up_ = true;
  if (!feedback_)
  {
    session_.ready();  // a camera without inquiries: its answers to the keep-alive bring the link up
  }
  poll();
}

void ViscaProtocol::write(const std::string& bytes)
{
  visca::IpMessage message;
  if (settings_.framing == ViscaFraming::SONY_IP && !bytes.empty() && static_cast<std::uint8_t>(bytes[0]) < 0x80)
  {
    message.type = visca::IP_CONTROL;
    sequence_ = 0;  // the reset carries 0; the camera then expects 1, 2, ...
  }
  else if (settings_.framing == ViscaFraming::SONY_IP)
  {
    message.type = bytes.size() > 1 && bytes[1] == 0x09 ? visca::IP_INQUIRY : visca::IP_COMMAND;
    const std::uint32_t cycle = sequence_cycle_;
    sequence_ = cycle > 0 && sequence_ >= cycle ? 1 : sequence_ + 1;
  }
  wire_sequences_.push_back(sequence_);  // every request of this protocol expects a reply
  overdue_sequences_.clear();            // the channel awaits the overdue ones no more
  if (settings_.framing == ViscaFraming::RAW)
  {
    session_.write(bytes);
    return;
  }
  message.payload = packetOf(bytes);
  message.sequence = sequence_;
  session_.write(bytesOf(visca::encodeIp(message)));
}

void ViscaProtocol::poll()
{
  if (!set_up_ || channel_.polling())
  {
    return;  // goal commands first; the position when the line is free
  }
  if (!feedback_)
  {
    keepAlive();
    return;
  }
  queuePacket(visca::panTiltInquiry(settings_.address), PAN_TILT_INQUIRY, true);
  if (settings_.model.has_zoom)
  {
    queuePacket(visca::zoomInquiry(settings_.address), ZOOM_INQUIRY, true);
  }
  pollLens();
}

void ViscaProtocol::keepAlive()
{
  // Often enough that an answer comes well within the state timeout, seldom enough to leave the line to the goals.
  const DeviceSessionConfig& config = session_.config();
  const double period = std::max(config.poll_period, config.state_timeout / 4.0);
  const TimePoint now = session_.now();
  if (kept_alive_at_ != TimePoint{} && secondsBetween(kept_alive_at_, now) < period)
  {
    return;
  }
  kept_alive_at_ = now;
  // Not tagged with the current command: a refusal of a repeated drive is no fault of the goal that sent it.
  channel_.queue(TransactionChannel::Request{ bytesOf(keep_alive_), PROBE, true, 0, true });
}

void ViscaProtocol::goToAtSpeed(const AxisValues& position, const AxisValues& speed)
{
  if (!session_.connected())
  {
    return;
  }
  channel_.clearQueue();  // what the previous command had not sent yet
  const visca::ViscaModel& model = settings_.model;
  const auto speed_byte = [&](Axis axis) {
    const std::uint8_t top = model.axes[axis].max_speed_byte;
    return speed[axis] > 0.0 ? std::clamp<std::uint8_t>(model.speedByte(axis, speed[axis]), 1, top) : top;
  };
  if (!std::isnan(position[PAN]) && !std::isnan(position[TILT]))
  {
    queuePacket(visca::panTiltPosition(settings_.address, speed_byte(PAN), speed_byte(TILT),
                                       model.toSteps(PAN, position[PAN]), model.toSteps(TILT, position[TILT]),
                                       model.layout),
                COMMAND);
  }
  if (model.has_zoom && !std::isnan(position[ZOOM]))
  {
    queuePacket(visca::zoomDirect(settings_.address, model.zoomToPosition(position[ZOOM])), COMMAND);
  }
}

void ViscaProtocol::moveAtVelocity(const AxisValues& velocity)
{
  if (!session_.connected())
  {
    return;
  }
  channel_.clearQueue();
  const visca::ViscaModel& model = settings_.model;
  // A stopped axis still needs a valid speed byte: 1.
  const std::uint8_t pan_speed = std::max<std::uint8_t>(1, model.speedByte(PAN, velocity[PAN]));
  const std::uint8_t tilt_speed = std::max<std::uint8_t>(1, model.speedByte(TILT, velocity[TILT]));
  const auto sign = [](double value) { return value > 0.0 ? 1 : (value < 0.0 ? -1 : 0); };
  keep_alive_ =
      visca::panTiltDrive(settings_.address, pan_speed, tilt_speed, sign(velocity[PAN]), sign(velocity[TILT]));
  queuePacket(keep_alive_, COMMAND);
  if (model.has_zoom)
  {
    queuePacket(zoomDrivePacket(model.zoomSpeed(velocity[ZOOM])), COMMAND);
  }
}

void ViscaProtocol::stop()
{
  if (!session_.connected())
  {
    return;
  }
  channel_.clearQueue();
  const visca::ViscaModel& model = settings_.model;
  keep_alive_ =
      visca::panTiltDrive(settings_.address, model.axes[PAN].max_speed_byte, model.axes[TILT].max_speed_byte, 0, 0);
  channel_.sendUrgent(TransactionChannel::Request{ bytesOf(keep_alive_), COMMAND, true, session_.currentCommand() });
  if (model.has_zoom)
  {
    queuePacket(visca::zoomStop(settings_.address), COMMAND);
  }
}

visca::Packet ViscaProtocol::zoomDrivePacket(int speed) const
{
  return variable_zoom_ ? visca::zoomDrive(settings_.address, speed) :
                          visca::zoomDriveStandard(settings_.address, speed);
}

void ViscaProtocol::queuePacket(const visca::Packet& packet, Tag tag, bool poll)
{
  channel_.queue(TransactionChannel::Request{ bytesOf(packet), tag, true, session_.currentCommand(), poll });
}

void ViscaProtocol::onReplyTimeout(const TransactionChannel::Request& lost)
{
  // The channel dropped every request on the wire; the oldest is the one that was not answered.
  const std::uint32_t lost_sequence = wire_sequences_.empty() ? 0 : wire_sequences_.front();
  overdue_sequences_ = std::move(wire_sequences_);
  wire_sequences_.clear();
  splitter_.reset();
  round_.broken();
  switch (lost.tag)
  {
    case ADDRESS_SET:
    case IF_CLEAR:
      channel_.retry(lost);  // the set-up goes on until the camera answers
      return;
    case SEQUENCE_RESET:
      if (++reset_timeouts_ < RESETS_BEFORE_GOING_ON)
      {
        channel_.retry(lost);
        return;
      }
      // NewTek's NDI PTZ1 reads only sequence numbers 1..3: it never answers the reset (sequence 0).
      session_.warn(deviceName() + " does not answer the VISCA over IP sequence reset: going on without it");
      setUpDone();
      return;
    case PAN_TILT_INQUIRY:
    case ZOOM_INQUIRY:
      if (feedback_ && settings_.inquiries && inquiry_answers_ == 0)
      {
        if (probe_answered_)
        {
          runWithoutFeedback();  // it answered a command, and still no inquiry after it
          return;
        }
        if (++inquiry_timeouts_ % INQUIRIES_BEFORE_PROBE == 0)
        {
          // Does it answer at all? A halt is what the node would send a camera it just found anyway.
          channel_.retry(TransactionChannel::Request{ bytesOf(keep_alive_), PROBE, true, 0 });
        }
      }
      break;
    case FOCUS_MODE_INQUIRY:
    case FOCUS_INQUIRY:
    case IRIS_INQUIRY:
      if (++lens_timeouts_ >= INQUIRIES_BEFORE_PROBE)
      {
        stopLensPolling(static_cast<Tag>(lost.tag), 0);  // a camera that answers the pose but not these
      }
      break;
    default:
      break;
  }
  if (settings_.framing == ViscaFraming::SONY_IP && settings_.sequence_cycle == 0 && sequence_cycle_ == 0 &&
      !replies_echo_sequence_ && highest_answered_ > 0 && lost_sequence > highest_answered_ &&
      ++timeouts_beyond_ >= TIMEOUTS_BEFORE_CYCLE)
  {
    // A camera that answers every request numbered up to N, none above, and does not echo the numbers it reads:
    // NewTek's NDI PTZ1 (1..3, always answering 1). Count 1..N from now on.
    sequence_cycle_ = highest_answered_;
    sequence_ = 0;
    session_.warn(deviceName() + " answers VISCA over IP sequence numbers 1.." + std::to_string(highest_answered_) +
                  " only: counting 1.." + std::to_string(highest_answered_) +
                  " from now on (set visca/sequence_cycle to skip the request lost to learn it)");
  }
}

void ViscaProtocol::runWithoutFeedback()
{
  feedback_ = false;
  round_.broken();
  session_.warn(deviceName() + " answers commands but no inquiry: it runs without position feedback (position goals "
                               "are refused, "
                               "velocity goals run until stopped); set visca/inquiries: false to skip the inquiries at "
                               "start");
  session_.setCapabilities(capabilities());
  if (set_up_)
  {
    session_.ready();
  }
  session_.reportAlive();
}

bool ViscaProtocol::fallBackToStandardZoom(const TransactionChannel::Request& refused)
{
  const visca::Packet packet = packetOf(refused.bytes);
  if (settings_.zoom_drive != ViscaZoomDrive::AUTO || !visca::isVariableZoomDrive(packet))
  {
    return false;
  }
  variable_zoom_ = false;
  session_.warn(deviceName() + " refuses the variable zoom drive ('" + visca::toHex(packet) +
                "': syntax error): zoom velocity goals use the standard drive, at one speed, from now on (set "
                "visca/zoom/drive: standard to say so)");
  TransactionChannel::Request standard = refused;
  standard.bytes = bytesOf(visca::zoomDriveStandard(settings_.address, (packet[4] & 0xF0) == 0x20 ? 1 : -1));
  channel_.retry(standard);
  return true;
}

bool ViscaProtocol::fromCamera(std::uint8_t address)
{
  if (address == settings_.address)
  {
    return true;
  }
  if (!any_reply_address_)
  {
    ++counters_.other_address;
    return false;
  }
  ++counters_.foreign_address;
  if (reply_address_.exchange(address) != address)
  {
    session_.warn(deviceName() + " answers from address " + std::to_string(address) + " (" +
                  visca::toHex({ static_cast<std::uint8_t>((address + 8) << 4) }) +
                  "), not its own: taken for its replies (a network link reaches one camera)");
  }
  return true;
}

std::string ViscaProtocol::refusal(const std::string& bytes, std::uint8_t error) const
{
  const std::string sent = visca::toHex(packetOf(bytes));
  return error == 0 ? "the VISCA camera refused '" + sent + "'" :
                      "the VISCA camera refused '" + sent + "': " + visca::errorName(error);
}

void ViscaProtocol::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.push_back(DiagnosticValue{ "model", settings_.model.name });
  values.push_back(DiagnosticValue{ "framing", toString(settings_.framing) });
  values.push_back(DiagnosticValue{ "position feedback", feedback_ ? "inquiries" : "none (no inquiry answered)" });
  values.push_back(DiagnosticValue{ "zoom drive", variable_zoom_ ? "variable" : "standard" });
  const bool focus_polled = feedback_ && focus_polled_;
  const bool iris_polled = feedback_ && iris_polled_;
  values.push_back(DiagnosticValue{ "lens inquiries", focus_polled && iris_polled ? "focus mode, focus, iris" :
                                                      focus_polled                ? "focus mode, focus" :
                                                      iris_polled                 ? "iris" :
                                                                                    "none" });
  const int reply_address = reply_address_;
  values.push_back(
      DiagnosticValue{ "replies from address", std::to_string(reply_address < 0 ? settings_.address : reply_address) });
  if (settings_.framing == ViscaFraming::SONY_IP)
  {
    const std::uint32_t cycle = sequence_cycle_;
    values.push_back(DiagnosticValue{ "sequence numbers", cycle == 0 ? "counting" : "1.." + std::to_string(cycle) });
  }
  addCounts(values, { { "address", settings_.address },
                      { "packets", counters_.packets },
                      { "completions", counters_.completions },
                      { "error replies", counters_.device_errors },
                      { "dropped: bytes outside packets", counters_.skipped_bytes },
                      { "dropped: broken packets", counters_.broken_packets },
                      { "dropped: bad VISCA over IP datagrams", counters_.bad_datagrams },
                      { "dropped: other address", counters_.other_address },
                      { "replies from another address taken", counters_.foreign_address },
                      { "unexpected replies", counters_.unexpected_replies },
                      { "sequence resets", counters_.sequence_resets },
                      { "network changes", counters_.network_changes } });
  channel_.diagnostics(values);
}

}  // namespace ptz_action_server
