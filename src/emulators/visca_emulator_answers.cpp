/**
 * \file
 * \brief What the VISCA emulator does with each packet: the broadcasts, the commands in their sockets, the inquiries.
 */
#include <cmath>

#include "ptz_action_server/emulators/visca_emulator.h"
#include "visca_emulator_internal.h"

namespace ptz_action_server
{
using namespace emulator_visca;

void ViscaEmulator::execute(const visca::Packet& packet, TimePoint at, std::uint32_t sequence, Replies& replies)
{
  if (executeBroadcast(packet, replies) || (packet[0] & 0x0F) != config_.address)
  {
    return;  // a broadcast, or a packet for another camera of the chain
  }
  const std::uint8_t kind = packet[1];
  if ((kind & 0xF0) == 0x20 && packet.size() == 3)
  {
    const std::uint8_t socket = kind & 0x0F;
    if (socket == 0 || socket >= sockets_.size() || !sockets_[socket].busy)
    {
      replies.push_back(reply(ERROR | socket, { visca::NO_SOCKET }));
      return;
    }
    model_.stop(at);  // the command in the socket ends where the axes come to rest
    sockets_[socket] = Socket{};
    replies.push_back(reply(ERROR | socket, { visca::CANCELLED }));
    return;
  }
  if (kind == 0x09)
  {
    answerInquiry(packet, at, replies);
    return;
  }
  if (packet == visca::ifClearAddressed(config_.address))
  {
    sockets_.fill(Socket{});  // the command buffers cleared: no completion will come
    replies.push_back(reply(COMPLETION));
    return;
  }
  if (kind == 0x01)
  {
    executeCommand(packet, at, sequence, replies);
    return;
  }
  ++counters_.syntax_errors;
  replies.push_back(reply(ERROR, { visca::SYNTAX }));
}

bool ViscaEmulator::executeBroadcast(const visca::Packet& packet, Replies& replies)
{
  if (packet[0] != visca::BROADCAST)
  {
    return false;
  }
  if (packet == visca::addressSet())
  {
    replies.push_back({ visca::BROADCAST, 0x30, static_cast<std::uint8_t>(config_.address + 1), visca::TERMINATOR });
  }
  else if (packet == visca::ifClear())
  {
    sockets_.fill(Socket{});
    replies.push_back(packet);
  }
  return true;
}

void ViscaEmulator::answerInquiry(const visca::Packet& packet, TimePoint at, Replies& replies)
{
  if (config_.modes.no_inquiries)
  {
    ++counters_.inquiries_ignored;
    return;
  }
  const PtzSample now = model_.sample(at);
  const visca::ViscaModel& model = config_.model;
  visca::Packet answer = reply(COMPLETION);
  answer.pop_back();
  if (packet == visca::panTiltInquiry(config_.address))
  {
    visca::putNibbles(answer, static_cast<std::uint32_t>(model.toSteps(PAN, now.position[PAN])),
                      model.layout.pan_nibbles);
    visca::putNibbles(answer, static_cast<std::uint32_t>(model.toSteps(TILT, now.position[TILT])),
                      model.layout.tilt_nibbles);
  }
  else if (packet == visca::zoomInquiry(config_.address) && model.has_zoom)
  {
    visca::putNibbles(answer, model.zoomToPosition(now.position[ZOOM]), 4);
  }
  else if (packet == visca::versionInquiry(config_.address))
  {
    // Vendor, model, ROM revision (1.00), the highest socket (2).
    for (std::uint16_t word : { model.vendor_id, model.model_id, std::uint16_t(0x0100) })
    {
      answer.push_back(static_cast<std::uint8_t>((word >> 8) & 0x7F));
      answer.push_back(static_cast<std::uint8_t>(word & 0x7F));
    }
    answer.push_back(0x02);
  }
  else if (packet == visca::powerInquiry(config_.address))
  {
    answer.push_back(0x02);  // on
  }
  else if (!answerLensInquiry(packet, at, answer))
  {
    ++counters_.syntax_errors;
    replies.push_back(reply(ERROR, { visca::SYNTAX }));
    return;
  }
  answer.push_back(visca::TERMINATOR);
  replies.push_back(answer);
}

void ViscaEmulator::executeCommand(const visca::Packet& packet, TimePoint at, std::uint32_t sequence, Replies& replies)
{
  // A command of the same group replaces the one still running; any other busy socket stays taken.
  const bool lens = isLensPacket(packet);
  const Group group = lens ? Group::LENS : (packet[2] == 0x04 ? Group::ZOOM : Group::PAN_TILT);
  std::size_t free_socket = 0;
  for (std::size_t socket = 1; socket < sockets_.size() && free_socket == 0; ++socket)
  {
    free_socket = sockets_[socket].busy && sockets_[socket].group != group ? 0 : socket;
  }
  if (free_socket == 0)
  {
    ++counters_.buffer_full;
    replies.push_back(reply(ERROR, { visca::BUFFER_FULL }));
    return;
  }
  bool until_rest = false;
  const std::uint8_t lens_error = lens ? runLens(packet, at) : 0;
  if (lens_error == visca::NOT_EXECUTABLE)
  {
    replies.push_back(reply(ERROR, { visca::NOT_EXECUTABLE }));
    return;
  }
  if (lens_error != 0 || (!lens && !run(packet, at, until_rest)))
  {
    ++counters_.syntax_errors;  // illegal parameters: nothing moved, no socket taken
    replies.push_back(reply(ERROR, { visca::SYNTAX }));
    return;
  }
  for (std::size_t socket = 1; socket < sockets_.size(); ++socket)
  {
    if (sockets_[socket].busy && sockets_[socket].group == group)
    {
      sockets_[socket] = Socket{};
      replies.push_back(reply(static_cast<std::uint8_t>(COMPLETION | socket)));
    }
  }
  const auto socket_byte = static_cast<std::uint8_t>(free_socket);
  replies.push_back(reply(ACK | socket_byte));
  if (until_rest)
  {
    sockets_[free_socket] = Socket{ true, group, true, sequence };
  }
  else
  {
    replies.push_back(reply(COMPLETION | socket_byte));
  }
}

bool ViscaEmulator::run(const visca::Packet& packet, TimePoint at, bool& until_rest)
{
  const visca::ViscaModel& model = config_.model;
  const std::size_t size = packet.size();
  const std::uint8_t category = packet[2];
  const std::uint8_t command = size > 3 ? packet[3] : 0;
  if (category == 0x06 && command == 0x01 && size == 9)  // pan-tilt drive
  {
    const std::uint8_t pan = packet[6];
    const std::uint8_t tilt = packet[7];
    const auto speed_ok = [&](Axis axis, std::uint8_t byte) {
      return byte >= 1 && byte <= model.axes[axis].max_speed_byte;
    };
    if (!speed_ok(PAN, packet[4]) || !speed_ok(TILT, packet[5]) || pan < 1 || pan > 3 || tilt < 1 || tilt > 3)
    {
      return false;
    }
    const double pan_speed = model.speedOfByte(PAN, packet[4]);
    const double tilt_speed = model.speedOfByte(TILT, packet[5]);
    model_.moveAxisAtVelocity(PAN, pan == 2 ? pan_speed : (pan == 1 ? -pan_speed : 0.0), at);
    model_.moveAxisAtVelocity(TILT, tilt == 1 ? tilt_speed : (tilt == 2 ? -tilt_speed : 0.0), at);
    return true;
  }
  if (category == 0x06 && (command == 0x02 || command == 0x03))  // absolute, relative
  {
    until_rest = true;
    return runPosition(packet, at);
  }
  if (category == 0x06 && command == 0x04 && size == 5)  // home
  {
    model_.goToAxis(PAN, 0.0, at);
    model_.goToAxis(TILT, 0.0, at);
    until_rest = true;
    return true;
  }
  if (category == 0x04 && command == 0x07 && size == 6 && model.has_zoom)  // zoom stop, tele, wide
  {
    return runZoomDrive(packet[4], at);
  }
  if (category == 0x04 && command == 0x47 && size == 9 && model.has_zoom)  // zoom direct
  {
    const auto position = static_cast<std::uint16_t>(visca::getNibbles(packet.data() + 4, 4));
    if (position > model.zoom_table.back().position)
    {
      return false;
    }
    model_.goToAxis(ZOOM, model.positionToZoom(position), at);
    until_rest = true;
    return true;
  }
  return false;
}

bool ViscaEmulator::runPosition(const visca::Packet& packet, TimePoint at)
{
  // `8x 01 06 02 VV WW <pan nibbles> <tilt nibbles> FF`, as the model writes them.
  const visca::ViscaModel& model = config_.model;
  const visca::PositionLayout& layout = model.layout;
  if (packet.size() != 7 + layout.answerSize())
  {
    return false;
  }
  const std::uint8_t pan_byte = packet[4];
  const std::uint8_t tilt_byte = packet[5];
  // One speed (`VV 00`), or two, where the 5-nibble models take a tilt speed of 00 for "in step with the pan".
  const bool tilt_synced = tilt_byte == 0 && (layout.shared_speed || layout.pan_nibbles == 5);
  if (pan_byte < 1 || pan_byte > model.axes[PAN].max_speed_byte || (layout.shared_speed && tilt_byte != 0) ||
      (!tilt_synced && (tilt_byte < 1 || tilt_byte > model.axes[TILT].max_speed_byte)))
  {
    return false;
  }
  const bool relative = packet[3] == 0x03;
  AxisValues target = model_.sample(at).position;
  const std::int32_t steps[2] = { visca::getSignedNibbles(packet.data() + 6, layout.pan_nibbles),
                                  visca::getSignedNibbles(packet.data() + 6 + layout.pan_nibbles,
                                                          layout.tilt_nibbles) };
  for (Axis axis : { PAN, TILT })
  {
    const double value = model.fromSteps(axis, steps[axis]);
    target[axis] = relative ? target[axis] + value : value;
    if (!model_.config().axes[axis].range.contains(target[axis]))
    {
      return false;
    }
  }
  const std::uint8_t speed_bytes[2] = {
    pan_byte, tilt_synced ? std::min<std::uint8_t>(pan_byte, model.axes[TILT].max_speed_byte) : tilt_byte
  };
  for (Axis axis : { PAN, TILT })
  {
    model_.setCruiseSpeed(axis, model.speedOfByte(axis, speed_bytes[axis]), at);
    model_.goToAxis(axis, target[axis], at);
  }
  return true;
}

bool ViscaEmulator::runZoomDrive(std::uint8_t drive, TimePoint at)
{
  const visca::ViscaModel& model = config_.model;
  const int step = (drive & 0x0F) + 1;
  const bool variable = (drive & 0xF0) == 0x20 || (drive & 0xF0) == 0x30;
  if (variable && config_.modes.standard_zoom_only)
  {
    return false;  // a camera that takes the standard zoom drive only
  }
  const double rate = drive == 0x00                       ? 0.0 :
                      drive == 0x02                       ? model.zoom_rate :
                      drive == 0x03                       ? -model.zoom_rate :
                      (drive & 0xF0) == 0x20 && step <= 8 ? model.rateOfZoomSpeed(step) :
                      (drive & 0xF0) == 0x30 && step <= 8 ? -model.rateOfZoomSpeed(step) :
                                                            NAN;
  if (std::isnan(rate))
  {
    return false;
  }
  model_.moveAxisAtVelocity(ZOOM, rate, at);
  return true;
}

}  // namespace ptz_action_server
