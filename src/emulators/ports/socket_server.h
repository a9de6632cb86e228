/**
 * \file
 * \brief What every network emulator serves on: a Boost.Asio context and its thread, and a listening TCP socket that
 * keeps its port across a close and a reopen. Under the DevicePort socket servers and the HTTP cameras' server.
 */
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <thread>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>

namespace ptz_action_server
{
/// A Boost.Asio context and the one thread that runs it.
class SocketServer
{
public:
  SocketServer() = default;
  /// Stops the thread if stop() was not called.
  ~SocketServer();
  SocketServer(const SocketServer&) = delete;
  SocketServer& operator=(const SocketServer&) = delete;

  boost::asio::io_context& context()
  {
    return context_;
  }
  /// Starts the thread (once).
  void start();
  /// Runs \p close_sockets on the thread, then stops it and joins it. Call it first in the owner's destructor.
  void stop(const std::function<void()>& close_sockets);
  /// Runs \p work on the thread and waits for it (at once when called on the thread, or before start()).
  void run(const std::function<void()>& work);

private:
  boost::asio::io_context context_;
  std::thread thread_;
};

/// A listening TCP socket: bound at construction (port 0: any free port, then kept), closed and reopened on the same
/// port. Its thread only (but for port()).
class TcpListener
{
public:
  TcpListener(boost::asio::io_context& context, const std::string& host, std::uint16_t port);

  /// The port it listens on (fixed once bound).
  std::uint16_t port() const
  {
    return port_;
  }
  bool isOpen() const
  {
    return acceptor_.is_open();
  }
  /// Listens again on the same port, if closed. Throws boost::system::system_error if it cannot.
  void open();
  /// Stops listening: connections are refused.
  void close();
  /// Accepts until closed: \p accepted gets each connection (no_delay set).
  void accept(std::function<void(boost::asio::ip::tcp::socket socket)> accepted);

private:
  const std::string host_;
  std::uint16_t port_;
  boost::asio::ip::tcp::acceptor acceptor_;
};

}  // namespace ptz_action_server
