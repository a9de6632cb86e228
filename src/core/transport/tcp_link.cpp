/**
 * \file
 * \brief A TCP client connection on Boost.Asio, reconnected with backoff, with a deadline on every attempt.
 */
#include <boost/asio/connect.hpp>
#include <boost/asio/ip/tcp.hpp>

#include "links.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
using boost::asio::ip::tcp;

class TcpLink : public StreamLink<tcp::socket>
{
public:
  TcpLink(boost::asio::io_context& context, const LinkConfig& config, Listener& listener)
    : StreamLink(context, config, listener)
    , resolver_(context)
    , connect_timer_(context)
    , peer_(config.host + ":" + std::to_string(config.port))
  {
  }

protected:
  void startOpen() override
  {
    boost::asio::ip::address address;
    if (numericAddress(config_.host, address))
    {
      connect({ tcp::endpoint(address, config_.port) });
      return;
    }
    resolver_.async_resolve(
        config_.host, std::to_string(config_.port),
        resolve_guard_.wrap([this, connection = connection()](const boost::system::error_code& error,
                                                              tcp::resolver::results_type found) {
          if (connection != this->connection())
          {
            return;
          }
          if (error)
          {
            openFailed("cannot resolve " + config_.host + ": " + error.message());
            return;
          }
          std::vector<tcp::endpoint> endpoints;
          for (const auto& entry : found)
          {
            endpoints.push_back(entry.endpoint());
          }
          connect(endpoints);
        }));
  }

  void closeHandle() override
  {
    resolver_.cancel();
    connect_timer_.cancel();
    boost::system::error_code ignored;
    stream_.shutdown(tcp::socket::shutdown_both, ignored);
    stream_.close(ignored);
  }

  std::string readFailure(const boost::system::error_code& error) const override
  {
    if (error == boost::asio::error::eof)
    {
      return "connection to " + peer_ + " closed";
    }
    if (error == boost::asio::error::connection_reset)
    {
      return "connection to " + peer_ + " reset";
    }
    return "connection to " + peer_ + ": read failed: " + error.message();
  }

private:
  void connect(const std::vector<tcp::endpoint>& found)
  {
    connect_timer_.expires_after(toDuration(config_.connect_timeout));
    connect_timer_.async_wait([this, connection = connection()](const boost::system::error_code& error) {
      if (!error && connection == this->connection())
      {
        openFailed("connection to " + peer_ + " timed out");
      }
    });
    boost::asio::async_connect(
        stream_, found,
        [this, connection = connection()](const boost::system::error_code& error, const tcp::endpoint&) {
          if (connection != this->connection())
          {
            return;
          }
          connect_timer_.cancel();
          if (error)
          {
            openFailed("connection to " + peer_ + " failed: " + error.message());
            return;
          }
          boost::system::error_code ignored;
          stream_.set_option(tcp::no_delay(true), ignored);  // commands are small and must not wait for Nagle
          stream_.set_option(boost::asio::socket_base::keep_alive(true), ignored);
          opened();
        });
  }

  tcp::resolver resolver_;
  boost::asio::steady_timer connect_timer_;
  const std::string peer_;      ///< host:port, for messages
  ResolveGuard resolve_guard_;  ///< last: destroyed first, before anything a late resolution would touch
};
}  // namespace

std::unique_ptr<Link> makeTcpLink(boost::asio::io_context& context, const LinkConfig& config, Link::Listener& listener)
{
  return std::make_unique<TcpLink>(context, config, listener);
}

}  // namespace ptz_action_server
