#include "socket_server.h"

#include <future>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/post.hpp>

namespace ptz_action_server
{
using boost::asio::ip::tcp;

SocketServer::~SocketServer()
{
  stop([] {});
}

void SocketServer::start()
{
  if (thread_.joinable())
  {
    return;
  }
  thread_ = std::thread([this] {
    auto work = boost::asio::make_work_guard(context_);
    context_.run();
  });
}

void SocketServer::stop(const std::function<void()>& close_sockets)
{
  if (!thread_.joinable())
  {
    return;
  }
  boost::asio::post(context_, [this, &close_sockets] {
    close_sockets();
    context_.stop();
  });
  thread_.join();
}

void SocketServer::run(const std::function<void()>& work)
{
  if (!thread_.joinable() || std::this_thread::get_id() == thread_.get_id())
  {
    work();
    return;
  }
  std::promise<void> done;
  boost::asio::post(context_, [&] {
    work();
    done.set_value();
  });
  done.get_future().wait();
}

TcpListener::TcpListener(boost::asio::io_context& context, const std::string& host, std::uint16_t port)
  : host_(host), port_(port), acceptor_(context)
{
  open();
}

void TcpListener::open()
{
  if (acceptor_.is_open())
  {
    return;
  }
  const tcp::endpoint endpoint(boost::asio::ip::make_address(host_), port_);
  acceptor_.open(endpoint.protocol());
  acceptor_.set_option(tcp::acceptor::reuse_address(true));
  acceptor_.bind(endpoint);
  acceptor_.listen();
  port_ = acceptor_.local_endpoint().port();  // a reopen takes the same port
}

void TcpListener::close()
{
  boost::system::error_code ignored;
  acceptor_.close(ignored);
}

void TcpListener::accept(std::function<void(tcp::socket socket)> accepted)
{
  acceptor_.async_accept(
      [this, accepted = std::move(accepted)](const boost::system::error_code& error, tcp::socket socket) mutable {
        if (error == boost::asio::error::operation_aborted || !acceptor_.is_open())
        {
          return;  // closed
        }
        if (!error)
        {
          boost::system::error_code ignored;
          socket.set_option(tcp::no_delay(true), ignored);
          accepted(std::move(socket));
        }
        accept(std::move(accepted));
      });
}

}  // namespace ptz_action_server
