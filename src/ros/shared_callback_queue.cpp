#include "ptz_action_server/ros/shared_callback_queue.h"

#include "ptz_action_server/core/process_shared.h"

namespace ptz_action_server
{
std::shared_ptr<SharedCallbackQueue> SharedCallbackQueue::shared()
{
  return processShared<SharedCallbackQueue>();
}

SharedCallbackQueue::SharedCallbackQueue() : thread_([this] { run(); })
{
}

SharedCallbackQueue::~SharedCallbackQueue()
{
  stopping_ = true;
  queue_.disable();  // wakes the wait
  thread_.join();
}

void SharedCallbackQueue::run()
{
  // An AsyncSpinner waits at most 0.1 s at a time; this thread sleeps until a call comes or the queue is disabled.
  constexpr double WAIT = 5.0;  // s, a backstop only
  while (!stopping_)
  {
    queue_.callAvailable(ros::WallDuration(WAIT));
  }
}

}  // namespace ptz_action_server
