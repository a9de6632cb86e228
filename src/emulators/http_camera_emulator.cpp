#include "ptz_action_server/emulators/http_camera_emulator.h"

#include <cmath>
#include <utility>

namespace ptz_action_server
{
HttpCameraEmulator::HttpCameraEmulator(const SimDeviceConfig& device, std::shared_ptr<const Clock> clock)
  : clock_(std::move(clock)), model_(device, clock_->now())
{
}

FieldOfViewAngles HttpCameraEmulator::defaultFieldOfView()
{
  const double horizontal = 60.0 * M_PI / 180.0;
  return { horizontal, 2.0 * std::atan(std::tan(horizontal / 2.0) * 9.0 / 16.0) };
}

void HttpCameraEmulator::centreOf(double pan, double tilt, const FieldOfViewAngles& view, double x, double y,
                                  double& new_pan, double& new_tilt)
{
  // World axes: forward at pan 0, left, up. The camera looks along f; r is its right, u its up.
  const double f[3] = { std::cos(tilt) * std::cos(pan), -std::cos(tilt) * std::sin(pan), std::sin(tilt) };
  const double r[3] = { -std::sin(pan), -std::cos(pan), 0.0 };
  const double u[3] = { -std::sin(tilt) * std::cos(pan), std::sin(tilt) * std::sin(pan), std::cos(tilt) };
  const double right = x * std::tan(view.horizontal / 2.0);
  const double up = y * std::tan(view.vertical / 2.0);
  double ray[3];
  for (int i = 0; i < 3; ++i)
  {
    ray[i] = f[i] + right * r[i] + up * u[i];
  }
  new_pan = std::atan2(-ray[1], ray[0]);
  new_tilt = std::atan2(ray[2], std::hypot(ray[0], ray[1]));
}

PtzSample HttpCameraEmulator::sample() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const TimePoint now = clock_->now();
  advance(now);
  return model_.sample(now);
}

void HttpCameraEmulator::setRefuse(bool refuse)
{
  std::lock_guard<std::mutex> lock(mutex_);
  refuse_ = refuse;
}

void HttpCameraEmulator::setFaults(const SimFaults& faults)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    model_.setFaults(faults, clock_->now());
  }
  server().setDelay(faults.reply_delay);  // a slow camera: every answer waits
}

bool HttpCameraEmulator::faultSilence(bool on)
{
  server().setSilent(on);
  return true;
}

bool HttpCameraEmulator::faultDrop(bool on)
{
  if (on)
  {
    server().dropConnections();
  }
  return true;
}

bool HttpCameraEmulator::faultEndless(bool on)
{
  server().setEndless(on);
  return true;
}

bool HttpCameraEmulator::faultModel(EmulatorFault /*fault*/, const SimFaults& faults)
{
  setFaults(faults);
  return true;
}

}  // namespace ptz_action_server
