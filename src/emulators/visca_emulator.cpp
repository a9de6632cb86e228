#include "ptz_action_server/emulators/visca_emulator.h"

#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/units.h"
#include "visca_emulator_internal.h"

namespace ptz_action_server
{
namespace
{
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

/// The first VISCA packet's start in \p data (a request, 8x), or size.
std::size_t requestStart(const std::uint8_t* data, std::size_t size)
{
  std::size_t index = 0;
  while (index < size && (data[index] < 0x81 || data[index] > 0x88))
  {
    ++index;
  }
  return index;
}
}  // namespace

const char* const ViscaEmulatorConfig::MODES = "g2-latency, g3-address, ndi-sequence, standard-zoom, no-inquiries, "
                                               "sony-reply-port";

bool ViscaEmulatorConfig::applyMode(const std::string& mode)
{
  if (mode == "g2-latency")
  {
    modes.g2_latency = true;
  }
  else if (mode == "g3-address")
  {
    modes.reply_header = 0xA0;
  }
  else if (mode == "ndi-sequence")
  {
    modes.ndi_sequence = true;
  }
  else if (mode == "standard-zoom")
  {
    modes.standard_zoom_only = true;
  }
  else if (mode == "no-inquiries")
  {
    modes.no_inquiries = true;
  }
  else if (mode == "sony-reply-port")
  {
    modes.reply_port = visca::SONY_IP_PORT;
  }
  else
  {
    return false;
  }
  return true;
}

ViscaEmulator::ViscaEmulator(const ViscaEmulatorConfig& config)
  : LineEmulator(modelConfig(config.model)), config_(config), lens_model_(lensModelConfig(config), SteadyClock::now())
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

double ViscaEmulator::g2Latency(const visca::Packet& packet, std::mt19937& random)
{
  const auto between = [&random](double low, double high) {
    return std::uniform_real_distribution<double>(low, high)(random);
  };
  if (packet.size() < 3 || packet[0] < 0x81 || packet[0] > 0x88)
  {
    return 0.0;
  }
  if (packet[1] == 0x09)
  {
    const bool pan_tilt = packet.size() == 5 && packet[2] == 0x06 && packet[3] == 0x12;
    return pan_tilt ? between(0.088, 0.123) : between(0.026, 0.058);
  }
  return between(0.028, 0.089);  // commands: the ACK
}

double ViscaEmulator::thinkingTime(const std::uint8_t* data, std::size_t size)
{
  double delay = LineEmulator::thinkingTime(data, size);
  if (config_.modes.g2_latency)
  {
    // A request (over VISCA over IP, after its header): the time its reply takes. A piece of one on a serial line
    // waits with the rest, and a control message is answered at once.
    const std::size_t header = config_.framing == ViscaFraming::SONY_IP ? std::min(size, visca::IP_HEADER_SIZE) : 0;
    const std::size_t start = header + requestStart(data + header, size - header);
    const std::uint8_t* end = std::find(data + start, data + size, visca::TERMINATOR);
    if (end != data + size)
    {
      delay += g2Latency(visca::Packet(data + start, end + 1), latency_random_);
    }
  }
  return delay;
}

void ViscaEmulator::onBytes(const std::uint8_t* data, std::size_t size, TimePoint arrived_at)
{
  Replies replies;
  if (config_.port.kind == DevicePortConfig::Kind::UDP)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const std::string sender = port_->sender();
    reply_host_ = sender.substr(0, sender.rfind(':'));
  }
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
  const visca::IpError error = visca::decodeIp(data, size, message);
  if (config_.modes.ndi_sequence && (message.sequence < 1 || message.sequence > 3))
  {
    ++counters_.unread_sequences;  // NDI PTZ1: whatever is numbered outside 1..3 goes unread, even the reset
    return;
  }
  if (error != visca::IpError::NONE)
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
      last_sequence_ = 0;  // "the value that was set as the sequence number is ignored"
      sendAll({ { visca::CONTROL_RESET } }, message.sequence, visca::IP_CONTROL_REPLY);
    }
    else
    {
      sendAll({ { visca::CONTROL_ERROR, visca::CONTROL_MESSAGE_ERROR } }, message.sequence, visca::IP_CONTROL_REPLY);
    }
    return;
  }
  if (message.type != visca::IP_COMMAND && message.type != visca::IP_INQUIRY &&
      message.type != visca::IP_DEVICE_SETTING)
  {
    ++counters_.bad_datagrams;
    sendAll({ { visca::CONTROL_ERROR, visca::CONTROL_MESSAGE_ERROR } }, message.sequence, visca::IP_CONTROL_REPLY);
    return;
  }
  if (!config_.modes.ndi_sequence && message.type != visca::IP_DEVICE_SETTING)
  {
    if (message.sequence <= last_sequence_)
    {
      ++counters_.sequence_errors;
      sendAll({ { visca::CONTROL_ERROR, visca::CONTROL_SEQUENCE_ERROR } }, message.sequence, visca::IP_CONTROL_REPLY);
      return;
    }
    last_sequence_ = message.sequence;
  }
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
  const std::uint32_t numbered = config_.modes.ndi_sequence ? 1 : sequence;  // NDI PTZ1 answers 1, always
  for (const visca::Packet& packet : replies)
  {
    const visca::Packet bytes =
        config_.framing == ViscaFraming::SONY_IP ? visca::encodeIp(visca::IpMessage{ type, numbered, packet }) : packet;
    if (config_.modes.reply_port != 0 && config_.port.kind == DevicePortConfig::Kind::UDP)
    {
      // Sony: replies to 52381 of the controller's host, whatever port asked.
      port_->sendTo(reply_host_ + ":" + std::to_string(config_.modes.reply_port), bytes.data(), bytes.size());
    }
    else
    {
      port_->send(bytes.data(), bytes.size());
    }
  }
}

visca::Packet ViscaEmulator::reply(std::uint8_t kind, std::initializer_list<std::uint8_t> rest) const
{
  visca::Packet packet(rest.size() + 3, visca::TERMINATOR);
  packet[0] = config_.modes.reply_header != 0 ? config_.modes.reply_header :
                                                static_cast<std::uint8_t>((config_.address + 8) << 4);
  packet[1] = kind;
  std::copy(rest.begin(), rest.end(), packet.begin() + 2);
  return packet;
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
        replies.push_back(reply(static_cast<std::uint8_t>(emulator_visca::COMPLETION | socket)));
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
