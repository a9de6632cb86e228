/**
 * \file
 * \brief The mavlink_gimbal backend: Ptz goals for a drone gimbal through its gimbal manager (MAVLink Gimbal
 * Protocol v2), over UDP or a serial line.
 */
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <string>
#include <vector>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/mavlink/mavlink_messages.h"

namespace ptz_action_server
{
/**
 * \brief One gimbal as its gimbal manager announces it (GIMBAL_MANAGER_INFORMATION): the manager's system and
 * component, and the gimbal's gimbal_device_id (see mavlink::isInternalGimbalId()).
 */
struct MavlinkGimbalAddress
{
  std::uint8_t system_id = 0;
  std::uint8_t manager_component = 0;
  std::uint8_t device_id = 0;  ///< 1..6: inside the manager's component; else the gimbal device's component id

  bool operator==(const MavlinkGimbalAddress& other) const
  {
    return system_id == other.system_id && manager_component == other.manager_component && device_id == other.device_id;
  }
  bool operator!=(const MavlinkGimbalAddress& other) const
  {
    return !(*this == other);
  }
  /// The component that sends the gimbal's GIMBAL_DEVICE_ATTITUDE_STATUS: the manager's for a gimbal inside it, the
  /// gimbal device's own for a MAVLink gimbal device.
  std::uint8_t attitudeComponent() const
  {
    return device_id == 0 || mavlink::isInternalGimbalId(device_id) ? manager_component : device_id;
  }
  /// "gimbal_device_id 2 of the gimbal manager 1/1", "gimbal_device_id 154 (the gimbal device 1/154) of the gimbal
  /// manager 1/1".
  std::string describe() const;
};

/// The frame the yaw of a gimbal's GIMBAL_DEVICE_ATTITUDE_STATUS is read in.
enum class MavlinkYawFrame
{
  /// As its flags say (FLAGS), except where an autopilot is known to say otherwise than it does: PX4's own gimbal
  /// output (a gimbal_device_id 1..6 of a PX4 autopilot) sets YAW_LOCK on every attitude, with no frame flag, while
  /// its quaternion is relative to the vehicle (PX4 src/modules/gimbal/output_rc.cpp): read as the vehicle's.
  AUTO,
  /// YAW_IN_EARTH_FRAME or YAW_IN_VEHICLE_FRAME; without either, YAW_LOCK means North (the MAVLink definition).
  FLAGS,
  VEHICLE,  ///< always relative to the vehicle, whatever the flags
  EARTH,    ///< always relative to North, whatever the flags
};

/// What only the MAVLink gimbal protocol needs to know.
struct MavlinkGimbalSettings
{
  std::uint8_t system_id = 1;         ///< ours: the vehicle's system, as a companion computer
  std::uint8_t component_id = 191;    ///< ours: MAV_COMP_ID_ONBOARD_COMPUTER
  std::uint8_t target_system = 0;     ///< the gimbal manager's system; 0: any
  std::uint8_t target_component = 0;  ///< the component that hosts the gimbal manager; 0: any
  /// The gimbal: 1..6 for a gimbal inside its manager's component, or the component id of a MAVLink gimbal device
  /// (154, ...); 0: the only gimbal found (several found and none chosen fails the start, naming them).
  std::uint8_t gimbal_device_id = 0;
  bool yaw_lock = false;  ///< false: yaw relative to the vehicle (ptz_base_link); true: to North (YAW_LOCK)
  MavlinkYawFrame attitude_yaw_frame = MavlinkYawFrame::AUTO;  ///< how the reported yaw is read
  double heartbeat_period = 1.0;                               ///< s
  /// s to listen for gimbal managers after the link opens before choosing among their gimbals (longer than the
  /// components' 1 s heartbeat period); not waited when target_system, target_component and gimbal_device_id name the
  /// gimbal in full.
  double discovery_time = 1.5;
  double attitude_interval = 0.05;  ///< s between GIMBAL_DEVICE_ATTITUDE_STATUS, asked with SET_MESSAGE_INTERVAL
  double rate_period = 0.1;         ///< s between the rate setpoints of a velocity goal (managers time rates out)
  double resend_period = 1.0;       ///< s between repeats of a position setpoint, and of an unanswered request
  AxisCapability pan = fullAxis({ -M_PI, M_PI }, 1.0, 0.0);  ///< max_speed and acceleration: for goal timeouts
  AxisCapability tilt = fullAxis({ -M_PI / 2.0, M_PI / 4.0 }, 1.0, 0.0);
};

struct MavlinkGimbalCounters
{
  Counter frames;              ///< good MAVLink 2 frames
  Counter attitudes;           ///< GIMBAL_DEVICE_ATTITUDE_STATUS of our gimbal
  Counter other_attitudes;     ///< GIMBAL_DEVICE_ATTITUDE_STATUS of other gimbals (or not telling which): dropped
  Counter setpoints;           ///< GIMBAL_MANAGER_SET_PITCHYAW sent
  Counter acks_refused;        ///< COMMAND_ACK results other than ACCEPTED / IN_PROGRESS
  Counter control_lost;        ///< another controller took primary control from us
  Counter foreign_frames;      ///< manager messages of other managers or other gimbals, and acks of others' commands
  Counter unusable_attitudes;  ///< attitudes in the other yaw frame with nothing (delta_yaw, ATTITUDE) to convert them
  std::array<Counter, mavlink::FRAME_ERROR_COUNT> bad;  ///< dropped by the parser, by FrameError
};

/**
 * \brief The client side of Gimbal Protocol v2, over a DeviceSession.
 *
 * Discovery: HEARTBEAT every heartbeat_period; every component that may host a gimbal manager (an autopilot, a
 * MAV_TYPE_GIMBAL component, a component at a gimbal's id, one that sends GIMBAL_MANAGER_STATUS) is asked for its
 * GIMBAL_MANAGER_INFORMATION, one per gimbal it manages. After discovery_time (and the answers asked for), the gimbal
 * the settings name is chosen (target_system, target_component, gimbal_device_id; 0 = any): exactly one must match,
 * else the start fails naming the gimbals found. The choice stands for the backend's life, reconnections included.
 *
 * Control: DO_GIMBAL_MANAGER_CONFIGURE to the manager with param7 = the gimbal's id takes primary control of that
 * gimbal only, confirmed by its GIMBAL_MANAGER_STATUS; a refusal fails the start with the manager's result and who
 * holds control. Before taking it the gimbal's status is looked at (as the protocol asks), and when another controller
 * held primary control the session is warned once (DeviceSession::warn()), naming it. shutdown() releases the gimbal
 * (-3, param7 = its id). When control comes free again (the manager restarted, the other controller released it), it is
 * taken back.
 *
 * Goals: positions as GIMBAL_MANAGER_SET_PITCHYAW to the manager for the gimbal (pitch = tilt, yaw = pan, rates NaN),
 * repeated every resend_period against loss; velocities as rates with NaN angles, repeated every rate_period; stop as
 * zero rates. State: GIMBAL_DEVICE_ATTITUDE_STATUS of the chosen gimbal only (its system; the manager's component with
 * its id 1..6, or the gimbal device's component with 0), asked for at attitude_interval from the component that sends
 * it; the quaternion turned into pan and tilt (in the vehicle frame, or North with yaw_lock, using delta_yaw when the
 * gimbal reports the other frame). Other gimbals' attitudes are counted and dropped. A COMMAND_ACK other than
 * ACCEPTED, or another controller taking control, is a device fault that aborts the goal with its name.
 *
 * The yaw frame of an attitude is read as attitude_yaw_frame says; converting it to the other frame takes the
 * attitude's delta_yaw, or (where it is missing, or 0 from PX4, which never fills it) the heading of the vehicle's
 * ATTITUDE.
 *
 * An autopilot that never answers with a GIMBAL_MANAGER_INFORMATION (it refuses the request, or is asked three
 * times) fails the start once discovery is over, saying what it speaks as far as it was heard: gimbal protocol v1
 * (MOUNT_ORIENTATION, MOUNT_STATUS), a gimbal device's attitude with no manager, or HEARTBEATs only; and what to set
 * (PX4's MNT_MODE_IN / MNT_MODE_OUT, ArduPilot's MNT1_TYPE and firmware 4.3 or later).
 */
class MavlinkGimbalProtocol : public DeviceProtocol
{
public:
  /// DeviceConfig<MavlinkGimbalProtocol> (device_backend.h): these settings, and the defaults of the link and the
  /// session.
  using Settings = MavlinkGimbalSettings;
  /// udp (the default) or serial
  static LinkConfig defaultLink()
  {
    LinkConfig link;
    link.kind = LinkKind::UDP;
    link.port = 14550;
    link.reconnect_min = 0.1;
    return link;
  }
  /// No attitude for 1 s drops the link (asked for every 50 ms).
  static DeviceSessionConfig defaultSession()
  {
    return { 1.0, 0.05, 10.0, 0.15, 0.5 };
  }

  MavlinkGimbalProtocol(const MavlinkGimbalSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "mavlink_gimbal";
  }
  std::string deviceName() const override;
  /// Pan and tilt from the settings (the manager's limits narrow them once known): positions, rates and attitude
  /// feedback; no zoom.
  Capabilities capabilities() const override;
  void onConnected() override;
  void onReceived(const std::uint8_t* data, std::size_t size) override;
  void onDisconnected() override;
  /// Heartbeat, discovery, repeats of unanswered requests, rate setpoints.
  void poll() override;
  void goTo(const AxisValues& position) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  /// Zero rates with NaN angles: the gimbal stops where it is.
  void stop() override;
  /// Releases primary control of the gimbal.
  void shutdown() override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const MavlinkGimbalCounters& counters() const
  {
    return counters_;
  }
  /// The gimbal driven (all zero until chosen). Any thread.
  MavlinkGimbalAddress gimbal() const;

private:
  /// What the node last asked of the gimbal, and when it was last sent.
  enum class Setpoint
  {
    NONE,
    POSITION,
    RATES,
    STOP,
  };
  /// A command awaiting its COMMAND_ACK, by MAV_CMD and the component it went to.
  struct PendingCommand
  {
    std::uint64_t goal_command;  ///< the session command current when it was sent
    TimePoint sent_at;
  };
  /// A component asked for its GIMBAL_MANAGER_INFORMATION during discovery.
  struct Asked
  {
    TimePoint first_at;
    TimePoint last_at;
    int times = 0;
    bool answered = false;  ///< its information came, or it refused the request (no manager)
  };
  /// A gimbal some manager announced.
  struct FoundGimbal
  {
    MavlinkGimbalAddress address;
    mavlink::GimbalManagerInformation information;
  };

  void handle(const mavlink::Frame& frame);
  void handleHeartbeat(const mavlink::Frame& frame);
  void handleInformation(const mavlink::Frame& frame, const mavlink::GimbalManagerInformation& information);
  void handleStatus(const mavlink::Frame& frame, const mavlink::GimbalManagerStatus& status);
  void handleAck(const mavlink::Frame& frame, const mavlink::CommandAck& ack);
  void handleAttitude(const mavlink::Frame& frame, const mavlink::GimbalDeviceAttitudeStatus& attitude);
  /// ATTITUDE of the gimbal's vehicle: its heading, to turn a yaw from one frame into the other.
  void handleVehicleAttitude(const mavlink::Frame& frame);
  /// Keeps what a component says of itself during discovery, for failWithoutManager().
  void noteHeard(const mavlink::Frame& frame);
  /// The attitude's yaw is relative to North (else to the vehicle), as attitude_yaw_frame reads it.
  bool attitudeInEarthFrame(const mavlink::GimbalDeviceAttitudeStatus& attitude) const;
  /// Its manager is PX4's own gimbal module (a gimbal 1..6 inside a PX4 autopilot).
  bool px4GimbalOutput(const mavlink::GimbalDeviceAttitudeStatus& attitude) const;

  // Discovery.
  /// The settings allow a manager at \p system_id / \p component_id.
  bool managerAllowed(std::uint8_t system_id, std::uint8_t component_id) const;
  bool gimbalAllowed(const MavlinkGimbalAddress& address) const;
  /// Asks a possible manager for its information, unless it answered or was asked often enough already.
  void askCandidate(std::uint8_t system_id, std::uint8_t component_id);
  /// Chooses the gimbal once discovery allows it, or fails the start when it cannot.
  void discover();
  void choose(const FoundGimbal& found);
  /// No manager answered and none is left to ask: fails the start saying what the vehicle speaks; false while
  /// discovery still waits for an answer.
  bool failWithoutManager();
  /// The names of the gimbals found, for messages.
  std::string foundList(const std::vector<const FoundGimbal*>& gimbals) const;

  // The chosen gimbal.
  bool fromManager(const mavlink::Frame& frame) const;
  /// \p gimbal_device_id (of a manager message from the manager) names our gimbal.
  bool namesOurGimbal(std::uint8_t gimbal_device_id) const;
  bool isOurAttitude(const mavlink::Frame& frame, const mavlink::GimbalDeviceAttitudeStatus& attitude) const;
  void applyInformation(const mavlink::GimbalManagerInformation& information);
  /// Says ready() once the limits are known and control is ours.
  void startIfReady();
  /// Warns (once) that \p system_id / \p component_id held primary control before us.
  void warnPreviousController(std::uint8_t system_id, std::uint8_t component_id);
  /// \p period s or more have passed since \p last.
  bool due(TimePoint last, double period) const
  {
    return secondsBetween(last, session_.now()) >= period;
  }

  template <class Message>
  void send(const Message& message);
  /// COMMAND_LONG to the manager, awaiting its ACK.
  void sendCommand(std::uint16_t command, const std::array<float, 7>& params);
  void sendCommandTo(std::uint8_t system_id, std::uint8_t component_id, std::uint16_t command,
                     const std::array<float, 7>& params);
  /// REQUEST_MESSAGE GIMBAL_MANAGER_INFORMATION.
  void requestInformation(std::uint8_t system_id, std::uint8_t component_id);
  void takeControl();
  void requestAttitude();
  void sendSetpoint();
  std::uint32_t setpointFlags() const;
  std::string controllerName(std::uint8_t system_id, std::uint8_t component_id) const;
  /// " (primary control of the gimbal is held by 3/190)", from the last status.
  std::string heldBy() const;

  const MavlinkGimbalSettings settings_;
  DeviceSession& session_;
  MavlinkGimbalCounters counters_;
  mavlink::FrameParser parser_;
  std::uint64_t dropped_reported_ = 0;  ///< of parser_'s noise bytes, those reported to the session

  // Written on the I/O thread under names_mutex_, which deviceName(), gimbal() and diagnostics() take; the I/O thread
  // reads them without it.
  mutable std::mutex names_mutex_;
  bool chosen_ = false;
  MavlinkGimbalAddress gimbal_;
  std::string found_names_;          ///< the gimbals discovery found, for diagnostics
  std::string previous_controller_;  ///< who held primary control before we took it ("" if no one)
  std::atomic<bool> in_control_{ false };

  // I/O thread only.
  std::map<std::uint16_t, Asked> asked_;  ///< by system_id << 8 | component_id
  std::vector<FoundGimbal> found_;
  std::map<std::uint32_t, mavlink::GimbalManagerStatus> statuses_;  ///< before the choice, by address
  /// What a component said of itself before the choice (and its autopilot type always), by system_id << 8 |
  /// component_id.
  struct Heard
  {
    std::uint8_t autopilot = mavlink::MAV_AUTOPILOT_INVALID;  ///< its HEARTBEAT's
    std::uint8_t type = 0;                                    ///< MAV_TYPE
    bool mount_orientation = false;                           ///< gimbal protocol v1
    bool mount_status = false;                                ///< gimbal protocol v1 (ArduPilot)
    bool device_attitude = false;                             ///< GIMBAL_DEVICE_ATTITUDE_STATUS
  };
  std::map<std::uint16_t, Heard> heard_;
  double vehicle_yaw_ = 0.0;  ///< rad, the last ATTITUDE's heading of the gimbal's vehicle
  TimePoint vehicle_yaw_at_{};
  bool vehicle_yaw_known_ = false;
  std::atomic<int> attitude_frame_{ -1 };  ///< the last attitude's yaw frame: 0 vehicle, 1 North, -1 none yet
  TimePoint listening_since_{};
  bool discovery_failed_ = false;
  std::set<std::uint8_t> manager_gimbals_;  ///< the gimbal ids the chosen manager component announced
  bool informed_ = false;                   ///< the chosen gimbal's GIMBAL_MANAGER_INFORMATION is applied
  bool status_seen_ = false;                ///< a GIMBAL_MANAGER_STATUS of our gimbal came on this connection
  TimePoint chosen_at_{};                   ///< on this connection (the wait for a status before taking control)
  bool control_requested_ = false;          ///< DO_GIMBAL_MANAGER_CONFIGURE sent on this connection
  bool warned_ = false;
  bool attitude_requested_ = false;  ///< SET_MESSAGE_INTERVAL answered (or asked often enough)
  int attitude_asks_ = 0;
  bool ready_ = false;              ///< ready() was said on this connection
  bool ever_ready_ = false;         ///< the start-up is over: refusals are goal faults from now on
  std::uint8_t holder_system_ = 0;  ///< who holds primary control, as the last status said
  std::uint8_t holder_component_ = 0;
  std::string startup_refusal_;  ///< control refused at start-up, awaiting the status that names the holder
  TimePoint refused_at_{};
  std::uint8_t sequence_ = 0;
  std::map<std::uint32_t, PendingCommand> pending_;  ///< by MAV_CMD << 16 | system_id << 8 | component_id
  TimePoint heartbeat_at_{};
  TimePoint information_asked_at_{};
  TimePoint control_asked_at_{};
  TimePoint attitude_asked_at_{};
  Setpoint setpoint_ = Setpoint::NONE;
  AxisValues setpoint_values_{};
  TimePoint setpoint_sent_at_{};
  TimePoint stop_until_{};
};

}  // namespace ptz_action_server
