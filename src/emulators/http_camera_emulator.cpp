#include "ptz_action_server/emulators/http_camera_emulator.h"

#include <utility>

namespace ptz_action_server
{
HttpCameraEmulator::HttpCameraEmulator(const SimDeviceConfig& device, std::shared_ptr<const Clock> clock)
  : clock_(std::move(clock)), model_(device, clock_->now())
{
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
