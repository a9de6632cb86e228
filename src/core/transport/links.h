/**
 * \file
 * \brief The three Link implementations, reached through Link::create() only.
 */
#pragma once

#include <array>
#include <memory>
#include <mutex>
#include <utility>

#include <boost/asio/ip/address.hpp>
#include <boost/asio/write.hpp>

#include "ptz_action_server/core/transport/link.h"

namespace ptz_action_server
{
std::unique_ptr<Link> makeSerialLink(boost::asio::io_context& context, const LinkConfig& config,
                                     Link::Listener& listener);
std::unique_ptr<Link> makeTcpLink(boost::asio::io_context& context, const LinkConfig& config, Link::Listener& listener);
std::unique_ptr<Link> makeHttpLink(boost::asio::io_context& context, const LinkConfig& config,
                                   Link::Listener& listener);
std::unique_ptr<Link> makeUdpLink(boost::asio::io_context& context, const LinkConfig& config, Link::Listener& listener);

/// \p host as a numeric address (dotted or IPv6), or false for a name to resolve. A numeric address needs no
/// resolution, and so none of the resolver threads Boost.Asio starts for one (one per io_context).
inline bool numericAddress(const std::string& host, boost::asio::ip::address& address)
{
  boost::system::error_code error;
  address = boost::asio::ip::make_address(host, error);
  return !error;
}

/**
 * \brief Keeps a name resolution's completion off a link that is gone.
 *
 * Boost.Asio resolves names on a thread of its own, and a cancelled resolution still completes (operation_aborted)
 * when getaddrinfo() returns, which may be after the session's teardown fence, on a pool thread that other sessions
 * keep running. Such a completion reaches the link only through wrap(), under a lock the link's destruction takes
 * too: it runs before the link goes, or not at all. Declare it as the link's last member (destroyed first).
 */
class ResolveGuard
{
public:
  ResolveGuard() = default;
  ~ResolveGuard()
  {
    std::lock_guard<std::mutex> lock(state_->mutex);
    state_->alive = false;
  }
  ResolveGuard(const ResolveGuard&) = delete;
  ResolveGuard& operator=(const ResolveGuard&) = delete;

  /// \p handler, run only while the guard lives.
  template <class Handler>
  auto wrap(Handler handler) const
  {
    return [state = state_, handler = std::move(handler)](const boost::system::error_code& error, auto results) {
      std::lock_guard<std::mutex> lock(state->mutex);
      if (state->alive)
      {
        handler(error, std::move(results));
      }
    };
  }

private:
  struct State
  {
    std::mutex mutex;
    bool alive = true;
  };
  const std::shared_ptr<State> state_ = std::make_shared<State>();
};

/// The read and write loops of a byte-stream link (Boost.Asio serial_port or tcp::socket).
template <class Stream>
class StreamLink : public ByteLink
{
protected:
  StreamLink(boost::asio::io_context& context, const LinkConfig& config, Listener& listener)
    : ByteLink(context, config, listener), stream_(context)
  {
  }

  /// The reason a read failed, naming the link.
  virtual std::string readFailure(const boost::system::error_code& error) const = 0;

  void startRead() override
  {
    stream_.async_read_some(
        boost::asio::buffer(buffer_),
        [this, connection = connection()](const boost::system::error_code& error, std::size_t size) {
          if (connection != this->connection())
          {
            return;  // an earlier connection's completion
          }
          if (error)
          {
            lost(readFailure(error));
            return;
          }
          received(buffer_.data(), size);
        });
  }

  void startWrite(const std::vector<std::uint8_t>& bytes) override
  {
    boost::asio::async_write(
        stream_, boost::asio::buffer(bytes),
        [this, connection = connection()](const boost::system::error_code& error, std::size_t size) {
          if (connection != this->connection())
          {
            return;
          }
          if (error)
          {
            lost(config_.describe() + ": write failed: " + error.message());
            return;
          }
          written(size);
        });
  }

  Stream stream_;

private:
  std::array<std::uint8_t, 4096> buffer_{};
};

}  // namespace ptz_action_server
