/**
 * \file
 * \brief MAVLink gimbal managers (Gimbal Protocol v2) with their gimbals, on the simulated motion model, over UDP or
 * a pseudo-terminal: the emulator behind `mavlink_gimbal_emulator` and the backend's tests.
 */
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

#include "ptz_action_server/core/mavlink/mavlink_messages.h"
#include "ptz_action_server/core/sim/sim_device_model.h"
#include "ptz_action_server/core/transport/link.h"
#include "ptz_action_server/emulators/ports/device_port.h"
#include "ptz_action_server/emulators/emulator_faults.h"
#include "ptz_action_server/emulators/ports/received_log.h"

namespace ptz_action_server
{
/// A gimbal: pan +-pi at 1.5 rad/s, tilt -pi/2 .. pi/4 at 1 rad/s, no zoom.
SimDeviceConfig defaultMavlinkGimbalDevice();

/**
 * \brief One emulated gimbal and where it sits, as Gimbal Protocol v2 defines gimbal_device_id.
 *
 * - device_id 1..6: a gimbal inside its manager's component (no MAVLink component of its own, as a gimbal an
 *   autopilot drives over PWM, or a camera-gimbal that is its own manager). The manager's component sends its
 *   GIMBAL_DEVICE_ATTITUDE_STATUS, with gimbal_device_id = device_id.
 * - device_id 7..255: a MAVLink gimbal device with that component id (154 = MAV_COMP_ID_GIMBAL, 171..175), beside its
 *   manager. It sends HEARTBEATs (MAV_TYPE_GIMBAL) and its own GIMBAL_DEVICE_ATTITUDE_STATUS with gimbal_device_id 0,
 *   as the message's definition asks of a device whose component is not its manager's.
 *
 * Either way the manager's messages (GIMBAL_MANAGER_INFORMATION, GIMBAL_MANAGER_STATUS) name the gimbal by device_id,
 * and commands and setpoints to the manager address it by device_id (0: every gimbal of that manager).
 */
struct MavlinkEmulatedGimbal
{
  std::uint8_t device_id = 1;
  std::uint8_t manager_component = 0;  ///< the component hosting its gimbal manager; 0: the config's component_id
  SimDeviceConfig device = defaultMavlinkGimbalDevice();
};

struct MavlinkGimbalEmulatorConfig
{
  LinkKind transport = LinkKind::UDP;  ///< UDP, or SERIAL (a pseudo-terminal, see line)
  std::string host = "127.0.0.1";      ///< udp: where to listen
  std::uint16_t port = 0;              ///< udp: 0 = any free port (see endpoint())
  DevicePortConfig line;               ///< serial: the pseudo-terminal
  std::uint8_t system_id = 1;          ///< the vehicle: every component emulated here is part of it
  /// The component hosting the gimbal managers: an autopilot (1, as PX4 and ArduPilot), or a gimbal that manages
  /// itself.
  std::uint8_t component_id = mavlink::MAV_COMP_ID_AUTOPILOT1;
  /// The gimbals (at least one): by default one gimbal inside the manager's component, gimbal_device_id 1.
  std::vector<MavlinkEmulatedGimbal> gimbals{ MavlinkEmulatedGimbal{} };
  double heartbeat_period = 1.0;
  double status_period = 0.2;       ///< s between GIMBAL_MANAGER_STATUS (5 Hz, as the protocol asks)
  double attitude_interval = 1.0;   ///< s between GIMBAL_DEVICE_ATTITUDE_STATUS until SET_MESSAGE_INTERVAL
  double rate_timeout = 0.5;        ///< s a rate setpoint lasts unless repeated
  double vehicle_yaw = 0.0;         ///< rad: the vehicle's heading, delta_yaw in every attitude
  bool report_earth_frame = false;  ///< attitudes with the yaw relative to North (YAW_IN_EARTH_FRAME)
  /// An autopilot that speaks only gimbal protocol v1 (its mount driven by MOUNT_CONTROL): no gimbal manager
  /// (REQUEST_MESSAGE of GIMBAL_MANAGER_INFORMATION answered UNSUPPORTED, no GIMBAL_MANAGER_STATUS, no
  /// GIMBAL_DEVICE_ATTITUDE_STATUS); the mount's orientation goes out as MOUNT_ORIENTATION every attitude_interval,
  /// or with v1_mount_status as ArduPilot's MOUNT_STATUS (the autopilot then says ArduPilot in its HEARTBEAT).
  bool gimbal_v1 = false;
  bool v1_mount_status = false;
  /// PX4's gimbal module driving its gimbal on AUX outputs (MNT_MODE_OUT AUX, src/modules/gimbal/output_rc.cpp):
  /// every GIMBAL_DEVICE_ATTITUDE_STATUS carries NEUTRAL | ROLL_LOCK | PITCH_LOCK | YAW_LOCK and no yaw frame flag,
  /// its quaternion is the output angles relative to the vehicle whatever YAW_LOCK says, and delta_yaw is 0 (PX4
  /// never fills it); the vehicle's heading (vehicle_yaw) goes out in ATTITUDE from the autopilot.
  bool px4_gimbal_output = false;
  /// PX4 losing YAW_IN_EARTH_FRAME on its way to the gimbal (PX4-Autopilot issue 26569): a setpoint's earth-frame
  /// flag is dropped; only YAW_LOCK aims relative to North.
  bool earth_frame_flag_dropped = false;
};

/// A frame as it reached the emulator (whichever of its components it was for).
struct ReceivedMavlinkFrame
{
  TimePoint at;
  mavlink::Frame frame;
};

/// What the managers have seen and done.
struct MavlinkGimbalEmulatorCounters
{
  /// SET_PITCHYAW, SET_ATTITUDE and DO_GIMBAL_MANAGER_PITCHYAW from the primary controller, counted per gimbal driven
  std::uint64_t setpoints_executed = 0;
  std::uint64_t setpoints_ignored = 0;  ///< the same from anyone else
  std::uint64_t commands_denied = 0;
  std::uint64_t rate_timeouts = 0;                 ///< rate setpoints not repeated in time: the gimbal stopped
  std::vector<std::uint64_t> executed_per_gimbal;  ///< setpoints_executed by gimbal, in the config's order
  std::array<std::uint64_t, mavlink::FRAME_ERROR_COUNT> dropped{};
};

/**
 * \brief Behaves as the gimbal managers and gimbal devices of one vehicle do towards a controller.
 *
 * Every component (the managers' and each MAVLink gimbal device's) sends a HEARTBEAT every heartbeat_period (an
 * autopilot's at component 1, MAV_TYPE_GIMBAL elsewhere). Per gimbal: GIMBAL_MANAGER_STATUS every status_period from
 * its manager, GIMBAL_DEVICE_ATTITUDE_STATUS at the interval SET_MESSAGE_INTERVAL asks of the component that sends it.
 * A manager answers REQUEST_MESSAGE with one GIMBAL_MANAGER_INFORMATION (the model's limits) or GIMBAL_MANAGER_STATUS
 * per gimbal; DO_GIMBAL_MANAGER_CONFIGURE hands primary control of the gimbal param7 names (0: all of the manager's)
 * over (-1 unchanged, -2 the manager itself, -3 released if the sender holds it) and is DENIED while refusing, for a
 * gimbal the manager does not have, or while another controller holds control and keeps it. Setpoints
 * (GIMBAL_MANAGER_SET_PITCHYAW, GIMBAL_MANAGER_SET_ATTITUDE with its quaternion and rates,
 * DO_GIMBAL_MANAGER_PITCHYAW) drive the gimbal they name (0: all of the manager's) when they come from its primary
 * controller, and are ignored (messages) or DENIED (the command) otherwise; NEUTRAL goes to pan 0 tilt 0; the yaw
 * is the vehicle's unless YAW_IN_EARTH_FRAME (or, without either frame flag, YAW_LOCK) says North; rates stop
 * unless repeated within rate_timeout. A gimbal device that is not a manager answers manager requests UNSUPPORTED.
 * Every command gets a COMMAND_ACK from each component it addresses (UNSUPPORTED for those it does not model).
 * Owns its I/O thread. The gimbal index of the methods below is its place in the config's gimbals.
 */
class MavlinkGimbalEmulator : public PushEmulatorFaults
{
public:
  /// Throws std::invalid_argument for gimbals the protocol cannot address (see MavlinkEmulatedGimbal).
  explicit MavlinkGimbalEmulator(const MavlinkGimbalEmulatorConfig& config,
                                 std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());
  ~MavlinkGimbalEmulator() override;
  MavlinkGimbalEmulator(const MavlinkGimbalEmulator&) = delete;
  MavlinkGimbalEmulator& operator=(const MavlinkGimbalEmulator&) = delete;

  /// udp: where the components listen; "host:port".
  std::string address() const;
  std::uint16_t udpPort() const;
  /// serial: the pseudo-terminal (or its link).
  std::string path() const;

  /// Silent: on UDP, datagrams go unread too (their sender does not become the peer).
  void setSilent(bool silent) override;
  /// Endless: every reply's bytes are replaced by the filler 'A' (no frame starts or ends in it).
  void setEndless(bool endless) override;
  /// Refuse: DO_GIMBAL_MANAGER_CONFIGURE and DO_GIMBAL_MANAGER_PITCHYAW are DENIED.
  void setRefuse(bool refuse);
  /// Fault hooks of a gimbal's motion model: a stalled axis accepts every command and silently stays where it is.
  void setFaults(const SimFaults& faults, std::size_t gimbal = 0);
  /// Another controller (\p system_id / \p component_id) takes primary control of a gimbal. With \p keep it refuses
  /// to give it up until releaseControl(); without, it yields to a DO_GIMBAL_MANAGER_CONFIGURE (a ground station
  /// that took control earlier and left it).
  void giveControlTo(std::uint8_t system_id, std::uint8_t component_id, bool keep = true, std::size_t gimbal = 0);
  void releaseControl(std::size_t gimbal = 0);
  /// serial: the port vanishes / comes back.
  void unplug();
  void replug();

  std::size_t gimbalCount() const
  {
    return config_.gimbals.size();
  }
  /// A gimbal's primary controller (0/0: none).
  std::pair<std::uint8_t, std::uint8_t> primaryController(std::size_t gimbal = 0) const;
  /// A gimbal: pan (yaw in the vehicle frame), tilt (pitch) in rad; zoom 1.
  PtzSample gimbal(std::size_t gimbal = 0) const;
  MavlinkGimbalEmulatorCounters counters() const;
  ReceivedLog<ReceivedMavlinkFrame>& received()
  {
    return received_;
  }
  const ReceivedLog<ReceivedMavlinkFrame>& received() const
  {
    return received_;
  }
  /// What the manager received, classified (mavlink_gimbal_emulator_classify.cpp): SET_PITCHYAW with angles (with
  /// the yaw they aim at) or with zero rates and no angle (the stop), DO_GIMBAL_MANAGER_CONFIGURE and rate setpoints
  /// (other), and every other message a query (heartbeats, requests, intervals).
  std::vector<ClassifiedCommand> classify() const;

private:
  // No DROP fault: UDP has no connection.
  void setModelFaults(const SimFaults& faults) override;  ///< the first gimbal's

  struct Gimbal;

  void receive(const std::uint8_t* data, std::size_t size);
  void tick();
  void handle(const mavlink::Frame& frame, TimePoint now);
  void handleCommand(std::uint8_t component, const mavlink::Frame& frame, const mavlink::CommandLong& command,
                     TimePoint now);
  mavlink::Result configure(Gimbal& gimbal, const mavlink::Frame& frame, const mavlink::CommandLong& command);
  /// The gimbals the manager at \p component drives for \p gimbal_device_id (0: all of them).
  std::vector<Gimbal*> addressed(std::uint8_t component, std::uint8_t gimbal_device_id);
  /// A setpoint (angles or rates in rad, rad/s; NaN: not set) for \p gimbal from \p frame's sender.
  void setpoint(Gimbal& gimbal, const mavlink::Frame& frame, std::uint32_t flags, float pitch, float yaw,
                float pitch_rate, float yaw_rate, TimePoint now);
  void execute(Gimbal& gimbal, std::uint32_t flags, float pitch, float yaw, float pitch_rate, float yaw_rate,
               TimePoint now);
  bool fromPrimary(const Gimbal& gimbal, const mavlink::Frame& frame) const;
  template <class Message>
  void send(std::uint8_t component, const Message& message);
  void sendStatus(const Gimbal& gimbal);
  void sendInformation(const Gimbal& gimbal);
  void sendAttitude(Gimbal& gimbal, TimePoint now);
  /// gimbal_v1: MOUNT_ORIENTATION (or MOUNT_STATUS) from the autopilot.
  void sendMountAttitude(const Gimbal& gimbal, const PtzSample& state, TimePoint now);
  /// px4_gimbal_output: the attitude as PX4's gimbal module sends it, and the vehicle's ATTITUDE.
  void sendPx4Attitude(const Gimbal& gimbal, const PtzSample& state, TimePoint now);
  Gimbal& at(std::size_t index) const;

  const MavlinkGimbalEmulatorConfig config_;
  const std::shared_ptr<const Clock> clock_;

  std::atomic<bool> refuse_{ false };

  mutable std::mutex mutex_;  ///< guards everything below up to the transports
  std::vector<std::unique_ptr<Gimbal>> gimbals_;
  std::vector<std::uint8_t> components_;  ///< every component emulated: the managers, then the gimbal devices
  mavlink::FrameParser parser_;
  MavlinkGimbalEmulatorCounters counters_;
  std::uint8_t sequence_ = 0;
  TimePoint heartbeat_at_{}, status_at_{};
  ReceivedLog<ReceivedMavlinkFrame> received_;

  /// UDP (replies and streams go to whoever sent last: the controller) or the serial line; its I/O thread runs the
  /// handlers. Last: the thread starts after everything above exists.
  std::unique_ptr<DevicePort> port_;
};

}  // namespace ptz_action_server
