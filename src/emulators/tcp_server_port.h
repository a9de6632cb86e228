/**
 * \file
 * \brief The Ethernet end of a device emulator: a TCP server on Boost.Asio that serves one client at a time.
 */
#pragma once

#include <array>
#include <deque>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/emulators/device_port.h"

namespace ptz_action_server
{
/**
 * \brief A TCP server standing for a unit on Ethernet (FLIR E-series on port 4000) or a serial device behind a
 * serial-to-Ethernet server. A new client replaces the previous one, as such servers do. Bytes are not paced.
 * Unplug closes the client and stops listening (connections are refused); replug listens again on the same port.
 */
class TcpServerPort : public DevicePort
{
public:
  TcpServerPort(const DevicePortConfig& config, Handlers handlers);
  ~TcpServerPort() override;

  void start() override;
  std::string path() const override;
  std::uint16_t tcpPort() const override
  {
    return port_;
  }
  double byteTime() const override
  {
    return 0.0;
  }
  void send(const std::uint8_t* data, std::size_t size) override;
  void unplug() override;
  void replug() override;

private:
  void listen();
  void accept();
  void read();
  void writeNext();
  void closeClient();
  void tick();

  const DevicePortConfig config_;
  const Handlers handlers_;
  boost::asio::io_context context_;
  boost::asio::ip::tcp::acceptor acceptor_;
  boost::asio::ip::tcp::socket client_;
  boost::asio::steady_timer tick_timer_;
  std::uint16_t port_ = 0;
  bool connected_ = false;           ///< I/O thread
  std::uint64_t client_serial_ = 0;  ///< I/O thread: completions of an earlier client are ignored
  std::array<std::uint8_t, 4096> buffer_{};
  std::deque<std::vector<std::uint8_t>> writes_;
  std::thread thread_;
};

}  // namespace ptz_action_server
