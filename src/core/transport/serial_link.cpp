/**
 * \file
 * \brief A serial port on Boost.Asio, reopened with backoff, that notices a port that vanished or was replaced under
 * the same path (a udev symlink now pointing to another device).
 */
#include <sys/stat.h>

#include <boost/asio/serial_port.hpp>

#include "links.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
namespace
{
class SerialLink : public StreamLink<boost::asio::serial_port>
{
public:
  SerialLink(boost::asio::io_context& context, const LinkConfig& config, Listener& listener)
    : StreamLink(context, config, listener), identity_timer_(context)
  {
  }

protected:
  void startOpen() override
  {
    using boost::asio::serial_port_base;
    boost::system::error_code error;
    stream_.open(config_.path, error);
    if (!error)
    {
      stream_.set_option(serial_port_base::baud_rate(config_.baud), error);
    }
    if (!error)
    {
      stream_.set_option(serial_port_base::character_size(8), error);
      stream_.set_option(serial_port_base::parity(serial_port_base::parity::none), error);
      stream_.set_option(serial_port_base::stop_bits(serial_port_base::stop_bits::one), error);
      stream_.set_option(serial_port_base::flow_control(serial_port_base::flow_control::none), error);
    }
    struct stat opened_device
    {
    };
    if (!error && ::fstat(stream_.native_handle(), &opened_device) != 0)
    {
      error = boost::system::error_code(errno, boost::system::system_category());
    }
    if (error)
    {
      openFailed("cannot open " + config_.path + ": " + error.message());
      return;
    }
    device_ = opened_device.st_rdev;
    inode_ = opened_device.st_ino;
    checkIdentity();
    opened();
  }

  void closeHandle() override
  {
    identity_timer_.cancel();
    boost::system::error_code ignored;
    stream_.cancel(ignored);
    stream_.close(ignored);
  }

  std::string readFailure(const boost::system::error_code& error) const override
  {
    return config_.path + ": read failed: " + error.message();
  }

private:
  /// The path must still name the device we hold open: a replugged adapter or a re-created pseudo-terminal gets a new
  /// device under the same (symlinked) path, while our descriptor still points at the old one.
  void checkIdentity()
  {
    identity_timer_.expires_after(toDuration(config_.identity_check));
    identity_timer_.async_wait([this, connection = connection()](const boost::system::error_code& error) {
      if (error || connection != this->connection())
      {
        return;
      }
      struct stat now
      {
      };
      if (::stat(config_.path.c_str(), &now) != 0)
      {
        lost(config_.path + " is gone");
        return;
      }
      if (now.st_rdev != device_ || now.st_ino != inode_)
      {
        lost(config_.path + " now names another device");
        return;
      }
      checkIdentity();
    });
  }

  boost::asio::steady_timer identity_timer_;
  dev_t device_ = 0;  ///< st_rdev of the open device
  ino_t inode_ = 0;   ///< st_ino of the open device node
};
}  // namespace

std::unique_ptr<Link> makeSerialLink(boost::asio::io_context& context, const LinkConfig& config,
                                     Link::Listener& listener)
{
  return std::make_unique<SerialLink>(context, config, listener);
}

}  // namespace ptz_action_server
