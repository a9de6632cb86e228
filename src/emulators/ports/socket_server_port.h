/**
 * \file
 * \brief What the emulators' network ports share: the socket server (context and thread), the bound port and the tick.
 */
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <boost/asio/steady_timer.hpp>

#include "ptz_action_server/emulators/ports/device_port.h"
#include "socket_server.h"

namespace ptz_action_server
{
/**
 * \brief A DevicePort on a socket of the loopback network: one I/O thread runs the context; the subclass binds its
 * socket (in its constructor, so the port is known before anyone asks) and serves it from beginServing().
 */
class SocketServerPort : public DevicePort
{
public:
  /// Starts the I/O thread: beginServing(), then the tick if there is an on_tick handler.
  void start() override;
  /// "host:port"
  std::string path() const override;
  double byteTime() const override
  {
    return 0.0;  // bytes are not paced on a network
  }
  /// To the last sender (udp) or the newest client (tcp).
  void send(const std::uint8_t* data, std::size_t size) override;
  void sendTo(const std::string& peer, const std::uint8_t* data, std::size_t size) override;

protected:
  SocketServerPort(const DevicePortConfig& config, Handlers handlers);
  /// Subclasses call it first in their destructor: runs \p close_sockets on the I/O thread, then joins it.
  void stopThread(const std::function<void()>& close_sockets);
  /// Starts the first read or accept (I/O thread).
  virtual void beginServing() = 0;
  /// Sends \p bytes (garbled as configured) to \p peer ("": the last sender or newest client). Any thread.
  virtual void post(std::vector<std::uint8_t> bytes, const std::string& peer) = 0;

  const DevicePortConfig config_;
  const Handlers handlers_;
  SocketServer server_;
  boost::asio::io_context& context_;  ///< server_'s
  std::uint16_t port_ = 0;            ///< set by the subclass once bound

private:
  void tick();

  boost::asio::steady_timer tick_timer_;
};

}  // namespace ptz_action_server
