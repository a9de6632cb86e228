#include "ptz_action_server/core/transport/serial_link.h"

#include <sys/stat.h>

#include <algorithm>
#include <chrono>

#include <boost/asio/post.hpp>
#include <boost/asio/write.hpp>

namespace ptz_action_server
{
namespace
{
std::chrono::steady_clock::duration seconds(double value)
{
  return std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(value));
}
}  // namespace

SerialLink::SerialLink(const SerialLinkConfig& config, Listener& listener)
  : config_(config), listener_(listener), port_(context_), reopen_timer_(context_), identity_timer_(context_)
{
}

SerialLink::~SerialLink()
{
  stop();
}

void SerialLink::start()
{
  boost::asio::post(context_, [this] { open(); });
  thread_ = std::thread([this] {
    auto work = boost::asio::make_work_guard(context_);
    context_.run();
  });
}

void SerialLink::stop()
{
  if (!thread_.joinable())
  {
    return;
  }
  boost::asio::post(context_, [this] {
    reopen_timer_.cancel();
    identity_timer_.cancel();
    boost::system::error_code ignored;
    port_.close(ignored);
    connected_ = false;
    context_.stop();
  });
  thread_.join();
}

void SerialLink::post(std::function<void()> work)
{
  boost::asio::post(context_, std::move(work));
}

SerialLinkCounters SerialLink::counters() const
{
  std::lock_guard<std::mutex> lock(counters_mutex_);
  return counters_;
}

std::string SerialLink::lastError() const
{
  std::lock_guard<std::mutex> lock(counters_mutex_);
  return last_error_;
}

void SerialLink::diagnostics(std::vector<DiagnosticValue>& values) const
{
  const SerialLinkCounters counters = this->counters();
  values.emplace_back("port", config_.path);
  values.emplace_back("baud", std::to_string(config_.baud));
  values.emplace_back("port opens", std::to_string(counters.opens));
  values.emplace_back("port open failures", std::to_string(counters.open_failures));
  values.emplace_back("port losses", std::to_string(counters.disconnects));
  values.emplace_back("last port error", lastError());
}

void SerialLink::open()
{
  boost::system::error_code error;
  port_.open(config_.path, error);
  struct stat opened
  {
  };
  if (!error)
  {
    using boost::asio::serial_port_base;
    port_.set_option(serial_port_base::baud_rate(config_.baud), error);
    if (!error)
    {
      port_.set_option(serial_port_base::character_size(8), error);
      port_.set_option(serial_port_base::parity(serial_port_base::parity::none), error);
      port_.set_option(serial_port_base::stop_bits(serial_port_base::stop_bits::one), error);
      port_.set_option(serial_port_base::flow_control(serial_port_base::flow_control::none), error);
    }
    if (!error && ::fstat(port_.native_handle(), &opened) != 0)
    {
      error = boost::system::error_code(errno, boost::system::system_category());
    }
  }
  if (error)
  {
    boost::system::error_code ignored;
    port_.close(ignored);
    {
      std::lock_guard<std::mutex> lock(counters_mutex_);
      ++counters_.open_failures;
      last_error_ = "cannot open " + config_.path + ": " + error.message();
    }
    scheduleReopen();
    return;
  }
  device_ = opened.st_rdev;
  inode_ = opened.st_ino;
  connected_ = true;
  backoff_ = 0.0;
  {
    std::lock_guard<std::mutex> lock(counters_mutex_);
    ++counters_.opens;
  }
  listener_.onConnected();
  startRead();
  checkIdentity();
}

void SerialLink::scheduleReopen()
{
  backoff_ = backoff_ <= 0.0 ? config_.reconnect_min : std::min(backoff_ * 2.0, config_.reconnect_max);
  reopen_timer_.expires_after(seconds(backoff_));
  reopen_timer_.async_wait([this](const boost::system::error_code& error) {
    if (!error)
    {
      open();
    }
  });
}

void SerialLink::startRead()
{
  port_.async_read_some(boost::asio::buffer(read_buffer_),
                        [this](const boost::system::error_code& error, std::size_t size) {
                          if (error == boost::asio::error::operation_aborted || !connected_)
                          {
                            return;
                          }
                          if (error)
                          {
                            disconnect("read failed: " + error.message());
                            return;
                          }
                          {
                            std::lock_guard<std::mutex> lock(counters_mutex_);
                            counters_.bytes_in += size;
                          }
                          listener_.onBytes(read_buffer_.data(), size);
                          if (connected_)
                          {
                            startRead();
                          }
                        });
}

void SerialLink::write(const std::string& bytes)
{
  write(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
}

void SerialLink::write(const std::uint8_t* data, std::size_t size)
{
  if (!connected_ || size == 0)
  {
    return;
  }
  write_queue_.emplace_back(data, data + size);
  if (write_queue_.size() == 1)
  {
    startWrite();
  }
}

void SerialLink::startWrite()
{
  boost::asio::async_write(port_, boost::asio::buffer(write_queue_.front()),
                           [this](const boost::system::error_code& error, std::size_t size) {
                             if (error == boost::asio::error::operation_aborted || !connected_)
                             {
                               return;
                             }
                             if (error)
                             {
                               disconnect("write failed: " + error.message());
                               return;
                             }
                             {
                               std::lock_guard<std::mutex> lock(counters_mutex_);
                               counters_.bytes_out += size;
                             }
                             write_queue_.pop_front();
                             if (!write_queue_.empty())
                             {
                               startWrite();
                             }
                           });
}

void SerialLink::disconnect(const std::string& reason)
{
  if (!connected_)
  {
    return;
  }
  connected_ = false;
  identity_timer_.cancel();
  write_queue_.clear();
  boost::system::error_code ignored;
  port_.cancel(ignored);
  port_.close(ignored);
  {
    std::lock_guard<std::mutex> lock(counters_mutex_);
    ++counters_.disconnects;
    last_error_ = reason;
  }
  listener_.onDisconnected(reason);
  scheduleReopen();
}

void SerialLink::checkIdentity()
{
  identity_timer_.expires_after(seconds(config_.identity_check));
  identity_timer_.async_wait([this](const boost::system::error_code& error) {
    if (error || !connected_)
    {
      return;
    }
    // The path must still name the device we hold open: a replugged adapter or a re-created pseudo-terminal gets a
    // new device under the same (symlinked) path, while our descriptor still points at the old one.
    struct stat now
    {
    };
    if (::stat(config_.path.c_str(), &now) != 0)
    {
      disconnect(config_.path + " is gone");
      return;
    }
    if (now.st_rdev != device_ || now.st_ino != inode_)
    {
      disconnect(config_.path + " now names another device");
      return;
    }
    checkIdentity();
  });
}

}  // namespace ptz_action_server
