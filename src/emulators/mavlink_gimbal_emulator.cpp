#include "ptz_action_server/emulators/mavlink_gimbal_emulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "mavlink_gimbal_emulator_internal.h"

namespace ptz_action_server
{
using namespace mavlink_emulator;

SimDeviceConfig defaultMavlinkGimbalDevice()
{
  SimDeviceConfig device = SimDeviceConfig::defaults();
  device.axes[TILT].range = AxisRange{ -M_PI / 2.0, M_PI / 4.0 };
  device.axes[TILT].resolution = 0.0;
  device.axes[PAN].resolution = 0.0;
  device.axes[ZOOM].present = false;
  device.axes[ZOOM].range = AxisRange{ 1.0, 1.0 };
  return device;
}

MavlinkGimbalEmulator::MavlinkGimbalEmulator(const MavlinkGimbalEmulatorConfig& config,
                                             std::shared_ptr<const Clock> clock)
  : config_(config), clock_(std::move(clock))
{
  if (config_.gimbals.empty())
  {
    throw std::invalid_argument("a MAVLink gimbal emulator needs at least one gimbal");
  }
  const TimePoint now = clock_->now();
  for (const MavlinkEmulatedGimbal& gimbal : config_.gimbals)
  {
    const std::uint8_t manager = gimbal.manager_component != 0 ? gimbal.manager_component : config_.component_id;
    const std::string name = "gimbal_device_id " + std::to_string(gimbal.device_id);
    if (manager == 0)
    {
      throw std::invalid_argument(name + ": its manager needs a component id (1..255)");
    }
    if (gimbal.device_id == 0)
    {
      throw std::invalid_argument("gimbal_device_id 0 means \"every gimbal\" in commands: a gimbal's id is 1..6 "
                                  "(inside "
                                  "its manager's component) or its own component id");
    }
    if (!isInternalGimbalId(gimbal.device_id) && gimbal.device_id == manager)
    {
      throw std::invalid_argument(name + " is its manager's own component: a gimbal inside its manager's component "
                                         "takes a gimbal_device_id 1..6 (a gimbal device of its own, another "
                                         "component id)");
    }
    for (const auto& other : gimbals_)
    {
      if (other->manager == manager && other->device_id == gimbal.device_id)
      {
        throw std::invalid_argument(name + " twice in the gimbal manager at component " + std::to_string(manager));
      }
      if (other->separate() && other->device_id == gimbal.device_id)
      {
        throw std::invalid_argument(name + ": the gimbal device at component " + std::to_string(gimbal.device_id) +
                                    " is there already");
      }
    }
    gimbals_.push_back(std::make_unique<Gimbal>(gimbal, manager, config_.attitude_interval, now));
    counters_.executed_per_gimbal.push_back(0);
  }
  for (const auto& gimbal : gimbals_)
  {
    if (std::find(components_.begin(), components_.end(), gimbal->manager) == components_.end())
    {
      components_.push_back(gimbal->manager);
    }
  }
  for (const auto& gimbal : gimbals_)
  {
    if (gimbal->separate())
    {
      if (std::find(components_.begin(), components_.end(), gimbal->device_id) != components_.end())
      {
        throw std::invalid_argument("component " + std::to_string(gimbal->device_id) +
                                    " cannot be a gimbal manager and a gimbal device beside it");
      }
      components_.push_back(gimbal->device_id);
    }
  }

  DevicePortConfig port = config_.line;
  if (config_.transport == LinkKind::UDP)
  {
    port.kind = DevicePortConfig::Kind::UDP;
    port.host = config_.host;
    port.port = config_.port;
  }
  port.tick_period = 0.01;
  DevicePort::Handlers handlers;
  handlers.on_bytes = [this](const std::uint8_t* data, std::size_t size, TimePoint) { receive(data, size); };
  handlers.on_tick = [this] { tick(); };
  port_ = DevicePort::create(port, handlers);
  port_->start();
}

MavlinkGimbalEmulator::~MavlinkGimbalEmulator()
{
  destroyPort(port_);  // first: its thread calls back into this
}

std::string MavlinkGimbalEmulator::address() const
{
  return port_->path();
}

std::uint16_t MavlinkGimbalEmulator::udpPort() const
{
  return port_->udpPort();
}

std::string MavlinkGimbalEmulator::path() const
{
  return config_.transport == LinkKind::UDP ? std::string() : port_->path();
}

MavlinkGimbalEmulator::Gimbal& MavlinkGimbalEmulator::at(std::size_t index) const
{
  if (index >= gimbals_.size())
  {
    throw std::out_of_range("the emulator has " + std::to_string(gimbals_.size()) + " gimbals, not " +
                            std::to_string(index + 1));
  }
  return *gimbals_[index];
}

void MavlinkGimbalEmulator::setSilent(bool silent)
{
  PushEmulatorFaults::setSilent(silent);
  port_->setSilent(silent);  // udp: datagrams go unread, so the sender does not become the peer
}

void MavlinkGimbalEmulator::setEndless(bool endless)
{
  port_->setEndless(endless);
}

void MavlinkGimbalEmulator::setRefuse(bool refuse)
{
  refuse_ = refuse;
}

void MavlinkGimbalEmulator::setFaults(const SimFaults& faults, std::size_t gimbal)
{
  std::lock_guard<std::mutex> lock(mutex_);
  at(gimbal).model.setFaults(faults, clock_->now());
}

void MavlinkGimbalEmulator::setModelFaults(const SimFaults& faults)
{
  setFaults(faults);
}

void MavlinkGimbalEmulator::giveControlTo(std::uint8_t system_id, std::uint8_t component_id, bool keep,
                                          std::size_t gimbal)
{
  std::lock_guard<std::mutex> lock(mutex_);
  Gimbal& taken = at(gimbal);
  taken.primary_system = system_id;
  taken.primary_component = component_id;
  taken.control_kept = keep;
  sendStatus(taken);
}

void MavlinkGimbalEmulator::releaseControl(std::size_t gimbal)
{
  std::lock_guard<std::mutex> lock(mutex_);
  Gimbal& released = at(gimbal);
  released.primary_system = released.primary_component = 0;
  released.control_kept = false;
  sendStatus(released);
}

void MavlinkGimbalEmulator::unplug()
{
  if (config_.transport != LinkKind::UDP)
  {
    port_->unplug();
  }
}

void MavlinkGimbalEmulator::replug()
{
  if (config_.transport != LinkKind::UDP)
  {
    port_->replug();
  }
}

std::pair<std::uint8_t, std::uint8_t> MavlinkGimbalEmulator::primaryController(std::size_t gimbal) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const Gimbal& asked = at(gimbal);
  return { asked.primary_system, asked.primary_component };
}

PtzSample MavlinkGimbalEmulator::gimbal(std::size_t gimbal) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return at(gimbal).model.sample(clock_->now());
}

MavlinkGimbalEmulatorCounters MavlinkGimbalEmulator::counters() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  MavlinkGimbalEmulatorCounters counters = counters_;
  counters.dropped = parser_.counts().errors;
  return counters;
}

// ---------------------------------------------------------------- transports

void MavlinkGimbalEmulator::receive(const std::uint8_t* data, std::size_t size)
{
  if (silent())
  {
    return;
  }
  const TimePoint now = clock_->now();
  std::lock_guard<std::mutex> lock(mutex_);
  parser_.feed(data, size, [&](const Frame& frame) {
    received_.add(ReceivedMavlinkFrame{ now, frame });
    handle(frame, now);
  });
}

// ---------------------------------------------------------------- what the components receive

bool MavlinkGimbalEmulator::fromPrimary(const Gimbal& gimbal, const Frame& frame) const
{
  return frame.header.system_id == gimbal.primary_system && frame.header.component_id == gimbal.primary_component;
}

std::vector<MavlinkGimbalEmulator::Gimbal*> MavlinkGimbalEmulator::addressed(std::uint8_t component,
                                                                             std::uint8_t gimbal_device_id)
{
  std::vector<Gimbal*> found;
  for (const auto& gimbal : gimbals_)
  {
    if (gimbal->manager == component && (gimbal_device_id == 0 || gimbal->device_id == gimbal_device_id))
    {
      found.push_back(gimbal.get());
    }
  }
  return found;
}

void MavlinkGimbalEmulator::handle(const Frame& frame, TimePoint now)
{
  switch (frame.message_id)
  {
    case message_id::COMMAND_LONG: {
      const CommandLong command = decode<CommandLong>(frame);
      if (command.target_system != config_.system_id && command.target_system != 0)
      {
        return;
      }
      for (std::uint8_t component : components_)
      {
        if (command.target_component == component || command.target_component == 0)
        {
          handleCommand(component, frame, command, now);
        }
      }
      return;
    }
    case message_id::GIMBAL_MANAGER_SET_PITCHYAW: {
      const GimbalManagerSetPitchYaw message = decode<GimbalManagerSetPitchYaw>(frame);
      if (message.target_system == config_.system_id)
      {
        for (Gimbal* gimbal : addressed(message.target_component, message.gimbal_device_id))
        {
          setpoint(*gimbal, frame, message.flags, message.pitch, message.yaw, message.pitch_rate, message.yaw_rate,
                   now);
        }
      }
      return;
    }
    case message_id::GIMBAL_MANAGER_SET_ATTITUDE: {
      const GimbalManagerSetAttitude message = decode<GimbalManagerSetAttitude>(frame);
      if (message.target_system != config_.system_id)
      {
        return;
      }
      // The quaternion, all NaN when only rates are set; x (roll) is not modelled: a two-axis gimbal.
      float pitch = UNSET, yaw = UNSET;
      if (std::all_of(message.q.begin(), message.q.end(), [](float value) { return std::isfinite(value); }))
      {
        const PanTilt angles = panTiltFromQuaternion(message.q);
        pitch = static_cast<float>(angles.tilt);
        yaw = static_cast<float>(angles.pan);
      }
      for (Gimbal* gimbal : addressed(message.target_component, message.gimbal_device_id))
      {
        setpoint(*gimbal, frame, message.flags, pitch, yaw, message.angular_velocity_y, message.angular_velocity_z,
                 now);
      }
      return;
    }
    default:
      return;
  }
}

}  // namespace ptz_action_server
