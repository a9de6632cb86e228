#include "ptz_action_server/core/device/device_backend.h"

namespace ptz_action_server
{
DeviceBackend::DeviceBackend(const LinkConfig& link, const DeviceSessionConfig& config,
                             const ProtocolFactory& make_protocol, std::shared_ptr<const Clock> clock)
  : session_(std::make_unique<DeviceSession>(link, config, std::move(clock))), protocol_(make_protocol(*session_))
{
  session_->attach(*protocol_);
}

DeviceBackend::~DeviceBackend()
{
  session_->stop();
}

void DeviceBackend::goTo(const AxisValues& position)
{
  session_->command([this, position] { protocol_->goTo(position); });
}

void DeviceBackend::goToAtSpeed(const AxisValues& position, const AxisValues& speed)
{
  session_->command([this, position, speed] { protocol_->goToAtSpeed(position, speed); });
}

void DeviceBackend::moveAtVelocity(const AxisValues& velocity)
{
  session_->command([this, velocity] { protocol_->moveAtVelocity(velocity); });
}

void DeviceBackend::stop()
{
  session_->command([this] { protocol_->stop(); });
}

void DeviceBackend::lens(const LensCommand& command)
{
  session_->post([this, command] { protocol_->lens(command); });
}

void DeviceBackend::aimInView(const ViewTarget& target)
{
  session_->command([this, target] { protocol_->aimInView(target); });
}

void DeviceBackend::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("protocol", protocol_->name());
  values.emplace_back("device", protocol_->deviceName());
  session_->diagnostics(values);
  protocol_->diagnostics(values);
}

}  // namespace ptz_action_server
