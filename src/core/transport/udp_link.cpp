/**
 * \file
 * \brief Datagrams to and from one peer on Boost.Asio. Datagrams from anyone else are counted and dropped.
 */
#include <boost/asio/ip/udp.hpp>

#include "links.h"

namespace ptz_action_server
{
namespace
{
using boost::asio::ip::udp;

/// Larger than any UDP payload (65507 bytes): a datagram is never cut.
constexpr std::size_t MAX_DATAGRAM = 65536;

class UdpLink : public ByteLink
{
public:
  UdpLink(boost::asio::io_context& context, const LinkConfig& config, Listener& listener)
    : ByteLink(context, config, listener), socket_(context), resolver_(context), buffer_(MAX_DATAGRAM)
  {
  }

protected:
  void startOpen() override
  {
    // The socket is not connected to the peer, so datagrams from strangers reach us to be counted, and no ICMP
    // "port unreachable" from an earlier send ever fails a receive.
    boost::asio::ip::address address;
    if (numericAddress(config_.host, address) && address.is_v4())
    {
      bindFor(udp::endpoint(address, config_.port));
      return;
    }
    resolver_.async_resolve(
        udp::v4(), config_.host, std::to_string(config_.port),
        resolve_guard_.wrap([this, connection = connection()](const boost::system::error_code& error,
                                                              udp::resolver::results_type found) {
          if (connection != this->connection())
          {
            return;
          }
          if (error || found.empty())
          {
            openFailed("cannot resolve " + config_.host + ": " + error.message());
            return;
          }
          bindFor(found.begin()->endpoint());
        }));
  }

  /// Opens the local socket for datagrams to and from \p peer.
  void bindFor(const udp::endpoint& peer)
  {
    peer_ = peer;
    boost::system::error_code failure;
    const auto local = boost::asio::ip::make_address(config_.local_host, failure);
    if (!failure)
    {
      socket_.open(udp::v4(), failure);
    }
    if (!failure)
    {
      socket_.bind(udp::endpoint(local, config_.local_port), failure);
    }
    if (failure)
    {
      openFailed("cannot bind udp " + config_.local_host + ":" + std::to_string(config_.local_port) + ": " +
                 failure.message());
      return;
    }
    opened();
  }

  void closeHandle() override
  {
    resolver_.cancel();
    boost::system::error_code ignored;
    socket_.close(ignored);
  }

  void startRead() override
  {
    socket_.async_receive_from(
        boost::asio::buffer(buffer_), sender_,
        [this, connection = connection()](const boost::system::error_code& error, std::size_t size) {
          if (connection != this->connection())
          {
            return;
          }
          if (error == boost::asio::error::connection_refused || error == boost::asio::error::connection_reset)
          {
            startRead();  // an ICMP error about an earlier datagram: not a datagram, not a broken socket
            return;
          }
          if (error)
          {
            lost(config_.describe() + ": receive failed: " + error.message());
            return;
          }
          if (sender_ != peer_)
          {
            ++counters_.foreign_datagrams;
            startRead();
            return;
          }
          received(buffer_.data(), size);
        });
  }

  void startWrite(const std::vector<std::uint8_t>& bytes) override
  {
    socket_.async_send_to(boost::asio::buffer(bytes), peer_,
                          [this, connection = connection()](const boost::system::error_code& error, std::size_t size) {
                            if (connection != this->connection())
                            {
                              return;
                            }
                            if (error)
                            {
                              ++counters_.write_failures;  // a datagram lost is no broken link
                            }
                            written(error ? 0 : size);
                          });
  }

private:
  udp::socket socket_;
  udp::resolver resolver_;
  udp::endpoint peer_;
  udp::endpoint sender_;
  std::vector<std::uint8_t> buffer_;
  ResolveGuard resolve_guard_;  ///< last: destroyed first, before anything a late resolution would touch
};
}  // namespace

std::unique_ptr<Link> makeUdpLink(boost::asio::io_context& context, const LinkConfig& config, Link::Listener& listener)
{
  return std::make_unique<UdpLink>(context, config, listener);
}

}  // namespace ptz_action_server
