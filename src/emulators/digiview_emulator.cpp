#include "ptz_action_server/emulators/digiview_emulator.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <tuple>

#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/write.hpp>

#include "digiview_emulator_internal.h"

namespace ptz_action_server
{
namespace
{
using boost::asio::ip::tcp;
using boost::asio::ip::udp;
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

DigiViewEmulator::DigiViewEmulator(const DigiViewEmulatorConfig& config)
  : config_(config), acceptor_(context_), udp_(context_)
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

void DigiViewEmulator::setEndless(bool endless)
{
  endless_ = endless;
}

void DigiViewEmulator::setRefuse(bool refuse)
{
  refuse_ = refuse;
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

bool DigiViewEmulator::faultSilence(bool on)
{
  setSilent(on);
  return true;
}

bool DigiViewEmulator::faultDrop(bool on)
{
  if (on)
  {
    dropConnections();
  }
  return true;
}

bool DigiViewEmulator::faultEndless(bool on)
{
  setEndless(on);
  return true;
}

bool DigiViewEmulator::faultFlood(bool on)
{
  setFlood(on ? FAULT_FLOOD_COPIES : 1);
  return true;
}

bool DigiViewEmulator::faultModel(EmulatorFault fault, const SimFaults& faults)
{
  if (fault != EmulatorFault::IMPOSSIBLE)
  {
    return false;
  }
  setFaults(faults);
  return true;
}

std::size_t DigiViewEmulator::connections() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return static_cast<std::size_t>(
      std::count_if(sessions_.begin(), sessions_.end(), [](const SessionPtr& session) { return session->open; }));
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
        // A stream: cut into messages of the format's size.
        const std::size_t message_size = layoutOf(config_.wire.format).size;
        std::size_t offset = 0;
        while (session->open && session->buffered - offset >= message_size)
        {
          handle(session, session->buffer.data() + offset, message_size);
          offset += message_size;
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
  Bytes bytes = stamped.pack();
  if (!config_.fill_checksum)
  {
    bytes[layoutOf(stamped.format).checksum_offset] = 0;
  }
  if (endless_)
  {
    bytes.assign(bytes.size() - 1, 'A');
  }
  if (session->is_udp)
  {
    auto datagram = std::make_shared<Bytes>(std::move(bytes));
    udp_.async_send_to(boost::asio::buffer(*datagram), session->peer,
                       [datagram](const boost::system::error_code&, std::size_t) {});
    return;
  }
  session->writes.push_back(std::move(bytes));
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
      for (unsigned copy = 0; copy < flood_; ++copy)
      {
        reply(alive, message);
      }
    }
    subscription.timer->expires_at(subscription.timer->expiry() +
                                   std::chrono::milliseconds(subscription.request.interval_ms));
    waitSubscription(alive, key);
  });
}

}  // namespace ptz_action_server
