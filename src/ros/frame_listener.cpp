#include "ptz_action_server/ros/frame_listener.h"

namespace ptz_action_server
{
namespace
{
constexpr double FRAME_LOOKUP_CACHE_TIME = 10.0;  ///< s of tf history kept for frame goals
}  // namespace

FrameListener::FrameListener(const ros::NodeHandle& node_handle, double listen_time, double warm_up)
  : node_handle_(node_handle)
  , listen_time_(listen_time)
  , warm_up_(warm_up)
  , quiet_timer_(node_handle_.getCallbackQueue(), [this] { stopListening(); })
{
}

void FrameListener::listen()
{
  if (!listener_)
  {
    buffer_ = std::make_unique<tf2_ros::Buffer>(ros::Duration(FRAME_LOOKUP_CACHE_TIME));
    // No dedicated thread: tf2_ros polls its queue every 10 ms, which alone costs more than the idle budget.
    listener_ = std::make_unique<tf2_ros::TransformListener>(*buffer_, node_handle_, false);
    listening_since_ = ros::SteadyTime::now();
    ROS_DEBUG("listening to tf for frame goals");
  }
  // Starting the one-shot timer again replaces (and stops) the old countdown.
  quiet_timer_.startOnce(listen_time_);
}

bool FrameListener::ready(const std::string& base_frame, const std::string& frame_id) const
{
  if (!listener_)
  {
    return false;
  }
  return (ros::SteadyTime::now() - listening_since_).toSec() >= warm_up_ ||
         buffer_->canTransform(base_frame, frame_id, ros::Time(0));
}

void FrameListener::stopListening()
{
  listener_.reset();
  buffer_.reset();
  ROS_DEBUG("no frame goal for %.1f s: stopped listening to tf", listen_time_);
}

}  // namespace ptz_action_server
