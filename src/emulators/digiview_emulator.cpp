#include "ptz_action_server/emulators/digiview_emulator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

#include "digiview_emulator_internal.h"

namespace ptz_action_server
{
namespace
{
using namespace digiview;
using namespace digiview_views;

SimDeviceConfig viewModel(const DigiViewEmulatorConfig& config)
{
  SimDeviceConfig model = SimDeviceConfig::defaults();
  model.axes[PAN] = SimAxisConfig{ true, { -M_PI, M_PI }, { config.slew_rate, config.acceleration, 0.0 }, 0.0, 0.0 };
  model.axes[TILT] =
      SimAxisConfig{ true, { -M_PI / 2.0, M_PI / 2.0 }, { config.slew_rate, config.acceleration, 0.0 }, 0.0, 0.0 };
  // The zoom slot holds the field of view, changing at a constant rate.
  model.axes[ZOOM] = SimAxisConfig{
    true, { NARROWEST_FOV, WIDEST_FOV }, { config.fov_rate, 1000.0, config.fov_rate }, 0.0, config.initial_fov
  };
  return model;
}
}  // namespace

DigiViewEmulator::DigiViewEmulator(const DigiViewEmulatorConfig& config) : config_(config)
{
  const SimDeviceConfig model = viewModel(config);
  for (const std::string& stream : config.streams)
  {
    for (std::size_t cam = 0; cam < viewsOf(config.layout_mode).size(); ++cam)
    {
      models_.emplace(std::make_pair(stream, static_cast<std::uint8_t>(cam)),
                      SimDeviceModel(model, SteadyClock::now()));
    }
  }
  DevicePortConfig port;
  port.kind = config.transport == LinkKind::TCP ? DevicePortConfig::Kind::TCP : DevicePortConfig::Kind::UDP;
  port.host = config.host;
  port.port = config.port;
  port.many_clients = true;  // DigiView serves every client at once
  port.tick_period = 0.01;   // the subscriptions' clock (100 ms at the least)
  DevicePort::Handlers handlers;
  handlers.on_bytes = [this](const std::uint8_t* data, std::size_t size, TimePoint) { received(data, size); };
  handlers.on_connect = [this] { session(); };
  handlers.on_disconnect = [this] {
    const auto found = sessions_.find(port_->sender());
    if (found != sessions_.end())
    {
      closeSession(found->second, false);
    }
  };
  handlers.on_tick = [this] { tick(); };
  port_ = DevicePort::create(port, handlers);
  port_->start();
}

DigiViewEmulator::~DigiViewEmulator()
{
  destroyPort(port_);  // first: its thread calls back into this
}

std::uint16_t DigiViewEmulator::port() const
{
  return config_.transport == LinkKind::TCP ? port_->tcpPort() : port_->udpPort();
}

void DigiViewEmulator::setEndless(bool endless)
{
  endless_ = endless;
}

void DigiViewEmulator::setRefuse(bool refuse)
{
  refuse_ = refuse;
}

void DigiViewEmulator::setHalted(bool halted)
{
  if (!hasAppStatus(config_.wire.format))
  {
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  halted_ = halted;
  if (halted)
  {
    for (auto& view : models_)
    {
      view.second.stop(SteadyClock::now());
    }
  }
}

void DigiViewEmulator::setFaults(const SimFaults& faults)
{
  std::lock_guard<std::mutex> lock(mutex_);
  for (auto& view : models_)
  {
    view.second.setFaults(faults, SteadyClock::now());
  }
}

void DigiViewEmulator::dropConnections()
{
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& entry : sessions_)
  {
    if (!entry.second->is_udp)
    {
      port_->disconnect(entry.first);  // its session closes when the port says it did
    }
  }
}

bool DigiViewEmulator::faultDrop(bool on)
{
  if (on)
  {
    dropConnections();
  }
  return true;
}

void DigiViewEmulator::setModelFaults(const SimFaults& faults)
{
  setFaults(faults);
}

std::size_t DigiViewEmulator::connections() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return sessions_.size();
}

DigiViewEmulator::SessionPtr DigiViewEmulator::session()
{
  const std::string peer = port_->sender();
  const auto found = sessions_.find(peer);
  if (found != sessions_.end())
  {
    return found->second;
  }
  auto created = std::make_shared<Session>();
  created->peer = peer;
  created->is_udp = config_.transport != LinkKind::TCP;
  std::lock_guard<std::mutex> lock(mutex_);
  sessions_.emplace(peer, created);
  return created;
}

void DigiViewEmulator::received(const std::uint8_t* bytes, std::size_t size)
{
  const SessionPtr client = session();
  if (client->is_udp)
  {
    handle(client, bytes, size);  // a datagram: one message
    return;
  }
  // A stream: cut into messages of the format's size.
  const std::size_t message_size = layoutOf(config_.wire.format).size;
  std::vector<std::uint8_t>& buffered = client->buffered;
  buffered.insert(buffered.end(), bytes, bytes + size);
  std::size_t offset = 0;
  while (client->open && buffered.size() - offset >= message_size)
  {
    handle(client, buffered.data() + offset, message_size);
    offset += message_size;
  }
  buffered.erase(buffered.begin(), buffered.begin() + static_cast<std::ptrdiff_t>(offset));
}

void DigiViewEmulator::closeSession(const SessionPtr& session, bool disconnect)
{
  if (!session->open)
  {
    return;
  }
  session->open = false;
  session->subscriptions.clear();
  if (disconnect && !session->is_udp)
  {
    port_->disconnect(session->peer);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  const auto found = sessions_.find(session->peer);
  if (found != sessions_.end() && found->second == session)
  {
    sessions_.erase(found);
  }
}

void DigiViewEmulator::reply(const SessionPtr& session, const Message& message)
{
  if (silent() || !session->open)
  {
    return;
  }
  Message stamped = message;
  stamped.timestamp = static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
  Bytes bytes = stamped.pack();
  if (!config_.fill_checksum)
  {
    bytes[layoutOf(stamped.format).checksum_offset] = 0;
  }
  if (endless_)
  {
    bytes.assign(bytes.size() - 1, 'A');
  }
  port_->sendTo(session->peer, bytes.data(), bytes.size());
}

void DigiViewEmulator::subscribe(const SessionPtr& session, const IntervalRequest& request)
{
  const auto key = std::make_tuple(static_cast<int>(request.param), request.camera.stream_name, request.camera.cam_id);
  if (request.interval_ms == 0)
  {
    session->subscriptions.erase(key);
    return;
  }
  if (request.interval_ms < minIntervalOf(config_.wire.format))
  {
    return;  // below DigiView's minimum: no subscription
  }
  Subscription& subscription = session->subscriptions[key];
  subscription.request = request;
  subscription.due = SteadyClock::now() + std::chrono::milliseconds(request.interval_ms);
}

void DigiViewEmulator::tick()
{
  const TimePoint now = SteadyClock::now();
  for (const auto& entry : sessions_)  // only this thread changes the map
  {
    for (auto& keyed : entry.second->subscriptions)
    {
      Subscription& subscription = keyed.second;
      if (now < subscription.due)
      {
        continue;
      }
      Message message;
      if (current(subscription.request.param, subscription.request.camera, message))
      {
        for (unsigned copy = 0; copy < floodCopies(); ++copy)
        {
          reply(entry.second, message);
        }
      }
      // On the subscription's beat: a late report shortens the next interval, the schedule does not drift.
      subscription.due += std::chrono::milliseconds(subscription.request.interval_ms);
    }
  }
}

}  // namespace ptz_action_server
