#include "ptz_action_server/core/mounted_backend.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
MountedBackend::MountedBackend(std::shared_ptr<PtzBackend> device, const MountConfig& mount)
  : ForwardingBackend(std::move(device)), mount_(mount), sign_(mount.inverted ? -1.0 : 1.0)
{
  if (!std::isfinite(mount_.pan_offset))
  {
    throw ConfigError("the mount's pan offset must be a finite number of radians");
  }
}

Capabilities MountedBackend::capabilities() const
{
  return contractLimits(inner().capabilities(), mount_);
}

void MountedBackend::goTo(const AxisValues& position)
{
  inner().goTo(toDevice(position));
}

void MountedBackend::goToAtSpeed(const AxisValues& position, const AxisValues& speed)
{
  inner().goToAtSpeed(toDevice(position), speed);  // speeds are magnitudes: the mount leaves them as they are
}

void MountedBackend::moveAtVelocity(const AxisValues& velocity)
{
  inner().moveAtVelocity(mapVelocity(velocity));
}

PtzSample MountedBackend::sample() const
{
  PtzSample sample = inner().sample();
  sample.position = toContract(sample.position);
  sample.velocity = mapVelocity(sample.velocity);
  return sample;
}

void MountedBackend::diagnostics(std::vector<DiagnosticValue>& values) const
{
  inner().diagnostics(values);
  values.emplace_back("mount", mountName(mount_));
  values.emplace_back("mount pan offset (rad)", formatText("%.4f", mount_.pan_offset));
  // The device's own angles, so a user can compare them with its display (and tests can see the mapping).
  const PtzSample sample = inner().sample();
  values.emplace_back("device pan (rad)", formatText("%.4f", sample.position[PAN]));
  values.emplace_back("device tilt (rad)", formatText("%.4f", sample.position[TILT]));
}

AxisValues MountedBackend::toContract(const AxisValues& device_position) const
{
  AxisValues contract = device_position;
  contract[PAN] = sign_ * device_position[PAN] + mount_.pan_offset;
  contract[TILT] = sign_ * device_position[TILT];
  return contract;
}

AxisValues MountedBackend::toDevice(const AxisValues& contract_position) const
{
  AxisValues device = contract_position;
  device[PAN] = sign_ * (contract_position[PAN] - mount_.pan_offset);
  device[TILT] = sign_ * contract_position[TILT];
  return device;
}

AxisValues MountedBackend::mapVelocity(const AxisValues& velocity) const
{
  AxisValues mapped = velocity;
  mapped[PAN] = sign_ * velocity[PAN];
  mapped[TILT] = sign_ * velocity[TILT];
  return mapped;
}

namespace
{
/// Maps the pan and tilt ranges of \p limits through value -> scale * (value + shift_before) + shift_after on pan
/// (tilt: scale only); an inverted scale swaps the ends.
Capabilities mapRanges(Capabilities limits, double scale, double pan_shift_before, double pan_shift_after)
{
  for (Axis axis : { PAN, TILT })
  {
    AxisRange& range = limits.axes[axis].range;
    const double before = axis == PAN ? pan_shift_before : 0.0;
    const double after = axis == PAN ? pan_shift_after : 0.0;
    const double first = scale * (range.min + before) + after;
    const double second = scale * (range.max + before) + after;
    range = AxisRange{ std::min(first, second), std::max(first, second) };
  }
  return limits;
}
}  // namespace

Capabilities contractLimits(const Capabilities& device, const MountConfig& mount)
{
  return mapRanges(device, mount.inverted ? -1.0 : 1.0, 0.0, mount.pan_offset);
}

Capabilities deviceLimits(const Capabilities& contract, const MountConfig& mount)
{
  return mapRanges(contract, mount.inverted ? -1.0 : 1.0, -mount.pan_offset, 0.0);
}

std::shared_ptr<PtzBackend> applyMount(std::shared_ptr<PtzBackend> device, const MountConfig& mount)
{
  if (mount.identity())
  {
    return device;
  }
  return std::make_shared<MountedBackend>(std::move(device), mount);
}

const char* mountName(const MountConfig& mount)
{
  return mount.inverted ? "inverted" : "upright";
}

}  // namespace ptz_action_server
