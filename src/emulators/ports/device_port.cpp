#include "ptz_action_server/emulators/ports/device_port.h"

#include <algorithm>

#include "pty_port.h"
#include "tcp_server_port.h"
#include "udp_server_port.h"

namespace ptz_action_server
{
std::unique_ptr<DevicePort> DevicePort::create(const DevicePortConfig& config, Handlers handlers)
{
  if (config.kind == DevicePortConfig::Kind::TCP)
  {
    return std::make_unique<TcpServerPort>(config, std::move(handlers));
  }
  if (config.kind == DevicePortConfig::Kind::UDP)
  {
    return std::make_unique<UdpServerPort>(config, std::move(handlers));
  }
  return std::make_unique<PtyPort>(config, std::move(handlers));
}

void DevicePort::setGarbleRatio(double ratio)
{
  garble_ratio_ = std::clamp(ratio, 0.0, 1.0);
}

void DevicePort::garble(std::uint8_t* bytes, std::size_t size)
{
  if (endless_)
  {
    std::fill(bytes, bytes + size, endless_filler_.load());
    return;
  }
  const double ratio = garble_ratio_;
  if (ratio <= 0.0)
  {
    return;
  }
  for (std::size_t index = 0; index < size; ++index)
  {
    if (std::uniform_real_distribution<double>(0.0, 1.0)(random_) < ratio)
    {
      bytes[index] = static_cast<std::uint8_t>(random_());
      ++bytes_garbled_;
    }
  }
}

}  // namespace ptz_action_server
