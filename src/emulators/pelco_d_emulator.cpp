#include "ptz_action_server/emulators/pelco_d_emulator.h"

#include <algorithm>
#include <cmath>
#include <mutex>
#include <utility>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
/// The motion model: the pan may turn at the turbo speed too.
SimDeviceConfig modelConfig(const PelcoDEmulatorConfig& config)
{
  SimDeviceConfig model = config.device;
  model.axes[PAN].motion.max_speed = std::max(model.axes[PAN].motion.max_speed, config.pan_turbo_speed);
  return model;
}
}  // namespace

bool PelcoDEmulatorConfig::applyMode(const std::string& mode)
{
  if (mode != "standard" && mode != "no-set-position")
  {
    return false;
  }
  set_position = mode == "standard";
  return true;
}

PelcoDEmulator::PelcoDEmulator(const PelcoDEmulatorConfig& config)
  : LineEmulator(modelConfig(config))
  , config_(config)
  , parser_(config.address, false)
  , lens_(config.lens, SteadyClock::now())
{
  openPort(
      config.port,
      DevicePort::Handlers{
          [this](const std::uint8_t* data, std::size_t size, TimePoint at) { onBytes(data, size, at); }, {}, {}, {} });
}

PelcoDEmulator::~PelcoDEmulator()
{
  closePort();
}

void PelcoDEmulator::powerUp()
{
  parser_.reset();
}

pelco::ParserCounters PelcoDEmulator::parserCounters() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return parser_.counters();
}

void PelcoDEmulator::onBytes(const std::uint8_t* data, std::size_t size, TimePoint arrived_at)
{
  std::vector<std::uint8_t> replies;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    std::vector<pelco::FrameParser::Event> events;
    const double byte_time = port_->byteTime();
    // Byte by byte, so each frame is stamped with the moment its own last byte crossed the line.
    for (std::size_t index = 0; index < size; ++index)
    {
      events.clear();
      parser_.feed(data + index, 1, events);
      const TimePoint at = addSeconds(arrived_at, -(static_cast<double>(size - 1 - index) * byte_time));
      for (const pelco::FrameParser::Event& event : events)
      {
        received_.add(ReceivedFrame{ at, event.frame });
        const std::vector<std::uint8_t> reply = execute(event.frame, at);
        replies.insert(replies.end(), reply.begin(), reply.end());
      }
    }
  }
  if (!replies.empty())
  {
    port_->send(replies.data(), replies.size());
  }
}

std::vector<std::uint8_t> PelcoDEmulator::execute(const pelco::Frame& frame, TimePoint at)
{
  const std::uint8_t address = config_.address;
  auto answer = [](const pelco::Frame& reply) {
    const pelco::Bytes bytes = pelco::encode(reply);
    return std::vector<std::uint8_t>(bytes.begin(), bytes.end());
  };
  const PtzSample now = model_.sample(at);
  const AxisRange& zoom = config_.device.axes[ZOOM].range;
  const auto acknowledge = [&config = config_, address]() -> std::vector<std::uint8_t> {
    if (!config.general_reply)
    {
      return {};
    }
    const std::uint8_t alarm = 0;
    return { pelco::SYNC, address, alarm, static_cast<std::uint8_t>(address + alarm) };
  };
  const bool set_position =
      frame.command2 == pelco::SET_PAN || frame.command2 == pelco::SET_TILT || frame.command2 == pelco::SET_ZOOM;
  if (set_position && !config_.set_position)
  {
    return acknowledge();  // a camera without set-position: ignored like any command it does not know
  }
  switch (frame.command2)
  {
    case pelco::QUERY_PAN:
      return answer(pelco::withValue(address, pelco::PAN_REPLY, pelco::encodePan(toDegrees(now.position[PAN]))));
    case pelco::QUERY_TILT:
      return answer(pelco::withValue(address, pelco::TILT_REPLY,
                                     pelco::encodeTilt(toDegrees(now.position[TILT]), config_.tilt_encoding)));
    case pelco::QUERY_ZOOM: {
      const double share = zoom.max > zoom.min ? (now.position[ZOOM] - zoom.min) / (zoom.max - zoom.min) : 0.0;
      return answer(pelco::withValue(address, pelco::ZOOM_REPLY,
                                     static_cast<std::uint16_t>(std::lround(share * config_.zoom_position_max))));
    }
    case pelco::SET_PAN:
      model_.goToAxis(PAN, toRadians(pelco::decodePan(frame.value())), at);
      break;
    case pelco::SET_TILT:
      model_.goToAxis(TILT, toRadians(pelco::decodeTilt(frame.value(), config_.tilt_encoding)), at);
      break;
    case pelco::SET_ZOOM:
      model_.goToAxis(
          ZOOM, zoom.min + std::min(1.0, double(frame.value()) / config_.zoom_position_max) * (zoom.max - zoom.min),
          at);
      break;
    case pelco::SET_PRESET:
      presets_[frame.data2] = now.position;
      break;
    case pelco::CLEAR_PRESET:
      presets_.erase(frame.data2);
      break;
    case pelco::GO_TO_PRESET: {
      const auto preset = presets_.find(frame.data2);
      if (preset != presets_.end())
      {
        model_.goTo(preset->second, at);
      }
      break;
    }
    default: {
      if (frame.command2 & 0x01)
      {
        break;  // another extended command: not modelled
      }
      // The standard movement command (all zero: stop). Speeds 0..0x3F scale the speed at 0x3F; a pan byte above it
      // is turbo.
      const auto speed = [](std::uint8_t value, double max_speed) {
        return std::min(1.0, value / static_cast<double>(pelco::MAX_SPEED)) * max_speed;
      };
      const double pan_speed = frame.data1 > pelco::MAX_SPEED && config_.pan_turbo_speed > 0.0 ?
                                   config_.pan_turbo_speed :
                                   speed(frame.data1, config_.device.axes[PAN].motion.max_speed);
      const double tilt_speed = speed(frame.data2, config_.device.axes[TILT].motion.max_speed);
      const double zoom_rate = config_.device.axes[ZOOM].motion.max_speed;
      const std::uint8_t bits = frame.command2;
      driveLens(frame, at);
      const std::uint8_t lens_bits = frame.command1 & (pelco::FOCUS_NEAR | pelco::IRIS_OPEN | pelco::IRIS_CLOSE);
      if ((bits & ~pelco::FOCUS_FAR) == 0 && frame.data1 == 0 && frame.data2 == 0 &&
          (lens_bits != 0 || (bits & pelco::FOCUS_FAR) != 0))
      {
        break;  // the lens bits alone: the pan, tilt and zoom go on as they were (a set-position goes on)
      }
      model_.moveAxisAtVelocity(PAN, bits & pelco::RIGHT ? pan_speed : (bits & pelco::LEFT ? -pan_speed : 0.0), at);
      model_.moveAxisAtVelocity(TILT, bits & pelco::UP ? tilt_speed : (bits & pelco::DOWN ? -tilt_speed : 0.0), at);
      model_.moveAxisAtVelocity(ZOOM,
                                bits & pelco::ZOOM_TELE ? zoom_rate : (bits & pelco::ZOOM_WIDE ? -zoom_rate : 0.0), at);
      break;
    }
  }
  return acknowledge();
}

void PelcoDEmulator::driveLens(const pelco::Frame& frame, TimePoint at)
{
  const int focus = frame.command2 & pelco::FOCUS_FAR ? 1 : (frame.command1 & pelco::FOCUS_NEAR ? -1 : 0);
  const int iris = frame.command1 & pelco::IRIS_OPEN ? 1 : (frame.command1 & pelco::IRIS_CLOSE ? -1 : 0);
  for (const auto& [function, drive] : { std::pair<LensFunction, int>{ LensFunction::FOCUS, focus },
                                         std::pair<LensFunction, int>{ LensFunction::IRIS, iris } })
  {
    if (!lens_.present(function))
    {
      continue;  // a camera without it ignores the bit
    }
    if (drive != 0)
    {
      lens_.setAuto(function, false, at);  // driven by hand: out of auto, as such cameras do
      lens_.drive(function, drive, at);
    }
    else if (!lens_.isAuto(function))
    {
      lens_.drive(function, 0.0, at);
    }
  }
}

LensState PelcoDEmulator::lensState() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return lensStateOf(lens_, SteadyClock::now());
}

}  // namespace ptz_action_server
