#include "ptz_action_server/ros/shared_transforms.h"

#include <set>
#include <string>

#include "ptz_action_server/core/process_shared.h"

namespace ptz_action_server
{
std::shared_ptr<SharedTransforms> SharedTransforms::shared()
{
  return processShared<SharedTransforms>();
}

SharedTransforms::SharedTransforms()
  : static_publisher_(node_handle_.advertise<tf2_msgs::TFMessage>("/tf_static", 100, true))
{
  publisher_.advertise<tf2_msgs::TFMessage>(node_handle_, "/tf", 100);
}

bool SharedTransforms::send(const std::vector<geometry_msgs::TransformStamped>& transforms)
{
  if (!publisher_.listened())
  {
    return false;
  }
  std::lock_guard<std::mutex> lock(send_mutex_);
  message_.transforms.assign(transforms.begin(), transforms.end());
  return publisher_.publish(message_);
}

void SharedTransforms::setStatic(const void* owner, const std::vector<geometry_msgs::TransformStamped>& transforms)
{
  std::lock_guard<std::mutex> lock(mutex_);
  statics_[owner] = transforms;
  publishStaticLocked();
}

void SharedTransforms::removeStatic(const void* owner)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (statics_.erase(owner) > 0)
  {
    publishStaticLocked();
  }
}

void SharedTransforms::publishStaticLocked()
{
  // Cameras on one robot description each name all of its fixed joints: each child frame goes in once.
  static_message_.transforms.clear();
  std::set<std::string> children;
  for (const auto& entry : statics_)
  {
    for (const geometry_msgs::TransformStamped& transform : entry.second)
    {
      if (children.insert(transform.child_frame_id).second)
      {
        static_message_.transforms.push_back(transform);
      }
    }
  }
  static_publisher_.publish(static_message_);
}

}  // namespace ptz_action_server
