/**
 * \file
 * \brief A function posted to a ros::CallbackQueue: how one thread hands work to the thread that serves the queue.
 */
#pragma once

#include <functional>
#include <utility>

#include <ros/callback_queue_interface.h>

namespace ptz_action_server
{
/// Runs a function once, on whichever thread serves the queue it was added to.
class FunctionCallback : public ros::CallbackInterface
{
public:
  explicit FunctionCallback(std::function<void()> function) : function_(std::move(function))
  {
  }
  CallResult call() override
  {
    function_();
    return Success;
  }

private:
  std::function<void()> function_;
};

}  // namespace ptz_action_server
