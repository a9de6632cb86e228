#include "socket_server_port.h"

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/post.hpp>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
SocketServerPort::SocketServerPort(const DevicePortConfig& config, Handlers handlers)
  : config_(config), handlers_(std::move(handlers)), port_(config.port), tick_timer_(context_)
{
}

void SocketServerPort::stopThread(const std::function<void()>& close_sockets)
{
  if (thread_.joinable())
  {
    boost::asio::post(context_, [this, &close_sockets] {
      close_sockets();
      tick_timer_.cancel();
      context_.stop();
    });
    thread_.join();
  }
}

void SocketServerPort::start()
{
  boost::asio::post(context_, [this] {
    beginServing();
    if (handlers_.on_tick)
    {
      tick();
    }
  });
  thread_ = std::thread([this] {
    auto work = boost::asio::make_work_guard(context_);
    context_.run();
  });
}

std::string SocketServerPort::path() const
{
  return config_.host + ":" + std::to_string(port_);
}

void SocketServerPort::tick()
{
  handlers_.on_tick();
  tick_timer_.expires_after(toDuration(config_.tick_period));
  tick_timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error)
    {
      tick();
    }
  });
}

}  // namespace ptz_action_server
