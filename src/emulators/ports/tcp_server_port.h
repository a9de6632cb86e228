/**
 * \file
 * \brief The Ethernet end of a device emulator: a TCP server on Boost.Asio that serves one client at a time, or
 * every client at once.
 */
#pragma once

#include <array>
#include <deque>
#include <memory>
#include <string>
#include <vector>

#include <boost/asio/ip/tcp.hpp>

#include "socket_server_port.h"

namespace ptz_action_server
{
/**
 * \brief A TCP server standing for a unit on Ethernet (FLIR E-series on port 4000) or a serial device behind a
 * serial-to-Ethernet server: a new client replaces the previous one, as such servers do. With
 * DevicePortConfig::many_clients (a DigiView), every client is served at once: sender() names the client a handler
 * runs for, sendTo() answers one. Bytes are not paced. Unplug closes the clients and stops listening (connections
 * are refused); replug listens again on the same port.
 */
class TcpServerPort : public SocketServerPort
{
public:
  TcpServerPort(const DevicePortConfig& config, Handlers handlers);
  ~TcpServerPort() override;

  std::uint16_t tcpPort() const override
  {
    return port_;
  }
  std::string sender() const override;
  void disconnect(const std::string& peer) override;
  void unplug() override;
  void replug() override;

private:
  /// One connection. I/O thread only.
  struct Client
  {
    explicit Client(boost::asio::ip::tcp::socket accepted) : socket(std::move(accepted))
    {
    }
    boost::asio::ip::tcp::socket socket;
    std::string peer;  ///< "host:port" of the client's end
    bool open = true;
    std::array<std::uint8_t, 4096> buffer{};
    std::deque<std::vector<std::uint8_t>> writes;
  };
  using ClientPtr = std::shared_ptr<Client>;

  void beginServing() override
  {
    accept();
  }
  void accept();
  void read(const ClientPtr& client);
  void post(std::vector<std::uint8_t> bytes, const std::string& peer) override;
  void writeNext(const ClientPtr& client);
  /// Closes \p client; \p notify: tells on_disconnect.
  void close(const ClientPtr& client, bool notify = true);
  void closeAll(bool notify);
  /// Runs \p handler with sender() naming \p client.
  template <class Handler>
  void on(const Client& client, const Handler& handler);

  TcpListener listener_;
  std::vector<ClientPtr> clients_;   ///< I/O thread: the open connections, the newest last
  const Client* current_ = nullptr;  ///< I/O thread: the client a handler runs for
};

}  // namespace ptz_action_server
