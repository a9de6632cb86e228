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

std::uint8_t DigiViewEmulator::numUserViews() const
{
  return viewsOf(config_.layout_mode);
}

SimDeviceModel* DigiViewEmulator::model(const CameraId& camera)
{
  const auto found = models_.find(std::make_pair(camera.stream_name, camera.cam_id));
  return found == models_.end() ? nullptr : &found->second;
}

bool DigiViewEmulator::current(ParamType param, const CameraId& camera, Message& message)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (param == ParamType::SYSTEM_STATUS)
  {
    message = packSystemStatus(MessageType::CURRENT_PARAMETERS, SystemStatus{ 1, 0, 45.0f });
    return true;
  }
  if (param == ParamType::VIDEO_OUTPUT)
  {
    if (std::find(config_.streams.begin(), config_.streams.end(), camera.stream_name) == config_.streams.end())
    {
      return false;
    }
    VideoOutput output;
    output.stream_name = camera.stream_name;
    output.layout_mode = config_.layout_mode;
    output.num_user_views = numUserViews();
    for (std::size_t index = 0; index < output.views.size(); ++index)
    {
      output.views[index] = BoundingBox{ static_cast<std::uint16_t>(960 * (index % 2)),
                                         static_cast<std::uint16_t>(540 * (index / 2)), 960, 540 };
    }
    message = packVideoOutput(MessageType::CURRENT_PARAMETERS, output);
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
    message = packTargeting(MessageType::CURRENT_PARAMETERS, targeting);
    return true;
  }
  if (param == ParamType::CAM_OPTICS_AND_CONTROL)
  {
    CamOpticsAndControl optics;
    optics.camera = camera;
    optics.fov = state.position[ZOOM];
    message = packOptics(MessageType::CURRENT_PARAMETERS, optics);
    return true;
  }
  return false;
}

void DigiViewEmulator::handle(const SessionPtr& session, const std::uint8_t* bytes, std::size_t size)
{
  Message message;
  const UnpackError error = Message::unpack(bytes, size, message);
  received_.add(ReceivedMessage{ SteadyClock::now(), error, message });
  if (silent_)
  {
    return;
  }
  const ParamType about =
      size > 10 && isParamType(bytes[10]) ? static_cast<ParamType>(bytes[10]) : ParamType::SYSTEM_STATUS;
  switch (error)
  {
    case UnpackError::NONE:
      break;
    case UnpackError::BAD_CHECKSUM:
      reply(session, packBare(MessageType::CHECKSUM_ERROR, about));
      return;
    case UnpackError::BAD_MESSAGE_TYPE:
    case UnpackError::BAD_PARAM_TYPE:
      reply(session, packBare(MessageType::UNKNOWN, about));
      return;
    default:
      reply(session, packBare(MessageType::DATA_ERROR, about));
      return;
  }

  const ParamType param = message.param_type;
  switch (message.message_type)
  {
    case MessageType::QUIT:
      if (session->is_udp)
      {
        session->subscriptions.clear();
        udp_sessions_.erase(session->peer);
      }
      closeSession(session);
      return;
    case MessageType::GET_PARAMETERS: {
      CameraId camera;
      if (unpackCamera(message, camera) != UnpackError::NONE)
      {
        reply(session, packBare(MessageType::DATA_ERROR, param));
        return;
      }
      Message answer;
      if (current(param, camera, answer))
      {
        reply(session, answer);
      }
      else if (param != ParamType::VIDEO_OUTPUT && param != ParamType::CAM_TARGETING &&
               param != ParamType::CAM_OPTICS_AND_CONTROL)
      {
        reply(session, packBare(MessageType::UNKNOWN, param));  // a parameter the emulator does not model
      }
      return;  // an unknown stream or camera: ignored, as DigiView does
    }
    case MessageType::GET_INTERVAL: {
      IntervalRequest request;
      if (unpackInterval(message, request) != UnpackError::NONE)
      {
        reply(session, packBare(MessageType::DATA_ERROR, param));
        return;
      }
      subscribe(session, request);
      return;
    }
    case MessageType::SET_PARAMETERS: {
      if (refuse_)
      {
        reply(session, packBare(MessageType::FORBIDDEN, param));
        return;
      }
      const TimePoint now = SteadyClock::now();
      if (param == ParamType::CAM_TARGETING)
      {
        CamTargeting targeting;
        if (unpackTargeting(message, targeting) != UnpackError::NONE)
        {
          reply(session, packBare(MessageType::DATA_ERROR, param));
          return;
        }
        std::unique_lock<std::mutex> lock(mutex_);
        SimDeviceModel* view = model(targeting.camera);
        if (view == nullptr)
        {
          return;  // unknown view: ignored
        }
        if (targeting.targeting_mode == 0)
        {
          const PtzSample state = view->sample(now);
          const double yaw = targeting.euler_delta ? state.position[PAN] + targeting.yaw : targeting.yaw;
          const double pitch = targeting.euler_delta ? state.position[TILT] + targeting.pitch : targeting.pitch;
          view->goToAxis(PAN, std::remainder(yaw, 2.0 * M_PI), now);
          view->goToAxis(TILT, pitch, now);
        }
        lock.unlock();
        reply(session, packBare(MessageType::ACKNOWLEDGEMENT, param));
        return;
      }
      if (param == ParamType::CAM_OPTICS_AND_CONTROL)
      {
        CamOpticsAndControl optics;
        if (unpackOptics(message, optics) != UnpackError::NONE)
        {
          reply(session, packBare(MessageType::DATA_ERROR, param));
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
        if (fov >= NARROWEST_FOV && fov <= WIDEST_FOV)  // outside: ignored, as DigiView does
        {
          view->goToAxis(ZOOM, fov, now);
        }
        lock.unlock();
        reply(session, packBare(MessageType::ACKNOWLEDGEMENT, param));
        return;
      }
      reply(session, packBare(MessageType::UNKNOWN, param));
      return;
    }
    default:
      reply(session, packBare(MessageType::UNKNOWN, param));
      return;
  }
}

}  // namespace ptz_action_server
