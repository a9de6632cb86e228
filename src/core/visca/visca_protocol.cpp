#include "ptz_action_server/core/visca/visca_protocol.h"

namespace ptz_action_server
{
namespace
{
/// The longest exchange: an absolute pan-tilt command (15 bytes) and its ACK (3).
constexpr std::size_t VISCA_EXCHANGE_BYTES = 18;

std::string bytesOf(const visca::Packet& packet)
{
  return std::string(packet.begin(), packet.end());
}
visca::Packet packetOf(const std::string& bytes)
{
  return visca::Packet(bytes.begin(), bytes.end());
}
}  // namespace

bool parseViscaFraming(const std::string& text, ViscaFraming& framing)
{
  if (text == "raw" || text == "sony_ip")
  {
    framing = text == "raw" ? ViscaFraming::RAW : ViscaFraming::SONY_IP;
    return true;
  }
  return false;
}

const char* toString(ViscaFraming framing)
{
  return framing == ViscaFraming::RAW ? "raw" : "sony_ip";
}

ViscaProtocol::ViscaProtocol(const ViscaSettings& settings, DeviceSession& session)
  : settings_(settings)
  , serial_(session.linkConfig().kind == LinkKind::SERIAL)
  , session_(session)
  , channel_(
        session, [this](const std::string& bytes) { write(bytes); },
        replyTimeout(session.linkConfig(), settings.reply_timeout, VISCA_EXCHANGE_BYTES),
        [this](const TransactionChannel::Request& lost) {
          splitter_.reset();
          round_.broken();
          if (lost.tag == ADDRESS_SET || lost.tag == IF_CLEAR || lost.tag == SEQUENCE_RESET)
          {
            channel_.retry(lost);  // the set-up goes on until the camera answers
          }
        })
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
  capabilities.relative_moves = true;  // 8x 01 06 03
  capabilities.device_presets = true;  // memory set / recall (8x 01 04 3F)
  capabilities.device_home = true;     // 8x 01 06 04
  return capabilities;
}

void ViscaProtocol::onConnected()
{
  channel_.reset();
  splitter_.reset();
  sockets_.fill(std::nullopt);
  round_.broken();
  sequence_ = 0;
  queueSetup();
}

void ViscaProtocol::onDisconnected()
{
  channel_.reset();
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
    set_up_ = true;  // raw VISCA over a network: the inquiries are the handshake
  }
}

void ViscaProtocol::setUpDone()
{
  set_up_ = true;
  poll();
}

void ViscaProtocol::write(const std::string& bytes)
{
  if (settings_.framing == ViscaFraming::RAW)
  {
    session_.write(bytes);
    return;
  }
  visca::IpMessage message;
  message.payload = packetOf(bytes);
  if (!bytes.empty() && static_cast<std::uint8_t>(bytes[0]) < 0x80)
  {
    message.type = visca::IP_CONTROL;
    sequence_ = 0;  // the reset carries 0; the camera then expects 1, 2, ...
  }
  else
  {
    message.type = bytes.size() > 1 && bytes[1] == 0x09 ? visca::IP_INQUIRY : visca::IP_COMMAND;
    ++sequence_;
  }
  message.sequence = sequence_;
  session_.write(bytesOf(visca::encodeIp(message)));
}

void ViscaProtocol::poll()
{
  if (!set_up_ || channel_.polling())
  {
    return;  // goal commands first; the position when the line is free
  }
  queuePacket(visca::panTiltInquiry(settings_.address), PAN_TILT_INQUIRY, true);
  if (settings_.model.has_zoom)
  {
    queuePacket(visca::zoomInquiry(settings_.address), ZOOM_INQUIRY, true);
  }
}

void ViscaProtocol::goTo(const AxisValues& position)
{
  if (!session_.connected())
  {
    return;
  }
  channel_.clearQueue();  // what the previous command had not sent yet
  const visca::ViscaModel& model = settings_.model;
  queuePacket(visca::panTiltPosition(settings_.address, model.axes[PAN].max_speed_byte, model.axes[TILT].max_speed_byte,
                                     model.toSteps(PAN, position[PAN]), model.toSteps(TILT, position[TILT])),
              COMMAND);
  if (model.has_zoom)
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
  queuePacket(visca::panTiltDrive(settings_.address, pan_speed, tilt_speed, sign(velocity[PAN]), sign(velocity[TILT])),
              COMMAND);
  if (model.has_zoom)
  {
    queuePacket(visca::zoomDrive(settings_.address, model.zoomSpeed(velocity[ZOOM])), COMMAND);
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
  const visca::Packet halt =
      visca::panTiltDrive(settings_.address, model.axes[PAN].max_speed_byte, model.axes[TILT].max_speed_byte, 0, 0);
  channel_.sendUrgent(TransactionChannel::Request{ bytesOf(halt), COMMAND, true, session_.currentCommand() });
  if (model.has_zoom)
  {
    queuePacket(visca::zoomStop(settings_.address), COMMAND);
  }
}

void ViscaProtocol::queuePacket(const visca::Packet& packet, Tag tag, bool poll)
{
  channel_.queue(TransactionChannel::Request{ bytesOf(packet), tag, true, session_.currentCommand(), poll });
}

void ViscaProtocol::onReceived(const std::uint8_t* data, std::size_t size)
{
  if (settings_.framing == ViscaFraming::SONY_IP)
  {
    visca::IpMessage message;
    if (visca::decodeIp(data, size, message) != visca::IpError::NONE)
    {
      ++counters_.bad_datagrams;
      session_.reportDropped(size);
      return;
    }
    if (message.type == visca::IP_CONTROL_REPLY)
    {
      handleControl(message.payload);
    }
    else if (message.type == visca::IP_REPLY)
    {
      readPackets(message.payload.data(), message.payload.size());
    }
    else
    {
      ++counters_.unexpected_replies;
    }
    return;
  }
  readPackets(data, size);
}

void ViscaProtocol::readPackets(const std::uint8_t* data, std::size_t size)
{
  packets_.clear();
  splitter_.feed(data, size, packets_);
  if (session_.carriesDatagrams())
  {
    splitter_.reset();  // a datagram holds whole packets: its tail ends with it
  }
  for (const visca::Packet& packet : packets_)
  {
    handle(packet);
  }
  updateSplitterCounters();
}

void ViscaProtocol::updateSplitterCounters()
{
  const visca::SplitterCounters& split = splitter_.counters();
  counters_.packets.set(split.packets);
  counters_.skipped_bytes.set(split.skipped_bytes);
  counters_.broken_packets.set(split.broken_packets);
  const std::uint64_t dropped = split.skipped_bytes + split.broken_bytes;
  session_.reportDropped(dropped - dropped_reported_);
  dropped_reported_ = dropped;
}

void ViscaProtocol::handle(const visca::Packet& packet)
{
  using Kind = visca::Reply::Kind;
  const visca::Reply reply = visca::classify(packet);
  const bool broadcast = reply.kind == Kind::ADDRESS_SET || reply.kind == Kind::IF_CLEAR;
  if (!broadcast && reply.kind != Kind::OTHER && reply.address != settings_.address)
  {
    ++counters_.other_address;
    return;
  }
  switch (reply.kind)
  {
    case Kind::COMPLETION:
      sockets_[reply.socket].reset();
      ++counters_.completions;
      session_.reportAlive();
      return;
    case Kind::ERROR:
      handleError(reply);
      return;
    case Kind::NETWORK_CHANGE:
      ++counters_.network_changes;
      if (serial_)
      {
        queueSetup();  // the camera may have a new address: set it again
      }
      return;
    case Kind::OTHER:
      ++counters_.unexpected_replies;
      return;
    default:
      break;
  }
  // ACK, ANSWER, ADDRESS_SET, IF_CLEAR: the reply to the one request on the wire, if it can be its reply (an ACK to a
  // command, an answer of its inquiry's size); otherwise the late reply of one before it.
  const auto can_answer = [&reply](const TransactionChannel::Request& on_wire) {
    std::int16_t pan = 0;
    std::int16_t tilt = 0;
    std::uint16_t zoom = 0;
    switch (reply.kind)
    {
      case Kind::ACK:
        return on_wire.tag == COMMAND;
      case Kind::ANSWER:
        return on_wire.tag == PAN_TILT_INQUIRY ? visca::decodePanTiltAnswer(reply, pan, tilt) :
                                                 on_wire.tag == ZOOM_INQUIRY && visca::decodeZoomAnswer(reply, zoom);
      case Kind::ADDRESS_SET:
        return on_wire.tag == ADDRESS_SET;
      default:
        return on_wire.tag == IF_CLEAR;
    }
  };
  const std::optional<TransactionChannel::Request> answered = channel_.complete(can_answer);
  if (!answered)
  {
    return;  // late: the channel counts it
  }
  // can_answer matched the reply's kind to the request's tag.
  switch (reply.kind)
  {
    case Kind::ACK:
      sockets_[reply.socket] = SocketUse{ answered->command, answered->bytes };
      session_.reportAlive();
      return;
    case Kind::ANSWER:
      handleAnswer(reply, static_cast<Tag>(answered->tag));
      return;
    case Kind::ADDRESS_SET: {
      const int cameras = reply.data[0] - 1;  // w is the next free address
      if (settings_.address > cameras)
      {
        session_.failStartup("the VISCA chain has " + std::to_string(cameras) + " camera(s), none at address " +
                             std::to_string(settings_.address));
      }
      return;
    }
    default:  // IF_CLEAR
      setUpDone();
      return;
  }
}

void ViscaProtocol::handleAnswer(const visca::Reply& reply, Tag tag)
{
  // The answer of the inquiry on the wire, whose size can_answer checked.
  std::int16_t pan = 0;
  std::int16_t tilt = 0;
  std::uint16_t zoom = 0;
  const bool pan_tilt = tag == PAN_TILT_INQUIRY;
  session_.reportAlive();
  if (pan_tilt)
  {
    visca::decodePanTiltAnswer(reply, pan, tilt);
    polled_[PAN] = settings_.model.fromSteps(PAN, pan);
    polled_[TILT] = settings_.model.fromSteps(TILT, tilt);
  }
  else
  {
    visca::decodeZoomAnswer(reply, zoom);
    polled_[ZOOM] = settings_.model.positionToZoom(zoom);
  }
  // Never a pan and tilt from before a lost answer (a silence) with a zoom from after it.
  if (!round_.answered(pan_tilt ? 0 : 1) || !set_up_)
  {
    return;
  }
  session_.ready();
  session_.reportState(polled_);
}

void ViscaProtocol::handleError(const visca::Reply& reply)
{
  ++counters_.device_errors;
  session_.reportAlive();  // the camera speaks, even if it refuses
  std::optional<SocketUse>& socket = sockets_[reply.socket];
  if (reply.socket != 0 && socket)
  {
    // A command that had its socket: refused or cancelled while it ran.
    session_.reportFault(refusal(socket->bytes, reply.error), socket->command);
    socket.reset();
    return;
  }
  // No socket (yet): the reply to the request on the wire.
  const std::optional<TransactionChannel::Request> answered = channel_.complete();
  if (answered && answered->tag == COMMAND)
  {
    session_.reportFault(refusal(answered->bytes, reply.error), answered->command);
  }
}

void ViscaProtocol::handleControl(const visca::Packet& payload)
{
  const std::optional<TransactionChannel::Request> answered = channel_.complete();
  if (!answered)
  {
    return;
  }
  if (payload == visca::Packet{ visca::CONTROL_RESET } && answered->tag == SEQUENCE_RESET)
  {
    session_.reportAlive();
    setUpDone();
    return;
  }
  if (payload == visca::Packet{ visca::CONTROL_ERROR, visca::CONTROL_SEQUENCE_ERROR })
  {
    // The camera lost count (it restarted, or another controller used it): reset, then ask again.
    ++counters_.sequence_resets;
    if (!answered->poll && answered->tag != SEQUENCE_RESET)
    {
      channel_.retry(*answered);
    }
    channel_.retry(TransactionChannel::Request{ std::string(1, char(visca::CONTROL_RESET)), SEQUENCE_RESET });
    return;
  }
  ++counters_.unexpected_replies;
  if (answered->tag == COMMAND)
  {
    session_.reportFault(refusal(answered->bytes, 0) + " (VISCA over IP message error)", answered->command);
  }
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
  addCounts(values, { { "address", settings_.address },
                      { "packets", counters_.packets },
                      { "completions", counters_.completions },
                      { "error replies", counters_.device_errors },
                      { "dropped: bytes outside packets", counters_.skipped_bytes },
                      { "dropped: broken packets", counters_.broken_packets },
                      { "dropped: bad VISCA over IP datagrams", counters_.bad_datagrams },
                      { "dropped: other address", counters_.other_address },
                      { "unexpected replies", counters_.unexpected_replies },
                      { "sequence resets", counters_.sequence_resets },
                      { "network changes", counters_.network_changes } });
  channel_.diagnostics(values);
}

}  // namespace ptz_action_server
