#include "ptz_action_server/ros/shared_callback_queue.h"

#include "ptz_action_server/core/process_shared.h"

namespace ptz_action_server
{
std::shared_ptr<SharedCallbackQueue> SharedCallbackQueue::shared()
{
  return processShared<SharedCallbackQueue>();
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
