/**
 * \file
 * \brief The network end of a device emulator that takes datagrams: a UDP socket on Boost.Asio that answers whoever
 * wrote last (a camera on VISCA over IP serves one controller at a time).
 */
#pragma once

#include <array>
#include <deque>
#include <thread>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/udp.hpp>
#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/emulators/device_port.h"

namespace ptz_action_server
{
/**
 * \brief A UDP socket standing for a device on the network. Each datagram is one on_bytes call; send() goes to the
 * sender of the last datagram (nothing before one came). Unplug closes the socket (datagrams go unanswered); replug
 * binds the same port again.
 */
class UdpServerPort : public DevicePort
{
public:
  UdpServerPort(const DevicePortConfig& config, Handlers handlers);
  ~UdpServerPort() override;

  void start() override;
  std::string path() const override;
  std::uint16_t udpPort() const override
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
  void bind();
  void receive();
  void tick();

  const DevicePortConfig config_;
  const Handlers handlers_;
  boost::asio::io_context context_;
  boost::asio::ip::udp::socket socket_;
  boost::asio::steady_timer tick_timer_;
  std::uint16_t port_ = 0;
  boost::asio::ip::udp::endpoint sender_;  ///< I/O thread: where the datagram being read came from
  boost::asio::ip::udp::endpoint peer_;    ///< I/O thread: who wrote last, and gets the answers
  bool has_peer_ = false;
  std::array<std::uint8_t, 65536> buffer_{};
  std::thread thread_;
};

}  // namespace ptz_action_server
