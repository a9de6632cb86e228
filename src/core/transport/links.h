/**
 * \file
 * \brief The three Link implementations, reached through Link::create() only.
 */
#pragma once

#include <array>
#include <memory>

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

/// The read and write loops of a byte-stream link (Boost.Asio serial_port or tcp::socket).
template <class Stream>
class StreamLink : public Link
{
protected:
  StreamLink(boost::asio::io_context& context, const LinkConfig& config, Listener& listener)
    : Link(context, config, listener), stream_(context)
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
