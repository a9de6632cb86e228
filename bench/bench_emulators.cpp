#include <string>

#include "bench_processes.h"
#include "device_table.h"
#include "ptz_action_server/core/pantilt/pantilt_codec.h"
#include "ptz_action_server/core/pelco_d/pelco_d_codec.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/emulators/digiview_emulator.h"
#include "ptz_action_server/emulators/flir_ptu_emulator.h"
#include "ptz_action_server/emulators/pantilt_emulator.h"
#include "ptz_action_server/emulators/pelco_d_emulator.h"

namespace ptz_bench
{
namespace
{
using namespace ptz_action_server;
using PortKind = DevicePortConfig::Kind;

class PanTiltDevice : public EmulatedDevice
{
public:
  PanTiltDevice() : emulator_(PanTiltEmulatorConfig())  // 127.0.0.1, ephemeral port, format seed
  {
  }
  std::uint16_t port() const override
  {
    return emulator_.udpPort();
  }
  std::string link() const override
  {
    return "";
  }
  std::vector<Arrival> goalCommands() const override
  {
    return select([](const ReceivedDatagram& datagram) {
      return datagram.bytes[0] != cr::pantilt::PARAMS_HEADER && !isStop(datagram);
    });
  }
  std::vector<Arrival> stopCommands() const override
  {
    return select(isStop);
  }
  ptz_action_server::EmulatorFaults* faults() override
  {
    return &emulator_;
  }

private:
  static bool isStop(const ReceivedDatagram& datagram)
  {
    cr::pantilt::PanTiltParam param{};
    cr::pantilt::PanTiltCommand command{};
    float value = 0.0f;
    return cr::pantilt::PanTilt::decodeCommand(datagram.bytes.data(), static_cast<int>(datagram.bytes.size()), param,
                                               command, value) == 0 &&
           command == cr::pantilt::PanTiltCommand::STOP;
  }
  template <class Predicate>
  std::vector<Arrival> select(Predicate predicate) const
  {
    std::vector<Arrival> arrivals;
    for (const ReceivedDatagram& datagram : emulator_.received().items())
    {
      if (!datagram.bytes.empty() && predicate(datagram))
      {
        arrivals.push_back(Arrival{ datagram.at, 0.0 });
      }
    }
    return arrivals;
  }
  PanTiltEmulator emulator_;
};

class DigiViewDevice : public EmulatedDevice
{
public:
  DigiViewDevice() : emulator_(DigiViewEmulatorConfig())  // TCP on 127.0.0.1, ephemeral port
  {
  }
  std::uint16_t port() const override
  {
    return emulator_.port();
  }
  std::string link() const override
  {
    return "";
  }
  std::vector<Arrival> goalCommands() const override
  {
    return targetings();
  }
  /// DigiView has no stop: the backend sets the view's target where it would come to rest.
  std::vector<Arrival> stopCommands() const override
  {
    return targetings();
  }
  ptz_action_server::EmulatorFaults* faults() override
  {
    return &emulator_;
  }

private:
  std::vector<Arrival> targetings() const
  {
    std::vector<Arrival> arrivals;
    for (const ReceivedMessage& item : emulator_.received().items())
    {
      if (item.error == digiview::UnpackError::NONE &&
          item.message.message_type == digiview::MessageType::SET_PARAMETERS &&
          item.message.param_type == digiview::ParamType::CAM_TARGETING)
      {
        arrivals.push_back(Arrival{ item.at, 0.0 });
      }
    }
    return arrivals;
  }
  DigiViewEmulator emulator_;
};

class FlirDevice : public EmulatedDevice
{
public:
  explicit FlirDevice(const DevicePortConfig& port) : emulator_(config(port))
  {
  }
  std::uint16_t port() const override
  {
    return emulator_.port().tcpPort();
  }
  std::string link() const override
  {
    return emulator_.port().tcpPort() == 0 ? emulator_.path() : "";
  }
  std::vector<Arrival> goalCommands() const override
  {
    return select([](const std::string& text) { return text != "PP" && text != "TP" && !isHalt(text); });
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
  static FlirPtuEmulatorConfig config(const DevicePortConfig& port)
  {
    FlirPtuEmulatorConfig config;
    config.port = port;
    return config;
  }
  static bool isHalt(const std::string& text)
  {
    return text == "H" || text == "HP" || text == "HT";
  }
  template <class Predicate>
  std::vector<Arrival> select(Predicate predicate) const
  {
    // Each command crossed the line with its delimiter.
    const double byte_time = emulator_.port().byteTime();
    std::vector<Arrival> arrivals;
    for (const ReceivedCommand& command : emulator_.received().items())
    {
      if (predicate(command.text))
      {
        arrivals.push_back(Arrival{ command.at, (command.text.size() + 1) * byte_time });
      }
    }
    return arrivals;
  }
  mutable FlirPtuEmulator emulator_;  ///< mutable: port() is not const
};

class PelcoDevice : public EmulatedDevice
{
public:
  explicit PelcoDevice(const DevicePortConfig& port) : emulator_(config(port))
  {
  }
  std::uint16_t port() const override
  {
    return emulator_.port().tcpPort();
  }
  std::string link() const override
  {
    return emulator_.port().tcpPort() == 0 ? emulator_.path() : "";
  }
  std::vector<Arrival> goalCommands() const override
  {
    return select([](const pelco::Frame& frame) {
      const std::uint8_t command = frame.command2;
      return command != pelco::QUERY_PAN && command != pelco::QUERY_TILT && command != pelco::QUERY_ZOOM &&
             !(frame == pelco::stop(frame.address));
    });
  }
  std::vector<Arrival> stopCommands() const override
  {
    return select([](const pelco::Frame& frame) { return frame == pelco::stop(frame.address); });
  }

  ptz_action_server::EmulatorFaults* faults() override
  {
    return &emulator_;
  }

private:
  static PelcoDEmulatorConfig config(const DevicePortConfig& port)
  {
    PelcoDEmulatorConfig config;
    config.port = port;
    return config;
  }
  template <class Predicate>
  std::vector<Arrival> select(Predicate predicate) const
  {
    const double wire = pelco::FRAME_SIZE * emulator_.port().byteTime();
    std::vector<Arrival> arrivals;
    for (const ReceivedFrame& item : emulator_.received().items())
    {
      if (predicate(item.frame))
      {
        arrivals.push_back(Arrival{ item.at, wire });
      }
    }
    return arrivals;
  }
  mutable PelcoDEmulator emulator_;  ///< mutable: port() is not const
};
}  // namespace

EmulatorSpec panTiltEmulator()
{
  EmulatorSpec spec;
  spec.summary = "PanTiltEmulator, UDP on 127.0.0.1, ephemeral port, format seed";
  spec.goal_items = "every datagram but a params frame (state request) or STOP; no wire time";
  spec.stop_items = "a COMMAND datagram STOP";
  spec.goal_target = spec.stop_target = "p99 <= 5 ms";
  spec.start = [](const std::string&) { return std::make_unique<PanTiltDevice>(); };
  return spec;
}

EmulatorSpec digiViewEmulator()
{
  EmulatorSpec spec;
  spec.summary = "DigiViewEmulator, TCP server on 127.0.0.1, ephemeral port";
  spec.goal_items = "SET_PARAMETERS CAM_TARGETING; no wire time";
  spec.stop_items = "the first SET_PARAMETERS CAM_TARGETING after the cancel (DigiView has no stop: the view is held)";
  spec.goal_target = spec.stop_target = "p99 <= 5 ms";
  spec.start = [](const std::string&) { return std::make_unique<DigiViewDevice>(); };
  return spec;
}

EmulatorSpec flirEmulator(PortKind kind, unsigned baud)
{
  EmulatorSpec spec;
  spec.summary = "FlirPtuEmulator, " + portSummary(kind, baud);
  spec.goal_items = "every command but the PP / TP polls and a halt; wire time: its characters and the delimiter";
  spec.stop_items = "H (halt)";
  spec.goal_pause = 80 * byteTime(kind, baud) + 0.005;
  // On a serial line an exchange already on the wire (a poll and its reply, ~12 bytes) may go first; the tests
  // allowed it and 1 ms.
  spec.goal_target = kind == PortKind::TCP ? "p99 <= 5 ms" : "";
  spec.stop_target = kind == PortKind::TCP ?
                         "p99 <= 5 ms" :
                         formatText("p99 <= one exchange + 1 ms (%.1f ms)", (12 * byteTime(kind, baud) + 0.001) * 1e3);
  spec.start = [kind, baud](const std::string& row) {
    return std::make_unique<FlirDevice>(portConfig(kind, baud, row));
  };
  return spec;
}

EmulatorSpec pelcoEmulator(PortKind kind, unsigned baud)
{
  EmulatorSpec spec;
  spec.summary = "PelcoDEmulator (address 1), " + portSummary(kind, baud);
  spec.goal_items = "every frame but a position query or a stop; wire time: 7 bytes";
  spec.stop_items = "the stop frame (all zero)";
  spec.goal_pause = 6 * pelco::FRAME_SIZE * byteTime(kind, baud) + 0.005;
  // On a serial line a frame already on the wire (a query) may go first; the tests allowed it and 2 ms.
  spec.goal_target = kind == PortKind::TCP ? "p99 <= 5 ms" : "";
  spec.stop_target = kind == PortKind::TCP ? "p99 <= 5 ms" :
                                             formatText("p99 <= one frame time + 2 ms (%.1f ms)",
                                                        (pelco::FRAME_SIZE * byteTime(kind, baud) + 0.002) * 1e3);
  spec.start = [kind, baud](const std::string& row) {
    return std::make_unique<PelcoDevice>(portConfig(kind, baud, row));
  };
  return spec;
}

}  // namespace ptz_bench
