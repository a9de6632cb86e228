/**
 * \file
 * \brief How the device is mounted (upright or inverted, pan zero offset), applied in one place: a backend decorator.
 */
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "ptz_action_server/core/forwarding_backend.h"

namespace ptz_action_server
{
/// How the device sits on the robot, relative to the URDF's ptz_base_link (which stays upright, z up).
struct MountConfig
{
  bool inverted = false;    ///< true: the device hangs upside down (a ceiling dome)
  double pan_offset = 0.0;  ///< rad: the contract's pan where the device reads pan 0

  /// Upright without offset: device angles are the contract's, and no wrapper is needed.
  bool identity() const
  {
    return !inverted && pan_offset == 0.0;
  }
};

/**
 * \brief A PtzBackend seen through its mount: the one place device angles become the contract's and back.
 *
 * With s = +1 upright and -1 inverted:
 *   contract_pan = s * device_pan + pan_offset, contract_tilt = s * device_tilt, velocities times s, zoom untouched.
 * Goals go the other way (device_pan = s * (contract_pan - pan_offset)). capabilities() reports the device's ranges in
 * contract angles (an inverted range swaps and negates its ends; the offset shifts pan), so the node's limits, goals,
 * state, joint_states and tf all speak the contract. Pan does not wrap: the part of the device's range the offset
 * pushes beyond the contract's [-pi, pi] is not used (the node's URDF intersection cuts it and warns).
 *
 * Thread-safe as the wrapped backend is: the mapping is immutable.
 */
class MountedBackend : public ForwardingBackend
{
public:
  /// Owns \p device. Throws ConfigError if it is null or the offset is not finite.
  MountedBackend(std::shared_ptr<PtzBackend> device, const MountConfig& mount);

  Capabilities capabilities() const override;
  void goTo(const AxisValues& position) override;
  void goToAtSpeed(const AxisValues& position, const AxisValues& speed) override;
  void moveAtVelocity(const AxisValues& velocity) override;
  PtzSample sample() const override;
  /// The device's, then the mount and the device's own pan and tilt (as it reads them).
  void diagnostics(std::vector<DiagnosticValue>& values) const override;

  /// Device position -> contract position (pan, tilt in rad; zoom unchanged).
  AxisValues toContract(const AxisValues& device_position) const;
  /// Contract position -> device position; the inverse of toContract().
  AxisValues toDevice(const AxisValues& contract_position) const;
  /// A velocity from device to contract axes, or back: the mapping is its own inverse (zoom unchanged).
  AxisValues mapVelocity(const AxisValues& velocity) const;

  const MountConfig& mount() const
  {
    return mount_;
  }

private:
  const MountConfig mount_;
  const double sign_;  ///< +1 upright, -1 inverted
};

/// Device limits in contract angles: an inverted range swaps and negates its ends, the offset shifts pan.
Capabilities contractLimits(const Capabilities& device, const MountConfig& mount);
/// The inverse of contractLimits(): contract limits (e.g. the URDF's) in the device's own angles.
Capabilities deviceLimits(const Capabilities& contract, const MountConfig& mount);

/// \p device itself for an identity mount, else \p device wrapped in a MountedBackend.
std::shared_ptr<PtzBackend> applyMount(std::shared_ptr<PtzBackend> device, const MountConfig& mount);

/// "upright" or "inverted".
const char* mountName(const MountConfig& mount);

}  // namespace ptz_action_server
