/**
 * \file
 * \brief What the VISCA protocol reads: datagrams, packets, and which request each reply answers.
 */
#include "ptz_action_server/core/visca/visca_protocol.h"

#include <algorithm>

#include "visca_protocol_internal.h"

namespace ptz_action_server
{
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
    reply_sequence_ = message.sequence;
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

std::optional<TransactionChannel::Request>
ViscaProtocol::completeRequest(const std::function<bool(const TransactionChannel::Request&)>& answers)
{
  // Nothing on the wire since a timeout: an answer now is an overdue request's, taken late. complete() may send the
  // next request at once (its sequence number joins wire_sequences_), so the answered one's is read before.
  const bool late = wire_sequences_.empty();
  const std::deque<std::uint32_t>& awaited = late ? overdue_sequences_ : wire_sequences_;
  const std::optional<std::uint32_t> oldest =
      awaited.empty() ? std::nullopt : std::optional<std::uint32_t>(awaited.front());
  std::optional<TransactionChannel::Request> answered = channel_.complete(answers);
  if (!answered || !oldest)
  {
    return answered;
  }
  std::deque<std::uint32_t>& sequences = late ? overdue_sequences_ : wire_sequences_;
  if (!sequences.empty() && sequences.front() == *oldest)
  {
    sequences.pop_front();  // (the next request's write cleared the overdue ones)
  }
  const std::uint32_t sequence = *oldest;
  if (settings_.framing == ViscaFraming::SONY_IP && answered->tag != SEQUENCE_RESET)
  {
    // Sony's cameras answer with the sequence number of the request; some others do not (NDI PTZ1: always 1).
    replies_echo_sequence_ = replies_echo_sequence_ && reply_sequence_ == sequence;
    highest_answered_ = std::max(highest_answered_, sequence);
    timeouts_beyond_ = 0;
  }
  return answered;
}

void ViscaProtocol::handle(const visca::Packet& packet)
{
  using Kind = visca::Reply::Kind;
  const visca::Reply reply = visca::classify(packet);
  const bool broadcast = reply.kind == Kind::ADDRESS_SET || reply.kind == Kind::IF_CLEAR;
  if (!broadcast && reply.kind != Kind::OTHER && !fromCamera(reply.address))
  {
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
  const visca::PositionLayout& layout = settings_.model.layout;
  const auto can_answer = [this, &reply, &layout](const TransactionChannel::Request& on_wire) {
    std::int32_t pan = 0;
    std::int32_t tilt = 0;
    std::uint16_t zoom = 0;
    switch (reply.kind)
    {
      case Kind::ACK:
        return on_wire.tag == COMMAND || on_wire.tag == PROBE || on_wire.tag == LENS;
      case Kind::ANSWER:
        if (isLensInquiry(on_wire.tag))
        {
          return answersLensInquiry(reply, on_wire.tag);
        }
        return on_wire.tag == PAN_TILT_INQUIRY ? visca::decodePanTiltAnswer(reply, layout, pan, tilt) :
                                                 on_wire.tag == ZOOM_INQUIRY && visca::decodeZoomAnswer(reply, zoom);
      case Kind::ADDRESS_SET:
        return on_wire.tag == ADDRESS_SET;
      default:
        return on_wire.tag == IF_CLEAR;
    }
  };
  const std::optional<TransactionChannel::Request> answered = completeRequest(can_answer);
  if (!answered)
  {
    return;  // late: the channel counts it
  }
  // can_answer matched the reply's kind to the request's tag.
  switch (reply.kind)
  {
    case Kind::ACK:
      sockets_[reply.socket] = SocketUse{ answered->command, answered->bytes, answered->tag == LENS };
      session_.reportAlive();
      if (answered->tag == PROBE && feedback_ && inquiry_answers_ == 0)
      {
        probe_answered_ = true;  // it answers commands: one more inquiry tells whether it answers those
      }
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
  if (isLensInquiry(tag))
  {
    handleLensAnswer(reply, tag);
    return;
  }
  std::int32_t pan = 0;
  std::int32_t tilt = 0;
  std::uint16_t zoom = 0;
  const bool pan_tilt = tag == PAN_TILT_INQUIRY;
  ++inquiry_answers_;
  inquiry_timeouts_ = 0;
  probe_answered_ = false;
  session_.reportAlive();
  if (pan_tilt)
  {
    visca::decodePanTiltAnswer(reply, settings_.model.layout, pan, tilt);
    polled_[PAN] = settings_.model.fromSteps(PAN, pan);
    polled_[TILT] = settings_.model.fromSteps(TILT, tilt);
  }
  else
  {
    visca::decodeZoomAnswer(reply, zoom);
    polled_[ZOOM] = settings_.model.positionToZoom(zoom);
  }
  // Never a pan and tilt from before a lost answer (a silence) with a zoom from after it.
  if (!round_.answered(pan_tilt ? 0 : 1) || !set_up_ || !feedback_)
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
    if (socket->lens)
    {
      session_.lens().fault(refusal(socket->bytes, reply.error));
    }
    else
    {
      session_.reportFault(refusal(socket->bytes, reply.error), socket->command);
    }
    socket.reset();
    return;
  }
  // No socket (yet): the reply to the request on the wire.
  const std::optional<TransactionChannel::Request> answered =
      completeRequest([](const TransactionChannel::Request&) { return true; });
  if (answered && answered->tag == LENS)
  {
    session_.lens().fault(refusal(answered->bytes, reply.error));
    return;
  }
  if (answered && isLensInquiry(answered->tag))
  {
    stopLensPolling(static_cast<Tag>(answered->tag), reply.error);  // a camera without that function, or its inquiry
    return;
  }
  if (!answered || answered->tag != COMMAND)
  {
    return;
  }
  if (reply.error == visca::SYNTAX && fallBackToStandardZoom(*answered))
  {
    return;  // sent again as the standard drive: no fault of the goal
  }
  session_.reportFault(refusal(answered->bytes, reply.error), answered->command);
}

void ViscaProtocol::handleControl(const visca::Packet& payload)
{
  const std::optional<TransactionChannel::Request> answered =
      completeRequest([](const TransactionChannel::Request&) { return true; });
  if (!answered)
  {
    return;
  }
  if (payload == visca::Packet{ visca::CONTROL_RESET } && answered->tag == SEQUENCE_RESET)
  {
    reset_timeouts_ = 0;
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

}  // namespace ptz_action_server
