/**
 * \file
 * \brief A callback queue and one spinner thread shared by every camera in a process, for the services that may
 * block on a file (preset saves write and fsync before they answer).
 */
#pragma once

#include <memory>

#include <ros/callback_queue.h>
#include <ros/spinner.h>

namespace ptz_action_server
{
/**
 * \brief The process's queue for slow services: one thread for all cameras instead of a spinner per camera.
 *
 * Its callbacks run one at a time, off every camera's goal queue and the state tick. An owner shuts its services
 * down before it lets go of the queue (roscpp then waits for a callback of that service in progress).
 */
class SharedCallbackQueue
{
public:
  /// The process's instance, started by the first caller; its thread stops with the last holder.
  static std::shared_ptr<SharedCallbackQueue> shared();

  SharedCallbackQueue();
  ~SharedCallbackQueue();
  SharedCallbackQueue(const SharedCallbackQueue&) = delete;
  SharedCallbackQueue& operator=(const SharedCallbackQueue&) = delete;

  ros::CallbackQueue* queue()
  {
    return &queue_;
  }

private:
  ros::CallbackQueue queue_;
  ros::AsyncSpinner spinner_;
};

}  // namespace ptz_action_server
