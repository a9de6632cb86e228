#include "device_table.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/emulators/visca_emulator.h"

namespace ptz_bench
{
namespace
{
using namespace ptz_action_server;
using PortKind = DevicePortConfig::Kind;

bool isHalt(const visca::Packet& packet)
{
  return packet.size() == 9 && packet[2] == 0x06 && packet[3] == 0x01 && packet[6] == 0x03 && packet[7] == 0x03;
}

/// A command of the node's, not an inquiry, a start-up broadcast or a control message.
bool isCommand(const ReceivedPacket& item)
{
  return !item.control && item.packet.size() > 3 && item.packet[0] != visca::BROADCAST && item.packet[1] == 0x01;
}

class ViscaDevice : public EmulatedDevice
{
public:
  ViscaDevice(const DevicePortConfig& port, ViscaFraming framing) : emulator_(config(port, framing))
  {
  }
  std::uint16_t port() const override
  {
    return emulator_.port().udpPort();
  }
  std::string link() const override
  {
    return emulator_.port().udpPort() == 0 ? emulator_.path() : "";
  }
  std::vector<Arrival> goalCommands() const override
  {
    return select([](const visca::Packet& packet) { return !isHalt(packet); });
  }
  std::vector<Arrival> stopCommands() const override
  {
    return select(isHalt);
  }

  ptz_action_server::EmulatorFaults* faults() override
  {
    return &emulator_;
  }

private:
  static ViscaEmulatorConfig config(const DevicePortConfig& port, ViscaFraming framing)
  {
    ViscaEmulatorConfig config;
    config.port = port;
    config.framing = framing;
    return config;
  }
  template <class Predicate>
  std::vector<Arrival> select(Predicate predicate) const
  {
    const double byte_time = emulator_.port().byteTime();
    std::vector<Arrival> arrivals;
    for (const ReceivedPacket& item : emulator_.received().items())
    {
      if (isCommand(item) && predicate(item.packet))
      {
        arrivals.push_back(Arrival{ item.at, item.packet.size() * byte_time });
      }
    }
    return arrivals;
  }
  mutable ViscaEmulator emulator_;  ///< mutable: port() is not const
};
}  // namespace

EmulatorSpec viscaEmulator(PortKind kind, unsigned baud)
{
  const bool udp = kind == PortKind::UDP;
  EmulatorSpec spec;
  spec.summary = "ViscaEmulator (address 1, ptzoptics), " + portSummary(kind, baud) + (udp ? ", sony_ip" : ", raw");
  spec.goal_items = "every command packet but the pan-tilt drive stop; wire time: its bytes";
  spec.stop_items = "the pan-tilt drive stop (`81 01 06 01 VV WW 03 03 FF`)";
  // A goal is two commands, each answered by an ACK (3 bytes) before the next goes.
  spec.goal_pause = 3 * (15 + 9 + 6) * byteTime(kind, baud) + 0.005;
  // On a serial line an inquiry and its answer (16 bytes) may be on the wire first.
  spec.goal_target = udp ? "p99 <= 5 ms" :
                           formatText("p99 <= one inquiry + 2 ms (%.1f ms)", (16 * byteTime(kind, baud) + 0.002) * 1e3);
  spec.stop_target = udp ? "p99 <= 5 ms" : spec.goal_target;
  spec.start = [kind, baud, udp](const std::string& row) {
    DevicePortConfig port = portConfig(kind, baud, row);
    return std::make_unique<ViscaDevice>(port, udp ? ViscaFraming::SONY_IP : ViscaFraming::RAW);
  };
  return spec;
}

}  // namespace ptz_bench
