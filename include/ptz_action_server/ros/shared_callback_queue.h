/**
 * \file
 * \brief A callback queue and one spinner thread shared by every camera in a process, for the services that may
 * block on a file (preset saves write and fsync before they answer).
 */
#pragma once

#include <atomic>
#include <memory>
#include <thread>

#include <ros/callback_queue.h>

namespace ptz_action_server
{
/**
 * \brief The process's queue for slow services: one thread for all cameras instead of a spinner per camera.
 *
 * Its callbacks run one at a time, off every camera's goal queue and the state tick; the thread sleeps until one comes.
 * An owner shuts its services down before it lets go of the queue (roscpp then waits for a callback of that service
 * in progress), and never from one of the queue's callbacks.
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
  void run();

  std::atomic<bool> stopping_{ false };
  ros::CallbackQueue queue_;
  std::thread thread_;  ///< last: runs on the members above
};

}  // namespace ptz_action_server
