/**
 * \file
 * \brief The network end of a device emulator that takes datagrams: a UDP socket on Boost.Asio that answers whoever
 * wrote last (a camera on VISCA over IP serves one controller at a time).
 */
#pragma once

#include <array>
#include <deque>
#include <vector>

#include <boost/asio/ip/udp.hpp>

#include "socket_server_port.h"

namespace ptz_action_server
{
/**
 * \brief A UDP socket standing for a device on the network. Each datagram is one on_bytes call; send() goes to the
 * sender of the last datagram (nothing before one came). Unplug closes the socket (datagrams go unanswered); replug
 * binds the same port again.
 */
class UdpServerPort : public SocketServerPort
{
public:
  UdpServerPort(const DevicePortConfig& config, Handlers handlers);
  ~UdpServerPort() override;

  std::uint16_t udpPort() const override
  {
    return port_;
  }
  std::string sender() const override;
  void unplug() override;
  void replug() override;

private:
  void beginServing() override
  {
    receive();
  }
  void bind();
  void receive();
  void post(std::vector<std::uint8_t> bytes, const std::string& to) override;

  boost::asio::ip::udp::socket socket_;
  boost::asio::ip::udp::endpoint sender_;  ///< I/O thread: where the datagram being read came from
  boost::asio::ip::udp::endpoint peer_;    ///< I/O thread: who wrote last, and gets the answers
  bool has_peer_ = false;
  std::array<std::uint8_t, 65536> buffer_{};
};

}  // namespace ptz_action_server
