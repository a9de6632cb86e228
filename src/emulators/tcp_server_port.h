/**
 * \file
 * \brief The Ethernet end of a device emulator: a TCP server on Boost.Asio that serves one client at a time.
 */
#pragma once

#include <array>
#include <deque>
#include <vector>

#include <boost/asio/ip/tcp.hpp>

#include "socket_server_port.h"

namespace ptz_action_server
{
/**
 * \brief A TCP server standing for a unit on Ethernet (FLIR E-series on port 4000) or a serial device behind a
 * serial-to-Ethernet server. A new client replaces the previous one, as such servers do. Bytes are not paced.
 * Unplug closes the client and stops listening (connections are refused); replug listens again on the same port.
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
  void send(const std::uint8_t* data, std::size_t size) override;
  void unplug() override;
  void replug() override;

private:
  void beginServing() override
  {
    accept();
  }
  void listen();
  void accept();
  void read();
  void writeNext();
  void closeClient();

  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::ip::tcp::socket client_;
  bool connected_ = false;           ///< I/O thread
  std::uint64_t client_serial_ = 0;  ///< I/O thread: completions of an earlier client are ignored
  std::array<std::uint8_t, 4096> buffer_{};
  std::deque<std::vector<std::uint8_t>> writes_;
};

}  // namespace ptz_action_server
