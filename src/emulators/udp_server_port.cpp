#include "udp_server_port.h"

#include <boost/asio/post.hpp>

namespace ptz_action_server
{
using boost::asio::ip::udp;

UdpServerPort::UdpServerPort(const DevicePortConfig& config, Handlers handlers)
  : SocketServerPort(config, std::move(handlers)), socket_(context_)
{
  bind();  // in the constructor: the port is known (and taken) before anyone asks for it
}

UdpServerPort::~UdpServerPort()
{
  stopThread([this] {
    boost::system::error_code ignored;
    socket_.close(ignored);
  });
}

void UdpServerPort::bind()
{
  const udp::endpoint endpoint(boost::asio::ip::make_address(config_.host), port_);
  socket_.open(endpoint.protocol());
  socket_.set_option(udp::socket::reuse_address(true));
  socket_.bind(endpoint);
  port_ = socket_.local_endpoint().port();
}

void UdpServerPort::receive()
{
  socket_.async_receive_from(boost::asio::buffer(buffer_), sender_,
                             [this](const boost::system::error_code& error, std::size_t size) {
                               if (error == boost::asio::error::operation_aborted || !socket_.is_open())
                               {
                                 return;
                               }
                               if (!error && !silent())
                               {
                                 peer_ = sender_;
                                 has_peer_ = true;
                                 handlers_.on_bytes(buffer_.data(), size, SteadyClock::now());
                               }
                               receive();  // errors (an ICMP port unreachable) do not close a UDP socket
                             });
}

void UdpServerPort::send(const std::uint8_t* data, std::size_t size)
{
  if (silent() || size == 0)
  {
    return;
  }
  std::vector<std::uint8_t> bytes(data, data + size);
  boost::asio::post(context_, [this, bytes = std::move(bytes)]() mutable {
    if (!has_peer_ || !socket_.is_open())
    {
      return;
    }
    garble(bytes.data(), bytes.size());
    boost::system::error_code ignored;
    socket_.send_to(boost::asio::buffer(bytes), peer_, 0, ignored);  // a datagram never blocks for long
  });
}

void UdpServerPort::unplug()
{
  boost::asio::post(context_, [this] {
    boost::system::error_code ignored;
    socket_.close(ignored);
    has_peer_ = false;
  });
}

void UdpServerPort::replug()
{
  boost::asio::post(context_, [this] {
    if (socket_.is_open())
    {
      return;
    }
    bind();
    receive();
  });
}

}  // namespace ptz_action_server
