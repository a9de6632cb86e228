/**
 * \file
 * \brief A custom PanTilt implementation (the seed's last section) that drives the simulated device model.
 */
#pragma once

#include <memory>
#include <mutex>

#include "ptz_action_server/core/pantilt/pantilt_codec.h"
#include "ptz_action_server/core/sim/sim_device_model.h"

namespace cr
{
namespace pantilt
{
/**
 * \brief A pan-tilt controller whose motors are ptz_action_server's SimDeviceModel.
 *
 * Units on the PanTilt side: angles in degrees (pan -180..180, tilt -90..90, clockwise pan and upward tilt
 * positive), motor positions 0..65535 spread over the angle range, speeds in % of the model's max speed.
 * Setting PAN_ANGLE, TILT_ANGLE or the motor positions sets the target of the next GO_TO_* command; reading them
 * gives where the device is. The PAN_TILT_* params set both axes. In v1.0 and v1.1, GO_TO_* commands take their
 * targets from the command's arguments and MOVE_* take signed speeds in %. Thread-safe.
 */
class SimPanTilt : public PanTilt
{
public:
  SimPanTilt(const ptz_action_server::SimDeviceConfig& config, std::shared_ptr<const ptz_action_server::Clock> clock,
             WireFormat format = WireFormat::SEED);

  bool setParam(PanTiltParam id, float value) override;
  float getParam(PanTiltParam id) const override;
  void getParams(PanTiltParams& params) const override;
  bool executeCommand(PanTiltCommand id, float arg1 = 0.0f, float arg2 = 0.0f) override;
  bool decodeAndExecuteCommand(const std::uint8_t* data, int size) override;

  WireFormat wireFormat() const
  {
    return format_;
  }
  /// The model's state now, in the core's units (rad), for tests.
  ptz_action_server::PtzSample sample() const;
  /// Fault hooks of the model (stall, lag).
  void setFaults(const ptz_action_server::SimFaults& faults);

  /// Motor position (0..65535) of an angle (deg) on \p axis, and back.
  static int angleToMotorPosition(ptz_action_server::Axis axis, double degrees);
  static double motorPositionToAngle(ptz_action_server::Axis axis, double position);

private:
  bool setParamLocked(PanTiltParam id, float value, ptz_action_server::TimePoint now);
  void fillParams(PanTiltParams& params, ptz_action_server::TimePoint now) const;
  void goToAngles(bool pan, bool tilt, ptz_action_server::TimePoint now);
  void setSpeed(ptz_action_server::Axis axis, float percent, ptz_action_server::TimePoint now);

  const std::shared_ptr<const ptz_action_server::Clock> clock_;
  const WireFormat format_;
  mutable std::mutex mutex_;                         ///< guards everything below
  mutable ptz_action_server::SimDeviceModel model_;  ///< mutable: sampling applies lagged commands
  double target_pan_ = 0.0;                          ///< deg, for the next GO_TO_* command
  double target_tilt_ = 0.0;                         ///< deg
  float pan_speed_ = 100.0f;                         ///< %
  float tilt_speed_ = 100.0f;                        ///< %
  float custom_[3] = { 0.0f, 0.0f, 0.0f };
};

}  // namespace pantilt
}  // namespace cr
