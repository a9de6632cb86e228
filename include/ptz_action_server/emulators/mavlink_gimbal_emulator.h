/**
 * \file
 * \brief A MAVLink gimbal manager (Gimbal Protocol v2) with its gimbal, on the simulated motion model, over UDP or
 * a pseudo-terminal: the emulator behind `mavlink_gimbal_emulator` and the backend's tests.
 */
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>

#include "ptz_action_server/core/mavlink/mavlink_messages.h"
#include "ptz_action_server/core/sim_device_model.h"
#include "ptz_action_server/core/transport/link.h"
#include "ptz_action_server/emulators/device_port.h"
#include "ptz_action_server/emulators/received_log.h"
#include "ptz_action_server/emulators/udp_socket.h"

namespace ptz_action_server
{
struct MavlinkGimbalEmulatorConfig
{
  LinkKind transport = LinkKind::UDP;  ///< UDP, or SERIAL (a pseudo-terminal, see line)
  std::string host = "127.0.0.1";      ///< udp: where to listen
  std::uint16_t port = 0;              ///< udp: 0 = any free port (see endpoint())
  DevicePortConfig line;               ///< serial: the pseudo-terminal
  std::uint8_t system_id = 1;
  std::uint8_t component_id = mavlink::MAV_COMP_ID_AUTOPILOT1;  ///< the manager: an autopilot, as PX4 and ArduPilot
  std::uint8_t gimbal_device_id = 1;  ///< 1..6: a gimbal the autopilot drives (not itself a MAVLink component)
  double heartbeat_period = 1.0;
  double status_period = 0.2;       ///< s between GIMBAL_MANAGER_STATUS (5 Hz, as the protocol asks)
  double attitude_interval = 1.0;   ///< s between GIMBAL_DEVICE_ATTITUDE_STATUS until SET_MESSAGE_INTERVAL
  double rate_timeout = 0.5;        ///< s a rate setpoint lasts unless repeated
  double vehicle_yaw = 0.0;         ///< rad: the vehicle's heading, delta_yaw in every attitude
  bool report_earth_frame = false;  ///< attitudes with the yaw relative to North (YAW_IN_EARTH_FRAME)
  SimDeviceConfig device = defaultDevice();

  /// A gimbal: pan +-pi at 1.5 rad/s, tilt -pi/2 .. pi/4 at 1 rad/s, no zoom.
  static SimDeviceConfig defaultDevice();
};

/// A frame as it reached the manager.
struct ReceivedMavlinkFrame
{
  TimePoint at;
  mavlink::Frame frame;
};

/// What the manager has seen and done.
struct MavlinkGimbalEmulatorCounters
{
  std::uint64_t setpoints_executed = 0;  ///< SET_PITCHYAW and DO_GIMBAL_MANAGER_PITCHYAW from the primary controller
  std::uint64_t setpoints_ignored = 0;   ///< the same from anyone else
  std::uint64_t commands_denied = 0;
  std::uint64_t rate_timeouts = 0;  ///< rate setpoints not repeated in time: the gimbal stopped
  std::array<std::uint64_t, mavlink::FRAME_ERROR_COUNT> dropped{};
};

/**
 * \brief Behaves as a gimbal manager does towards a controller.
 *
 * HEARTBEAT every heartbeat_period, GIMBAL_MANAGER_STATUS every status_period, GIMBAL_DEVICE_ATTITUDE_STATUS at
 * the interval SET_MESSAGE_INTERVAL asks for; REQUEST_MESSAGE answers GIMBAL_MANAGER_INFORMATION (the model's
 * limits) and GIMBAL_MANAGER_STATUS; DO_GIMBAL_MANAGER_CONFIGURE hands primary control over (-1 unchanged,
 * -2 the manager itself, -3 released) and is DENIED while refusing or while another controller holds control and
 * keeps it; setpoints from anyone but the primary controller are ignored (SET_PITCHYAW) or DENIED
 * (DO_GIMBAL_MANAGER_PITCHYAW); rates stop unless repeated within rate_timeout. Every command gets a COMMAND_ACK
 * (UNSUPPORTED for those it does not model). Owns its I/O thread.
 */
class MavlinkGimbalEmulator
{
public:
  explicit MavlinkGimbalEmulator(const MavlinkGimbalEmulatorConfig& config,
                                 std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~MavlinkGimbalEmulator();
  MavlinkGimbalEmulator(const MavlinkGimbalEmulator&) = delete;
  MavlinkGimbalEmulator& operator=(const MavlinkGimbalEmulator&) = delete;

  /// udp: where the manager listens; "host:port".
  std::string address() const;
  std::uint16_t udpPort() const;
  /// serial: the pseudo-terminal (or its link).
  std::string path() const;

  /// Silent: reads and ignores everything, sends nothing.
  void setSilent(bool silent);
  /// Refuse: DO_GIMBAL_MANAGER_CONFIGURE and DO_GIMBAL_MANAGER_PITCHYAW are DENIED.
  void setRefuse(bool refuse);
  /// Fault hooks of the motion model: a stalled axis accepts every command and silently stays where it is.
  void setFaults(const SimFaults& faults);
  /// Another controller (\p system_id / \p component_id) takes primary control and keeps it until released with
  /// releaseControl().
  void giveControlTo(std::uint8_t system_id, std::uint8_t component_id);
  void releaseControl();
  /// serial: the port vanishes / comes back.
  void unplug();
  void replug();

  /// The primary controller (0/0: none).
  std::pair<std::uint8_t, std::uint8_t> primaryController() const;
  /// The gimbal: pan (yaw in the vehicle frame), tilt (pitch) in rad; zoom 1.
  PtzSample gimbal() const;
  MavlinkGimbalEmulatorCounters counters() const;
  ReceivedLog<ReceivedMavlinkFrame>& received()
  {
    return received_;
  }
  const ReceivedLog<ReceivedMavlinkFrame>& received() const
  {
    return received_;
  }

private:
  void runUdp();
  void receive(const std::uint8_t* data, std::size_t size);
  void tick();
  void handle(const mavlink::Frame& frame, TimePoint now);
  void handleCommand(const mavlink::Frame& frame, const mavlink::CommandLong& command, TimePoint now);
  mavlink::Result configure(const mavlink::Frame& frame, const mavlink::CommandLong& command);
  void setPitchYaw(const mavlink::GimbalManagerSetPitchYaw& setpoint, TimePoint now);
  bool fromPrimary(const mavlink::Frame& frame) const;
  template <class Message>
  void send(const Message& message);
  void sendStatus();
  void sendInformation();
  void sendAttitude(TimePoint now);

  const MavlinkGimbalEmulatorConfig config_;
  const std::shared_ptr<const Clock> clock_;

  std::atomic<bool> silent_{ false };
  std::atomic<bool> refuse_{ false };

  mutable std::mutex mutex_;      ///< guards everything below up to the transports
  mutable SimDeviceModel model_;  ///< mutable: sampling advances it
  mavlink::FrameParser parser_;
  MavlinkGimbalEmulatorCounters counters_;
  std::uint8_t primary_system_ = 0;
  std::uint8_t primary_component_ = 0;
  bool control_kept_ = false;  ///< another controller holds control and refuses to give it up
  std::uint8_t sequence_ = 0;
  double attitude_interval_;
  TimePoint heartbeat_at_{}, status_at_{}, attitude_at_{};
  bool rates_active_ = false;
  TimePoint rates_until_{};
  ReceivedLog<ReceivedMavlinkFrame> received_;

  // The transport: a UDP socket with its thread, or a device port (which has its own).
  UdpSocket udp_;
  bool has_peer_ = false;
  UdpEndpoint peer_;
  std::unique_ptr<DevicePort> line_;
  std::atomic<bool> running_{ true };
  std::thread thread_;
};

}  // namespace ptz_action_server
