#include "socket_server_port.h"

#include <boost/asio/post.hpp>

#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
SocketServerPort::SocketServerPort(const DevicePortConfig& config, Handlers handlers)
  : config_(config)
  , handlers_(std::move(handlers))
  , context_(server_.context())
  , port_(config.port)
  , tick_timer_(context_)
{
}

void SocketServerPort::stopThread(const std::function<void()>& close_sockets)
{
  server_.stop([this, &close_sockets] {
    close_sockets();
    tick_timer_.cancel();
  });
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
  server_.start();
}

void SocketServerPort::send(const std::uint8_t* data, std::size_t size)
{
  if (!silent() && size > 0)
  {
    post(std::vector<std::uint8_t>(data, data + size), std::string());
  }
}

void SocketServerPort::sendTo(const std::string& peer, const std::uint8_t* data, std::size_t size)
{
  if (!silent())  // a datagram may be empty
  {
    post(std::vector<std::uint8_t>(data, data + size), peer);
  }
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
