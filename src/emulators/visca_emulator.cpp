#include "ptz_action_server/emulators/visca_emulator.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
constexpr std::uint8_t ACK = 0x40;
constexpr std::uint8_t COMPLETION = 0x50;
constexpr std::uint8_t ERROR = 0x60;

/// The motion model of a camera with \p model's ranges, speeds and steps.
SimDeviceConfig modelConfig(const visca::ViscaModel& model)
{
  SimDeviceConfig device = SimDeviceConfig::defaults();
  const std::array<AxisCapability, AXIS_COUNT> axes = model.capabilities();
  for (Axis axis : ALL_AXES)
  {
    SimAxisConfig& sim = device.axes[axis];
    sim.present = axes[axis].present;
    sim.range = axes[axis].range;
    sim.motion.max_speed = axes[axis].max_speed;
    sim.initial_position = axis == ZOOM ? axes[axis].range.min : 0.0;
    if (axis != ZOOM)
    {
      sim.motion.acceleration = model.acceleration;
      sim.resolution = toRadians(1.0 / model.axes[axis].steps_per_degree);
    }
  }
  return device;
}

bool rests(const PtzSample& sample, Axis axis)
{
  return std::abs(sample.velocity[axis]) < 1e-9;
}
}  // namespace

ViscaEmulator::ViscaEmulator(const ViscaEmulatorConfig& config)
  : LineEmulator(modelConfig(config.model)), config_(config)
{
  openPort(config.port, DevicePort::Handlers{ [this](const std::uint8_t* data, std::size_t size, TimePoint at) {
                                               onBytes(data, size, at);
                                             },
                                              [this] { onTick(); },
                                              {},
                                              {} });
}

ViscaEmulator::~ViscaEmulator()
{
  closePort();
}

void ViscaEmulator::powerUp()
{
  splitter_.reset();
  sockets_.fill(Socket{});
  last_sequence_ = 0;
}

ViscaEmulatorCounters ViscaEmulator::counters() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

visca::SplitterCounters ViscaEmulator::splitterCounters() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return splitter_.counters();
}

void ViscaEmulator::skipSequence(std::uint32_t sequence)
{
  std::lock_guard<std::mutex> lock(mutex_);
  last_sequence_ = sequence;
}

void ViscaEmulator::onBytes(const std::uint8_t* data, std::size_t size, TimePoint arrived_at)
{
  Replies replies;
  if (config_.framing == ViscaFraming::SONY_IP)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    onDatagram(data, size, arrived_at, replies);
    return;  // onDatagram sent its own replies, with their sequence numbers
  }
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<visca::Packet> packets;
    const double byte_time = port_->byteTime();
    // Byte by byte, so each packet is stamped with the moment its own last byte crossed the line.
    for (std::size_t index = 0; index < size; ++index)
    {
      packets.clear();
      splitter_.feed(data + index, 1, packets);
      const TimePoint at = addSeconds(arrived_at, -(static_cast<double>(size - 1 - index) * byte_time));
      for (const visca::Packet& packet : packets)
      {
        received_.add(ReceivedPacket{ at, packet, false, 0 });
        execute(packet, at, 0, replies);
      }
    }
    if (config_.port.kind == DevicePortConfig::Kind::UDP)
    {
      splitter_.reset();  // a datagram holds whole packets
    }
  }
  sendAll(replies, 0);
}

void ViscaEmulator::onDatagram(const std::uint8_t* data, std::size_t size, TimePoint at, Replies& replies)
{
  visca::IpMessage message;
  if (visca::decodeIp(data, size, message) != visca::IpError::NONE)
  {
    ++counters_.bad_datagrams;
    sendAll({ { visca::CONTROL_ERROR, visca::CONTROL_MESSAGE_ERROR } }, message.sequence, visca::IP_CONTROL_REPLY);
    return;
  }
  const bool control = message.type == visca::IP_CONTROL;
  received_.add(ReceivedPacket{ at, message.payload, control, message.sequence });
  if (control)
  {
    if (message.payload == visca::Packet{ visca::CONTROL_RESET })
    {
      last_sequence_ = message.sequence;
      sendAll({ { visca::CONTROL_RESET } }, message.sequence, visca::IP_CONTROL_REPLY);
    }
    return;
  }
  if (message.sequence <= last_sequence_)
  {
    ++counters_.sequence_errors;
    sendAll({ { visca::CONTROL_ERROR, visca::CONTROL_SEQUENCE_ERROR } }, message.sequence, visca::IP_CONTROL_REPLY);
    return;
  }
  last_sequence_ = message.sequence;
  std::vector<visca::Packet> packets;
  splitter_.feed(message.payload.data(), message.payload.size(), packets);
  splitter_.reset();
  for (const visca::Packet& packet : packets)
  {
    execute(packet, at, message.sequence, replies);
  }
  sendAll(replies, message.sequence);
}

void ViscaEmulator::sendAll(const Replies& replies, std::uint32_t sequence, std::uint16_t type)
{
  for (const visca::Packet& packet : replies)
  {
    const visca::Packet bytes =
        config_.framing == ViscaFraming::SONY_IP ? visca::encodeIp(visca::IpMessage{ type, sequence, packet }) : packet;
    port_->send(bytes.data(), bytes.size());
  }
}

visca::Packet ViscaEmulator::reply(std::uint8_t kind, std::initializer_list<std::uint8_t> rest) const
{
  visca::Packet packet(rest.size() + 3, visca::TERMINATOR);
  packet[0] = static_cast<std::uint8_t>((config_.address + 8) << 4);
  packet[1] = kind;
  std::copy(rest.begin(), rest.end(), packet.begin() + 2);
  return packet;
}

void ViscaEmulator::execute(const visca::Packet& packet, TimePoint at, std::uint32_t sequence, Replies& replies)
{
  if (packet[0] == visca::BROADCAST)
  {
    if (packet == visca::addressSet())
    {
      replies.push_back({ visca::BROADCAST, 0x30, static_cast<std::uint8_t>(config_.address + 1), visca::TERMINATOR });
    }
    else if (packet == visca::ifClear())
    {
      sockets_.fill(Socket{});
      replies.push_back(packet);
    }
    return;
  }
  if ((packet[0] & 0x0F) != config_.address)
  {
    return;  // for another camera of the chain
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
  if (kind == 0x01)
  {
    executeCommand(packet, at, sequence, replies);
    return;
  }
  ++counters_.syntax_errors;
  replies.push_back(reply(ERROR, { visca::SYNTAX }));
}

void ViscaEmulator::answerInquiry(const visca::Packet& packet, TimePoint at, Replies& replies)
{
  const PtzSample now = model_.sample(at);
  const visca::ViscaModel& model = config_.model;
  visca::Packet answer = reply(COMPLETION);
  answer.pop_back();
  if (packet.size() == 5 && packet[2] == 0x06 && packet[3] == 0x12)
  {
    visca::putNibbles(answer, static_cast<std::uint16_t>(model.toSteps(PAN, now.position[PAN])), 4);
    visca::putNibbles(answer, static_cast<std::uint16_t>(model.toSteps(TILT, now.position[TILT])), 4);
  }
  else if (packet.size() == 5 && packet[2] == 0x04 && packet[3] == 0x47 && model.has_zoom)
  {
    visca::putNibbles(answer, model.zoomToPosition(now.position[ZOOM]), 4);
  }
  else
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
  const Group group = packet[2] == 0x04 ? Group::ZOOM : Group::PAN_TILT;
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
  if (!run(packet, at, until_rest))
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
  const auto speed_ok = [&](Axis axis, std::uint8_t byte) {
    return byte >= 1 && byte <= model.axes[axis].max_speed_byte;
  };
  if (category == 0x06 && command == 0x01 && size == 9)  // pan-tilt drive
  {
    const std::uint8_t pan = packet[6];
    const std::uint8_t tilt = packet[7];
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
  if (category == 0x06 && (command == 0x02 || command == 0x03) && size == 15)  // absolute, relative
  {
    const auto steps = [&](std::size_t offset) {
      return static_cast<std::int16_t>(static_cast<std::uint16_t>(visca::getNibbles(packet.data() + offset, 4)));
    };
    AxisValues target = model_.sample(at).position;
    for (Axis axis : { PAN, TILT })
    {
      const double value = model.fromSteps(axis, steps(axis == PAN ? 6 : 10));
      target[axis] = command == 0x03 ? target[axis] + value : value;
      if (!model_.config().axes[axis].range.contains(target[axis]))
      {
        return false;
      }
    }
    if (!speed_ok(PAN, packet[4]) || !speed_ok(TILT, packet[5]))
    {
      return false;
    }
    for (Axis axis : { PAN, TILT })
    {
      model_.setCruiseSpeed(axis, model.speedOfByte(axis, packet[axis == PAN ? 4 : 5]), at);
      model_.goToAxis(axis, target[axis], at);
    }
    until_rest = true;
    return true;
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
    const std::uint8_t drive = packet[4];
    const int step = (drive & 0x0F) + 1;
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

void ViscaEmulator::onTick()
{
  Replies replies;
  std::vector<std::uint32_t> sequences;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const PtzSample now = model_.sample(SteadyClock::now());
    for (std::size_t socket = 1; socket < sockets_.size(); ++socket)
    {
      Socket& running = sockets_[socket];
      if (!running.busy || !running.until_rest)
      {
        continue;
      }
      const bool done = running.group == Group::ZOOM ? rests(now, ZOOM) : rests(now, PAN) && rests(now, TILT);
      if (done)
      {
        replies.push_back(reply(static_cast<std::uint8_t>(COMPLETION | socket)));
        sequences.push_back(running.sequence);
        running = Socket{};
      }
    }
  }
  for (std::size_t index = 0; index < replies.size(); ++index)
  {
    sendAll({ replies[index] }, sequences[index]);
  }
}

}  // namespace ptz_action_server
