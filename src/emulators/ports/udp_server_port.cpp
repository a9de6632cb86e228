#include "udp_server_port.h"

#include <string>

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
                               if (!error && takesInput())
                               {
                                 peer_ = sender_;
                                 has_peer_ = true;
                                 handlers_.on_bytes(buffer_.data(), size, SteadyClock::now());
                               }
                               receive();  // errors (an ICMP port unreachable) do not close a UDP socket
                             });
}

std::string UdpServerPort::sender() const
{
  return sender_.address().to_string() + ":" + std::to_string(sender_.port());
}

void UdpServerPort::post(std::vector<std::uint8_t> bytes, const std::string& to)
{
  boost::asio::post(context_, [this, bytes = std::move(bytes), to]() mutable {
    udp::endpoint destination = peer_;
    if (!to.empty())
    {
      const std::size_t colon = to.rfind(':');
      if (colon == std::string::npos)
      {
        return;
      }
      boost::system::error_code invalid;
      destination = udp::endpoint(boost::asio::ip::make_address(to.substr(0, colon), invalid),
                                  static_cast<std::uint16_t>(std::stoul(to.substr(colon + 1))));
      if (invalid)
      {
        return;
      }
    }
    else if (!has_peer_)
    {
      return;
    }
    if (!socket_.is_open())
    {
      return;
    }
    garble(bytes.data(), bytes.size());
    boost::system::error_code ignored;
    socket_.send_to(boost::asio::buffer(bytes), destination, 0, ignored);  // a datagram never blocks for long
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
