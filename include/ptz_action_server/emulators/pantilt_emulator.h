/**
 * \file
 * \brief A PanTilt device controller on UDP: the emulator behind `pantilt_emulator` and the pantilt backend's tests.
 *
 * State reporting, which the PanTilt protocol leaves open, is defined here:
 * - every valid datagram (SET_PARAM, COMMAND or a params frame) is answered with a full params frame;
 * - a params frame with an empty mask (`02 1 MINOR 00 00`) is the "state request": it changes nothing;
 * - every state_period the device also sends a full params frame, unasked, to the last client that sent a valid
 *   datagram.
 * The device speaks one wire format, as a real one does. Invalid datagrams are counted by reason and dropped without
 * a reply; so are frames of another PanTilt format (DecodeError::FOREIGN_FORMAT): they are never executed.
 */
#pragma once

#include <array>
#include <atomic>
#include <deque>
#include <memory>
#include <mutex>
#include <random>
#include <vector>

#include "ptz_action_server/core/framing/slip.h"
#include "ptz_action_server/emulators/ports/device_port.h"
#include "ptz_action_server/emulators/emulator_faults.h"
#include "ptz_action_server/emulators/sim_pantilt.h"
#include "ptz_action_server/emulators/ports/received_log.h"

namespace ptz_action_server
{
using cr::pantilt::SimPanTilt;
using cr::pantilt::WireFormat;
struct PanTiltEmulatorConfig
{
  std::string host = "127.0.0.1";
  std::uint16_t port = 0;  ///< 0: an ephemeral port (see udpPort())
  bool serial = false;     ///< true: SLIP frames on a pseudo-terminal (line) instead of UDP datagrams
  DevicePortConfig line;   ///< serial: the pseudo-terminal
  WireFormat format = WireFormat::SEED;
  double state_period = 0.1;  ///< s between unsolicited params frames (0: replies only)
  SimDeviceConfig device = defaultDevice();

  /// The sim defaults without zoom: a pan-tilt unit.
  static SimDeviceConfig defaultDevice();
};

/// What the device has seen, for diagnostics and tests.
struct PanTiltEmulatorCounters
{
  std::uint64_t commands_executed = 0;  ///< SET_PARAM and COMMAND frames decoded and executed
  std::uint64_t commands_refused = 0;   ///< decoded, but the value or command was refused
  std::uint64_t state_requests = 0;     ///< params frames received
  std::array<std::uint64_t, cr::pantilt::DECODE_ERROR_COUNT> invalid{};  ///< indexed by DecodeError
  std::uint64_t replies_sent = 0;
  std::uint64_t dropped_by_fault = 0;  ///< datagrams ignored while silent, replies dropped on purpose

  /// Datagrams dropped for \p reason.
  std::uint64_t dropped(cr::pantilt::DecodeError reason) const
  {
    return invalid[static_cast<std::size_t>(reason)];
  }
};

/// One frame as it reached the device (a datagram, or a SLIP frame on a serial line).
struct ReceivedDatagram
{
  TimePoint at;
  std::vector<std::uint8_t> bytes;
};

/**
 * \brief Listens on UDP (a frame per datagram) or on a pseudo-terminal (SLIP frames, RFC 1055), executes what
 * arrives on a SimPanTilt, and reports its params. Its DevicePort owns the I/O thread; the periodic params frame goes
 * to the last client that sent a valid frame.
 *
 * Fault switches (any thread): silent (receive and do nothing, send nothing: an unplugged device), a ratio of
 * replies dropped, and a reply delay.
 */
class PanTiltEmulator : public PushEmulatorFaults
{
public:
  explicit PanTiltEmulator(const PanTiltEmulatorConfig& config,
                           std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~PanTiltEmulator() override;
  PanTiltEmulator(const PanTiltEmulator&) = delete;
  PanTiltEmulator& operator=(const PanTiltEmulator&) = delete;

  /// udp: the port the device listens on; 0 on a serial line.
  std::uint16_t udpPort() const;
  /// udp: where the device listens ("host:port").
  std::string address() const;
  /// serial: the pseudo-terminal (or its link); "" on UDP.
  std::string path() const;
  /// serial: the port vanishes / comes back.
  void unplug();
  void replug();

  /// Endless: every reply's bytes are replaced by the filler 'A' (no frame starts or ends in it).
  void setEndless(bool endless) override;
  void setDropRatio(double ratio);
  void setReplyDelay(double seconds);

  /// What the device received, oldest first.
  ReceivedLog<ReceivedDatagram>& received()
  {
    return received_;
  }
  const ReceivedLog<ReceivedDatagram>& received() const
  {
    return received_;
  }
  /// What the device received, classified (pantilt_emulator_classify.cpp): state requests (params frames), STOP, the
  /// parameters and commands that move it (angles, positions, speeds, go-to and move commands), the rest (RESTART,
  /// frames that do not decode in its format).
  std::vector<ClassifiedCommand> classify() const;

  /// udp: sends raw bytes from the device's own socket to \p to ("host:port"; tests: garbage from the device's
  /// address).
  void sendRaw(const std::string& to, const std::uint8_t* data, std::size_t size);

  PanTiltEmulatorCounters counters() const;
  SimPanTilt& panTilt()
  {
    return pan_tilt_;
  }

private:
  bool faultDrop(bool on) override;  ///< half the replies lost
  void setModelFaults(const SimFaults& faults) override;

  struct PendingReply
  {
    TimePoint send_at;
    std::string to;
  };

  void handleDatagram(const std::uint8_t* data, std::size_t size, const std::string& from);
  void reply(const std::string& to, TimePoint now);
  void sendState(const std::string& to);
  /// Delayed replies and the periodic params frame, when due (the port's tick).
  void sendDueReplies(TimePoint now);

  const PanTiltEmulatorConfig config_;
  const std::shared_ptr<const Clock> clock_;
  SimPanTilt pan_tilt_;

  std::atomic<double> drop_ratio_{ 0.0 };
  std::atomic<double> reply_delay_{ 0.0 };

  mutable std::mutex mutex_;  ///< guards the counters
  ReceivedLog<ReceivedDatagram> received_;
  PanTiltEmulatorCounters counters_;

  // I/O thread only.
  bool has_client_ = false;
  std::string last_client_;  ///< udp: "host:port" of the last valid frame's sender
  TimePoint next_state_at_{};
  std::deque<PendingReply> pending_replies_;
  std::mt19937 random_{ 12345 };
  slip::Decoder slip_;
  std::vector<std::uint8_t> framed_;

  std::unique_ptr<DevicePort> port_;  ///< UDP, or the serial line; last: its thread starts after everything above
};

}  // namespace ptz_action_server
