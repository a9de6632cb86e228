/**
 * \file
 * \brief The mavlink_gimbal backend: Ptz goals for a drone gimbal through its gimbal manager (MAVLink Gimbal
 * Protocol v2), over UDP or a serial line.
 */
#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/mavlink/mavlink_messages.h"

namespace ptz_action_server
{
/// What only the MAVLink gimbal protocol needs to know.
struct MavlinkGimbalSettings
{
  std::uint8_t system_id = 1;         ///< ours: the vehicle's system, as a companion computer
  std::uint8_t component_id = 191;    ///< ours: MAV_COMP_ID_ONBOARD_COMPUTER
  std::uint8_t target_system = 0;     ///< the gimbal manager's system; 0: the first manager heard
  std::uint8_t target_component = 0;  ///< the gimbal manager's component; 0: the first manager heard
  std::uint8_t gimbal_device_id = 0;  ///< the gimbal the manager drives; 0: the one its information names
  bool yaw_lock = false;              ///< false: yaw relative to the vehicle (ptz_base_link); true: to North (YAW_LOCK)
  double heartbeat_period = 1.0;      ///< s
  double attitude_interval = 0.05;    ///< s between GIMBAL_DEVICE_ATTITUDE_STATUS, asked with SET_MESSAGE_INTERVAL
  double rate_period = 0.1;           ///< s between the rate setpoints of a velocity goal (managers time rates out)
  double resend_period = 1.0;         ///< s between repeats of a position setpoint, and of an unanswered request
  AxisCapability pan = fullAxis({ -M_PI, M_PI }, 1.0, 0.0);  ///< max_speed and acceleration: for goal timeouts
  AxisCapability tilt = fullAxis({ -M_PI / 2.0, M_PI / 4.0 }, 1.0, 0.0);
};

/// Everything a mavlink_gimbal backend is built from.
struct MavlinkGimbalConfig
{
  MavlinkGimbalConfig()
  {
    link.kind = LinkKind::UDP;
    link.port = 14550;
    link.reconnect_min = 0.1;
  }
  LinkConfig link;  ///< udp (the default) or serial
  /// No attitude for 1 s drops the link (asked for every 50 ms).
  DeviceSessionConfig session{ 1.0, 0.05, 10.0, 0.15, 0.5 };
  MavlinkGimbalSettings gimbal;
};

struct MavlinkGimbalCounters
{
  Counter frames;              ///< good MAVLink 2 frames
  Counter attitudes;           ///< GIMBAL_DEVICE_ATTITUDE_STATUS of our gimbal
  Counter setpoints;           ///< GIMBAL_MANAGER_SET_PITCHYAW sent
  Counter acks_refused;        ///< COMMAND_ACK results other than ACCEPTED / IN_PROGRESS
  Counter control_lost;        ///< another controller took primary control from us
  Counter foreign_frames;      ///< good frames from systems other than the manager's, or for another gimbal
  Counter unusable_attitudes;  ///< attitudes in the other yaw frame without a delta_yaw to convert them
  std::array<Counter, mavlink::FRAME_ERROR_COUNT> bad;  ///< dropped by the parser, by FrameError
};

/**
 * \brief The client side of Gimbal Protocol v2, over a DeviceSession.
 *
 * Start-up: HEARTBEAT every heartbeat_period; the gimbal manager is the configured one or, if none is, the first
 * that speaks (a GIMBAL_MANAGER_STATUS, or a heartbeat of an autopilot or of MAV_COMP_ID_GIMBAL). REQUEST_MESSAGE
 * GIMBAL_MANAGER_INFORMATION gives the limits (intersected with the settings') and the gimbal;
 * DO_GIMBAL_MANAGER_CONFIGURE takes primary control with our ids, confirmed by GIMBAL_MANAGER_STATUS; a refusal
 * fails the start with the manager's result and who holds control. SET_MESSAGE_INTERVAL asks for the attitude.
 *
 * Goals: positions as GIMBAL_MANAGER_SET_PITCHYAW (pitch = tilt, yaw = pan, rates NaN), repeated every
 * resend_period against loss; velocities as rates with NaN angles, repeated every rate_period; stop as zero rates.
 * State: GIMBAL_DEVICE_ATTITUDE_STATUS, the quaternion turned into pan and tilt (in the vehicle frame, or North
 * with yaw_lock, using delta_yaw when the gimbal reports the other frame). A COMMAND_ACK other than ACCEPTED, or
 * another controller taking control, is a device fault that aborts the goal with its name. When control comes
 * free again (the manager restarted, the other controller released it), it is taken back.
 */
class MavlinkGimbalProtocol : public DeviceProtocol
{
public:
  MavlinkGimbalProtocol(const MavlinkGimbalSettings& settings, DeviceSession& session);

  std::string name() const override
  {
    return "mavlink_gimbal";
  }
  std::string deviceName() const override;
  /// Pan and tilt from the settings (the manager's limits narrow them once known); no zoom.
  Capabilities capabilities() const override;
  void onConnected() override;
  void onReceived(const std::uint8_t* data, std::size_t size) override;
  void onDisconnected() override;
  /// Heartbeat, repeats of unanswered requests, rate setpoints.
  void poll() override;
  void goTo(const AxisValues& position) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  /// Zero rates with NaN angles: the gimbal stops where it is.
  void stop() override;
  /// Releases primary control.
  void shutdown() override;
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  const MavlinkGimbalCounters& counters() const
  {
    return counters_;
  }

private:
  /// What the node last asked of the gimbal, and when it was last sent.
  enum class Setpoint
  {
    NONE,
    POSITION,
    RATES,
    STOP,
  };
  struct PendingCommand
  {
    std::uint64_t goal_command;  ///< the session command current when it was sent
    TimePoint sent_at;
  };

  void handle(const mavlink::Frame& frame);
  void handleHeartbeat(const mavlink::Frame& frame);
  void handleInformation(const mavlink::GimbalManagerInformation& information);
  void handleStatus(const mavlink::GimbalManagerStatus& status);
  void handleAck(const mavlink::CommandAck& ack);
  void handleAttitude(const mavlink::GimbalDeviceAttitudeStatus& attitude);
  /// Says ready() once the limits are known and control is ours.
  void startIfReady();
  bool fromManager(const mavlink::Frame& frame) const;
  /// \p period s or more have passed since \p last.
  bool due(TimePoint last, double period) const
  {
    return secondsBetween(last, session_.now()) >= period;
  }
  void chooseManager(std::uint8_t system_id, std::uint8_t component_id);

  template <class Message>
  void send(const Message& message);
  /// COMMAND_LONG to the manager, awaiting its ACK.
  void sendCommand(std::uint16_t command, const std::array<float, 7>& params);
  void sendCommandTo(std::uint8_t system_id, std::uint8_t component_id, std::uint16_t command,
                     const std::array<float, 7>& params);
  /// REQUEST_MESSAGE GIMBAL_MANAGER_INFORMATION, of the manager or of a candidate.
  void requestInformation();
  void requestInformation(std::uint8_t system_id, std::uint8_t component_id);
  void takeControl();
  void requestAttitude();
  void sendSetpoint();
  std::uint32_t setpointFlags() const;
  std::string managerName() const;
  std::string controllerName(std::uint8_t system_id, std::uint8_t component_id) const;
  /// " (primary control of the gimbal is held by 3/190)", from the last status.
  std::string heldBy() const;

  const MavlinkGimbalSettings settings_;
  DeviceSession& session_;
  MavlinkGimbalCounters counters_;
  mavlink::FrameParser parser_;

  // Written on the I/O thread under names_mutex_, which deviceName() and diagnostics() take; the I/O thread reads
  // them without it.
  mutable std::mutex names_mutex_;
  std::uint8_t manager_system_ = 0;
  std::uint8_t manager_component_ = 0;
  std::atomic<std::uint8_t> gimbal_device_id_{ 0 };
  std::atomic<bool> in_control_{ false };

  // I/O thread only.
  bool manager_known_ = false;
  bool informed_ = false;            ///< GIMBAL_MANAGER_INFORMATION arrived
  bool attitude_requested_ = false;  ///< SET_MESSAGE_INTERVAL accepted
  bool ready_ = false;               ///< ready() was said on this connection
  bool ever_ready_ = false;          ///< the start-up is over: refusals are goal faults from now on
  std::uint8_t holder_system_ = 0;   ///< who holds primary control, as the last status said
  std::uint8_t holder_component_ = 0;
  std::string startup_refusal_;  ///< control refused at start-up, awaiting the status that names the holder
  TimePoint refused_at_{};
  std::uint8_t sequence_ = 0;
  std::map<std::uint16_t, PendingCommand> pending_;  ///< by MAV_CMD: the last of each awaiting its ACK
  TimePoint heartbeat_at_{};
  TimePoint information_asked_at_{};
  TimePoint control_asked_at_{};
  TimePoint attitude_asked_at_{};
  Setpoint setpoint_ = Setpoint::NONE;
  AxisValues setpoint_values_{};
  TimePoint setpoint_sent_at_{};
  TimePoint stop_until_{};
};

/// A mavlink_gimbal backend: MavlinkGimbalProtocol on a DeviceSession.
std::unique_ptr<DeviceBackend> makeMavlinkGimbalBackend(
    const MavlinkGimbalConfig& config, std::shared_ptr<const Clock> clock = std::make_shared<SystemClock>());

}  // namespace ptz_action_server
