#include "ptz_action_server/core/device/device_session.h"

#include <functional>
#include <mutex>
#include <utility>

#include <boost/asio/post.hpp>

namespace ptz_action_server
{
void DeviceSession::post(std::function<void()> work)
{
  std::lock_guard<std::mutex> lock(post_mutex_);
  if (stop_begun_)
  {
    return;
  }
  boost::asio::post(context(), std::move(work));
}

}  // namespace ptz_action_server
