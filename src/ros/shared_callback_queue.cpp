#include "ptz_action_server/ros/shared_callback_queue.h"

#include <mutex>

namespace ptz_action_server
{
std::shared_ptr<SharedCallbackQueue> SharedCallbackQueue::shared()
{
  static std::mutex mutex;
  static std::weak_ptr<SharedCallbackQueue> instance;
  std::lock_guard<std::mutex> lock(mutex);
  std::shared_ptr<SharedCallbackQueue> queue = instance.lock();
  if (!queue)
  {
    queue = std::make_shared<SharedCallbackQueue>();
    instance = queue;
  }
  return queue;
}

SharedCallbackQueue::SharedCallbackQueue() : spinner_(1, &queue_)
{
  spinner_.start();
}

SharedCallbackQueue::~SharedCallbackQueue()
{
  spinner_.stop();
}

}  // namespace ptz_action_server
