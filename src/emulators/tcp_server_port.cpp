#include "tcp_server_port.h"

#include <boost/asio/post.hpp>
#include <boost/asio/write.hpp>

namespace ptz_action_server
{
using boost::asio::ip::tcp;

TcpServerPort::TcpServerPort(const DevicePortConfig& config, Handlers handlers)
  : SocketServerPort(config, std::move(handlers)), acceptor_(context_), client_(context_)
{
  listen();  // in the constructor: the port is known (and taken) before anyone asks for it
}

TcpServerPort::~TcpServerPort()
{
  stopThread([this] {
    closeClient();
    boost::system::error_code ignored;
    acceptor_.close(ignored);
  });
}

void TcpServerPort::listen()
{
  const tcp::endpoint endpoint(boost::asio::ip::make_address(config_.host), port_);
  acceptor_.open(endpoint.protocol());
  acceptor_.set_option(tcp::acceptor::reuse_address(true));
  acceptor_.bind(endpoint);
  acceptor_.listen();
  port_ = acceptor_.local_endpoint().port();
}

void TcpServerPort::accept()
{
  acceptor_.async_accept([this](const boost::system::error_code& error, tcp::socket socket) {
    if (error == boost::asio::error::operation_aborted || !acceptor_.is_open())
    {
      return;
    }
    if (!error)
    {
      closeClient();  // one client at a time: the newest wins
      client_ = std::move(socket);
      boost::system::error_code ignored;
      client_.set_option(tcp::no_delay(true), ignored);
      connected_ = true;
      ++client_serial_;
      if (handlers_.on_connect)
      {
        handlers_.on_connect();
      }
      read();
    }
    accept();
  });
}

void TcpServerPort::read()
{
  client_.async_read_some(boost::asio::buffer(buffer_),
                          [this, serial = client_serial_](const boost::system::error_code& error, std::size_t size) {
                            if (serial != client_serial_ || !connected_)
                            {
                              return;
                            }
                            if (error)
                            {
                              closeClient();
                              return;
                            }
                            if (!silent())
                            {
                              handlers_.on_bytes(buffer_.data(), size, SteadyClock::now());
                            }
                            read();
                          });
}

void TcpServerPort::send(const std::uint8_t* data, std::size_t size)
{
  if (silent() || size == 0)
  {
    return;
  }
  std::vector<std::uint8_t> bytes(data, data + size);
  boost::asio::post(context_, [this, bytes = std::move(bytes)]() mutable {
    if (!connected_)
    {
      return;
    }
    garble(bytes.data(), bytes.size());
    writes_.push_back(std::move(bytes));
    if (writes_.size() == 1)
    {
      writeNext();
    }
  });
}

void TcpServerPort::writeNext()
{
  boost::asio::async_write(client_, boost::asio::buffer(writes_.front()),
                           [this, serial = client_serial_](const boost::system::error_code& error, std::size_t) {
                             if (serial != client_serial_ || !connected_)
                             {
                               return;
                             }
                             if (error)
                             {
                               closeClient();
                               return;
                             }
                             writes_.pop_front();
                             if (!writes_.empty())
                             {
                               writeNext();
                             }
                           });
}

void TcpServerPort::closeClient()
{
  if (!connected_)
  {
    return;
  }
  connected_ = false;
  ++client_serial_;
  writes_.clear();
  boost::system::error_code ignored;
  client_.shutdown(tcp::socket::shutdown_both, ignored);
  client_.close(ignored);
}

void TcpServerPort::unplug()
{
  boost::asio::post(context_, [this] {
    closeClient();
    boost::system::error_code ignored;
    acceptor_.close(ignored);
  });
}

void TcpServerPort::replug()
{
  boost::asio::post(context_, [this] {
    if (acceptor_.is_open())
    {
      return;
    }
    listen();
    accept();
  });
}

}  // namespace ptz_action_server
