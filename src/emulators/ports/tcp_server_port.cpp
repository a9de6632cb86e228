#include "tcp_server_port.h"

#include <algorithm>

#include <boost/asio/post.hpp>
#include <boost/asio/write.hpp>

namespace ptz_action_server
{
using boost::asio::ip::tcp;

TcpServerPort::TcpServerPort(const DevicePortConfig& config, Handlers handlers)
  : SocketServerPort(config, std::move(handlers))
  , listener_(context_, config.host, config.port)  // the port is known (and taken) before anyone asks for it
{
  port_ = listener_.port();
}

TcpServerPort::~TcpServerPort()
{
  stopThread([this] {
    closeAll(false);  // the owner is going: no handler runs any more
    listener_.close();
  });
}

template <class Handler>
void TcpServerPort::on(const Client& client, const Handler& handler)
{
  current_ = &client;
  handler();
  current_ = nullptr;
}

std::string TcpServerPort::sender() const
{
  return current_ != nullptr ? current_->peer : std::string();
}

void TcpServerPort::accept()
{
  listener_.accept([this](tcp::socket socket) {
    if (!config_.many_clients)
    {
      closeAll(true);  // one client at a time: the newest wins
    }
    auto client = std::make_shared<Client>(std::move(socket));
    boost::system::error_code ignored;
    const tcp::endpoint remote = client->socket.remote_endpoint(ignored);
    client->peer = remote.address().to_string() + ":" + std::to_string(remote.port());
    clients_.push_back(client);
    if (handlers_.on_connect)
    {
      on(*client, handlers_.on_connect);
    }
    if (client->open)
    {
      read(client);
    }
  });
}

void TcpServerPort::read(const ClientPtr& client)
{
  client->socket.async_read_some(
      boost::asio::buffer(client->buffer), [this, client](const boost::system::error_code& error, std::size_t size) {
        if (!client->open)
        {
          return;
        }
        if (error)
        {
          close(client);
          return;
        }
        if (takesInput())
        {
          on(*client, [&] { handlers_.on_bytes(client->buffer.data(), size, SteadyClock::now()); });
        }
        if (client->open)
        {
          read(client);
        }
      });
}

void TcpServerPort::post(std::vector<std::uint8_t> bytes, const std::string& peer)
{
  if (bytes.empty())
  {
    return;
  }
  boost::asio::post(context_, [this, bytes = std::move(bytes), peer]() mutable {
    const auto found = peer.empty() ? clients_.rbegin() :
                                      std::find_if(clients_.rbegin(), clients_.rend(),
                                                   [&peer](const ClientPtr& client) { return client->peer == peer; });
    if (found == clients_.rend())
    {
      return;  // nobody there: lost, as on a real line
    }
    const ClientPtr client = *found;
    garble(bytes.data(), bytes.size());
    client->writes.push_back(std::move(bytes));
    if (client->writes.size() == 1)
    {
      writeNext(client);
    }
  });
}

void TcpServerPort::writeNext(const ClientPtr& client)
{
  boost::asio::async_write(client->socket, boost::asio::buffer(client->writes.front()),
                           [this, client](const boost::system::error_code& error, std::size_t) {
                             if (!client->open)
                             {
                               return;
                             }
                             if (error)
                             {
                               close(client);
                               return;
                             }
                             client->writes.pop_front();
                             if (!client->writes.empty())
                             {
                               writeNext(client);
                             }
                           });
}

void TcpServerPort::close(const ClientPtr& client, bool notify)
{
  if (!client->open)
  {
    return;
  }
  client->open = false;
  client->writes.clear();
  boost::system::error_code ignored;
  client->socket.shutdown(tcp::socket::shutdown_both, ignored);
  client->socket.close(ignored);
  clients_.erase(std::remove(clients_.begin(), clients_.end(), client), clients_.end());
  if (notify && handlers_.on_disconnect)
  {
    on(*client, handlers_.on_disconnect);
  }
}

void TcpServerPort::closeAll(bool notify)
{
  const std::vector<ClientPtr> clients = clients_;
  for (const ClientPtr& client : clients)
  {
    close(client, notify);
  }
}

void TcpServerPort::disconnect(const std::string& peer)
{
  boost::asio::post(context_, [this, peer] {
    const std::vector<ClientPtr> clients = clients_;
    for (const ClientPtr& client : clients)
    {
      if (client->peer == peer)
      {
        close(client);
      }
    }
  });
}

void TcpServerPort::unplug()
{
  boost::asio::post(context_, [this] {
    closeAll(true);
    listener_.close();
  });
}

void TcpServerPort::replug()
{
  boost::asio::post(context_, [this] {
    if (listener_.isOpen())
    {
      return;
    }
    listener_.open();
    accept();
  });
}

}  // namespace ptz_action_server
