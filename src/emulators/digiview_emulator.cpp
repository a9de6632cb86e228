#include "ptz_action_server/emulators/digiview_emulator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <tuple>

#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>

namespace ptz_action_server
{
namespace
{
using boost::asio::ip::tcp;
using boost::asio::ip::udp;
using namespace digiview;

constexpr double NARROWEST_FOV = 0.1;
constexpr double WIDEST_FOV = 3.14;
constexpr double ZOOM_STEP = 1.1;  ///< a relative zoom step of 1 narrows the field of view by this factor

/// User views per layout mode (6 is the debug view: one).
std::uint8_t viewsOf(std::uint8_t layout_mode)
{
  static const std::uint8_t VIEWS[] = { 1, 2, 2, 3, 4, 4, 1 };
  return layout_mode < sizeof(VIEWS) ? VIEWS[layout_mode] : 1;
}

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

/// A GET_INTERVAL subscription: its request and its timer.
struct DigiViewEmulator::Subscription
{
  IntervalRequest request;
  std::unique_ptr<boost::asio::steady_timer> timer;
};

/// One client: a TCP connection, or a UDP peer. Lives on the I/O thread.
struct DigiViewEmulator::Session
{
  using Key = std::tuple<int, std::string, std::uint8_t>;  ///< param, stream, camera
  explicit Session(boost::asio::io_context& context) : socket(context)
  {
  }
  tcp::socket socket;  ///< TCP only
  bool is_udp = false;
  udp::endpoint peer;
  bool open = true;
  std::array<std::uint8_t, 2048> buffer{};
  std::size_t buffered = 0;
  std::deque<digiview::Bytes> writes;
  std::map<Key, Subscription> subscriptions;
};

DigiViewEmulator::DigiViewEmulator(const DigiViewEmulatorConfig& config)
  : config_(config), acceptor_(context_), udp_(context_)
{
  const SimDeviceConfig model = viewModel(config);
  for (const std::string& stream : config.streams)
  {
    for (std::uint8_t cam = 0; cam < viewsOf(config.layout_mode); ++cam)
    {
      models_.emplace(std::make_pair(stream, cam), SimDeviceModel(model, SteadyClock::now()));
    }
  }
  const auto address = boost::asio::ip::make_address(config.host);
  if (config.transport == LinkKind::TCP)
  {
    const tcp::endpoint endpoint(address, config.port);
    acceptor_.open(endpoint.protocol());
    acceptor_.set_option(tcp::acceptor::reuse_address(true));
    acceptor_.bind(endpoint);
    acceptor_.listen();
    port_ = acceptor_.local_endpoint().port();
    accept();
  }
  else
  {
    udp_.open(udp::v4());
    udp_.bind(udp::endpoint(address, config.port));
    port_ = udp_.local_endpoint().port();
    readUdp();
  }
  thread_ = std::thread([this] {
    auto work = boost::asio::make_work_guard(context_);
    context_.run();
  });
}

DigiViewEmulator::~DigiViewEmulator()
{
  boost::asio::post(context_, [this] {
    boost::system::error_code ignored;
    acceptor_.close(ignored);
    udp_.close(ignored);
    for (const SessionPtr& session : sessions_)
    {
      closeSession(session);
    }
    context_.stop();
  });
  thread_.join();
}

void DigiViewEmulator::setSilent(bool silent)
{
  silent_ = silent;
}

void DigiViewEmulator::setRefuse(bool refuse)
{
  refuse_ = refuse;
}

void DigiViewEmulator::dropConnections()
{
  boost::asio::post(context_, [this] {
    const std::vector<SessionPtr> sessions = sessions_;
    for (const SessionPtr& session : sessions)
    {
      if (!session->is_udp)
      {
        closeSession(session);
      }
    }
  });
}

std::size_t DigiViewEmulator::connections() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<std::size_t>(
      std::count_if(sessions_.begin(), sessions_.end(), [](const SessionPtr& session) { return session->open; }));
}

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

void DigiViewEmulator::accept()
{
  auto session = std::make_shared<Session>(context_);
  acceptor_.async_accept(session->socket, [this, session](const boost::system::error_code& error) {
    if (error == boost::asio::error::operation_aborted)
    {
      return;
    }
    if (!error)
    {
      session->socket.set_option(tcp::no_delay(true));
      {
        std::lock_guard<std::mutex> lock(mutex_);
        sessions_.push_back(session);
      }
      readTcp(session);
    }
    accept();
  });
}

void DigiViewEmulator::readTcp(const SessionPtr& session)
{
  session->socket.async_read_some(
      boost::asio::buffer(session->buffer.data() + session->buffered, session->buffer.size() - session->buffered),
      [this, session](const boost::system::error_code& error, std::size_t size) {
        if (error || !session->open)
        {
          closeSession(session);
          return;
        }
        session->buffered += size;
        std::size_t offset = 0;
        while (session->open && session->buffered - offset >= MESSAGE_SIZE)
        {
          handle(session, session->buffer.data() + offset, MESSAGE_SIZE);
          offset += MESSAGE_SIZE;
        }
        std::copy(session->buffer.begin() + offset, session->buffer.begin() + session->buffered,
                  session->buffer.begin());
        session->buffered -= offset;
        if (session->open)
        {
          readTcp(session);
        }
      });
}

void DigiViewEmulator::readUdp()
{
  udp_.async_receive_from(boost::asio::buffer(udp_buffer_), udp_peer_,
                          [this](const boost::system::error_code& error, std::size_t size) {
                            if (error == boost::asio::error::operation_aborted)
                            {
                              return;
                            }
                            if (!error)
                            {
                              SessionPtr& session = udp_sessions_[udp_peer_];
                              if (!session || !session->open)
                              {
                                session = std::make_shared<Session>(context_);
                                session->is_udp = true;
                                session->peer = udp_peer_;
                                std::lock_guard<std::mutex> lock(mutex_);
                                sessions_.push_back(session);
                              }
                              handle(session, udp_buffer_.data(), size);
                            }
                            readUdp();
                          });
}

void DigiViewEmulator::closeSession(const SessionPtr& session)
{
  if (!session->open)
  {
    return;
  }
  session->open = false;
  session->subscriptions.clear();  // the timers' destructors cancel them
  session->writes.clear();
  boost::system::error_code ignored;
  if (!session->is_udp)
  {
    session->socket.shutdown(tcp::socket::shutdown_both, ignored);
    session->socket.close(ignored);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  sessions_.erase(std::remove(sessions_.begin(), sessions_.end(), session), sessions_.end());
}

void DigiViewEmulator::reply(const SessionPtr& session, const Message& message)
{
  if (silent_ || !session->open)
  {
    return;
  }
  Message stamped = message;
  stamped.timestamp = static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
  if (session->is_udp)
  {
    auto bytes = std::make_shared<digiview::Bytes>(stamped.pack());
    udp_.async_send_to(boost::asio::buffer(*bytes), session->peer,
                       [bytes](const boost::system::error_code&, std::size_t) {});
    return;
  }
  session->writes.push_back(stamped.pack());
  if (session->writes.size() == 1)
  {
    writeNext(session);
  }
}

void DigiViewEmulator::writeNext(const SessionPtr& session)
{
  boost::asio::async_write(session->socket, boost::asio::buffer(session->writes.front()),
                           [this, session](const boost::system::error_code& error, std::size_t) {
                             if (error || !session->open)
                             {
                               closeSession(session);
                               return;
                             }
                             session->writes.pop_front();
                             if (!session->writes.empty())
                             {
                               writeNext(session);
                             }
                           });
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

void DigiViewEmulator::subscribe(const SessionPtr& session, const IntervalRequest& request)
{
  const auto key = std::make_tuple(static_cast<int>(request.param), request.camera.stream_name, request.camera.cam_id);
  if (request.interval_ms == 0)
  {
    session->subscriptions.erase(key);
    return;
  }
  if (request.interval_ms < MIN_INTERVAL_MS)
  {
    return;  // below DigiView's minimum: ignored
  }
  Subscription& subscription = session->subscriptions[key];
  subscription.request = request;
  subscription.timer = std::make_unique<boost::asio::steady_timer>(context_);
  subscription.timer->expires_after(std::chrono::milliseconds(request.interval_ms));
  waitSubscription(session, key);
}

void DigiViewEmulator::waitSubscription(const SessionPtr& session, const Session::Key& key)
{
  std::weak_ptr<Session> weak = session;
  session->subscriptions.at(key).timer->async_wait([this, weak, key](const boost::system::error_code& error) {
    const SessionPtr alive = weak.lock();
    if (error || !alive || !alive->open)
    {
      return;
    }
    const auto found = alive->subscriptions.find(key);
    if (found == alive->subscriptions.end())
    {
      return;
    }
    Subscription& subscription = found->second;
    Message message;
    if (current(subscription.request.param, subscription.request.camera, message))
    {
      reply(alive, message);
    }
    subscription.timer->expires_at(subscription.timer->expiry() +
                                   std::chrono::milliseconds(subscription.request.interval_ms));
    waitSubscription(alive, key);
  });
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
