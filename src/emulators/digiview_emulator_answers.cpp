#include "ptz_action_server/emulators/digiview_emulator.h"

#include <algorithm>
#include <cmath>

#include "digiview_emulator_internal.h"

namespace ptz_action_server
{
namespace
{
using namespace digiview;
using namespace digiview_views;

constexpr double ZOOM_STEP = 1.1;  ///< a relative zoom step of 1 narrows the field of view by this factor
}  // namespace

PtzSample DigiViewEmulator::view(const std::string& stream, std::uint8_t cam_id) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return models_.at(std::make_pair(stream, cam_id)).sample(SteadyClock::now());
}

SimDeviceModel* DigiViewEmulator::model(const CameraId& camera)
{
  const auto found = models_.find(std::make_pair(camera.stream_name, camera.cam_id));
  return found == models_.end() ? nullptr : &found->second;
}

bool DigiViewEmulator::current(ParamType param, const CameraId& camera, Message& message)
{
  const Wire& wire = config_.wire;
  std::lock_guard<std::mutex> lock(mutex_);
  if (param == ParamType::SYSTEM_STATUS)
  {
    const std::uint8_t status = halted_ ? APP_STATUS_HALT : runningStatus(wire.format);
    message = packSystemStatus(wire, MessageType::CURRENT_PARAMETERS, SystemStatus{ status, 0, 45.5 });
    return true;
  }
  if (param == ParamType::VIDEO_OUTPUT)
  {
    if (std::find(config_.streams.begin(), config_.streams.end(), camera.stream_name) == config_.streams.end())
    {
      return false;
    }
    VideoOutput output;  // 1920 x 1080, no detection overlay
    output.stream_name = camera.stream_name;
    output.fps = 30;
    output.layout_mode = config_.layout_mode;
    const std::vector<BoundingBox> views = viewsOf(config_.layout_mode);
    output.num_user_views = static_cast<std::uint8_t>(views.size());
    std::copy(views.begin(), views.end(), output.views.begin());
    message = packVideoOutput(wire, MessageType::CURRENT_PARAMETERS, output);
    return true;
  }
  SimDeviceModel* view = model(camera);
  if (view == nullptr)
  {
    return false;
  }
  const PtzSample state = view->sample(SteadyClock::now());
  if (param == ParamType::CAM_TARGETING)
  {
    CamTargeting targeting;
    targeting.camera = camera;
    targeting.yaw = state.position[PAN];
    targeting.pitch = state.position[TILT];
    message = packTargeting(wire, MessageType::CURRENT_PARAMETERS, targeting);
    return true;
  }
  if (param == ParamType::CAM_OPTICS_AND_CONTROL)
  {
    CamOpticsAndControl optics;
    optics.camera = camera;
    optics.fov = state.position[ZOOM];
    message = packOptics(wire, MessageType::CURRENT_PARAMETERS, optics);
    return true;
  }
  return false;
}

void DigiViewEmulator::handle(const SessionPtr& session, const std::uint8_t* bytes, std::size_t size)
{
  Message message;
  bool unverified = false;
  const UnpackError error = Message::unpack(bytes, size, config_.wire, message, &unverified);
  received_.add(ReceivedMessage{ SteadyClock::now(), error, unverified, message });
  if (silent())
  {
    return;
  }
  const Wire& wire = config_.wire;
  const Format format = wire.format;
  auto answer = [&](MessageType type, ParamType param_type) { reply(session, packBare(wire, type, param_type)); };
  ParamType about = ParamType::SYSTEM_STATUS;
  if (size <= 10 || !paramFromWire(format, bytes[10], about))
  {
    about = ParamType::SYSTEM_STATUS;
  }
  switch (error)
  {
    case UnpackError::NONE:
      break;
    case UnpackError::BAD_CHECKSUM:
      answer(MessageType::CHECKSUM_ERROR, about);
      return;
    case UnpackError::BAD_MESSAGE_TYPE:
    case UnpackError::BAD_PARAM_TYPE:
      answer(MessageType::UNKNOWN, about);
      return;
    default:
      answer(MessageType::DATA_ERROR, about);
      return;
  }

  const ParamType param = message.param_type;
  switch (message.message_type)
  {
    case MessageType::QUIT:
      closeSession(session, true);
      return;
    case MessageType::GET_PARAMETERS: {
      CameraId camera;
      if (unpackCamera(message, camera) != UnpackError::NONE)
      {
        answer(MessageType::DATA_ERROR, param);
        return;
      }
      // From 1.0 on: interval_ms subscribes (minIntervalOf() or more) or cancels (0); a GET with less is ignored, as
      // a GET_INTERVAL, or in 1.2 answered once.
      const bool too_short = message.interval_ms != 0 && message.interval_ms < minIntervalOf(format);
      if (too_short && !shortIntervalIsOneShot(format))
      {
        return;
      }
      Message state;
      if (current(param, camera, state))
      {
        reply(session, state);
        if (subscribesWithGet(format) && !too_short)
        {
          subscribe(session, IntervalRequest{ param, camera, message.interval_ms });
        }
      }
      else if (param != ParamType::VIDEO_OUTPUT && param != ParamType::CAM_TARGETING &&
               param != ParamType::CAM_OPTICS_AND_CONTROL)
      {
        answer(MessageType::UNKNOWN, param);  // a parameter the emulator does not model
      }
      return;  // an unknown stream or camera: ignored, as DigiView does
    }
    case MessageType::GET_INTERVAL: {
      IntervalRequest request;
      if (unpackInterval(message, request) != UnpackError::NONE)
      {
        answer(MessageType::DATA_ERROR, param);
        return;
      }
      subscribe(session, request);
      return;
    }
    case MessageType::SET_PARAMETERS: {
      if (refuse_)
      {
        answer(MessageType::FORBIDDEN, param);
        return;
      }
      const TimePoint now = SteadyClock::now();
      if (param == ParamType::SYSTEM_STATUS && hasAppStatus(format))
      {
        // Its documentation: a SET switches only between RUNNING and HALT.
        SystemStatus status;
        if (unpackSystemStatus(message, status) != UnpackError::NONE ||
            (status.status != APP_STATUS_RUNNING && status.status != APP_STATUS_HALT))
        {
          answer(MessageType::DATA_ERROR, param);
          return;
        }
        setHalted(status.status == APP_STATUS_HALT);
        answer(MessageType::ACKNOWLEDGEMENT, param);
        return;
      }
      if (param == ParamType::CAM_TARGETING)
      {
        CamTargeting targeting;
        if (unpackTargeting(message, targeting) != UnpackError::NONE)
        {
          answer(MessageType::DATA_ERROR, param);
          return;
        }
        std::unique_lock<std::mutex> lock(mutex_);
        SimDeviceModel* view = model(targeting.camera);
        if (view == nullptr)
        {
          return;  // unknown view: ignored
        }
        if (targeting.targeting_mode == 0 && !halted_)
        {
          const PtzSample state = view->sample(now);
          const double yaw = targeting.euler_delta ? state.position[PAN] + targeting.yaw : targeting.yaw;
          const double pitch = targeting.euler_delta ? state.position[TILT] + targeting.pitch : targeting.pitch;
          view->goToAxis(PAN, std::remainder(yaw, 2.0 * M_PI), now);
          view->goToAxis(TILT, pitch, now);
        }
        lock.unlock();
        answer(MessageType::ACKNOWLEDGEMENT, param);
        return;
      }
      if (param == ParamType::CAM_OPTICS_AND_CONTROL)
      {
        CamOpticsAndControl optics;
        if (unpackOptics(message, optics) != UnpackError::NONE)
        {
          answer(MessageType::DATA_ERROR, param);
          return;
        }
        std::unique_lock<std::mutex> lock(mutex_);
        SimDeviceModel* view = model(optics.camera);
        if (view == nullptr)
        {
          return;
        }
        double fov = optics.fov;
        if (optics.zoom != 0)
        {
          fov = view->sample(now).position[ZOOM] / std::pow(ZOOM_STEP, optics.zoom);
        }
        if (fov >= NARROWEST_FOV && fov <= WIDEST_FOV && !halted_)  // outside: ignored, as DigiView does
        {
          view->goToAxis(ZOOM, fov, now);
        }
        lock.unlock();
        answer(MessageType::ACKNOWLEDGEMENT, param);
        return;
      }
      answer(MessageType::UNKNOWN, param);
      return;
    }
    default:
      answer(MessageType::UNKNOWN, param);
      return;
  }
}

}  // namespace ptz_action_server
