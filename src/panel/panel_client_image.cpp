/**
 * \file
 * \brief PanelClient's picture: the image view's subscription (image_transport), each image converted once for
 * display (cv_bridge), the camera's recent views for drawing the aim, and the pixel goals (move_ptz/pixel) it sends
 * and those it hears.
 */
#include "ptz_action_server/panel/panel_client.h"

#include <image_transport/image_transport.h>

namespace ptz_action_server::panel
{
void PanelClient::subscribeImageParts(ros::NodeHandle& node, std::uint64_t generation)
{
  subscribers_.push_back(node.subscribe<FieldOfView>(
      "field_of_view", 10, [this, generation](const FieldOfView::ConstPtr& view) { onFieldOfView(generation, view); }));
  subscribers_.push_back(node.subscribe<PtzPixelActionGoal>(
      "move_ptz/pixel/goal", 10,
      [this, generation](const PtzPixelActionGoal::ConstPtr& goal) { onPixelGoal(generation, goal); }));
}

void PanelClient::setImageTopic(const std::string& topic)
{
  image_transport::Subscriber old_subscriber;  // ended after the lock, as setNamespace does with its subscriptions
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (topic == image_topic_)
    {
      return;
    }
    const std::uint64_t generation = ++image_generation_;
    image_topic_ = topic;
    latest_frame_.reset();
    image_message_ = topic.empty() ? "no image" : "waiting for " + topic;
    old_subscriber = image_subscriber_;
    image_subscriber_ = image_transport::Subscriber();
    if (!topic.empty())
    {
      ros::NodeHandle node;
      node.setCallbackQueue(&queue_);
      image_transport::ImageTransport transport(node);
      image_subscriber_ = transport.subscribe(
          topic, 1, [this, generation](const sensor_msgs::ImageConstPtr& image) { onImage(generation, image); });
    }
  }
  old_subscriber.shutdown();
}

std::shared_ptr<const ImageFrame> PanelClient::latestFrame() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return latest_frame_;
}

void PanelClient::setFrameListener(std::function<void()> listener)
{
  std::lock_guard<std::mutex> lock(listener_mutex_);
  frame_listener_ = std::move(listener);
}

std::optional<View> PanelClient::viewAt(double stamp) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return views_.at(stamp);
}

void PanelClient::onImage(std::uint64_t image_generation, const sensor_msgs::ImageConstPtr& image)
{
  auto frame = std::make_shared<ImageFrame>();
  const std::string error = toFrame(image, *frame);  // off the lock: the widget never waits for a conversion
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (image_generation != image_generation_)
    {
      return;
    }
    if (!error.empty())
    {
      image_message_ = image_topic_ + ": " + error;
      return;
    }
    image_message_.clear();
    latest_frame_ = std::move(frame);
  }
  std::lock_guard<std::mutex> lock(listener_mutex_);
  if (frame_listener_)
  {
    frame_listener_();
  }
}

void PanelClient::onFieldOfView(std::uint64_t generation, const FieldOfView::ConstPtr& view)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation == generation_)
  {
    views_.addFieldOfView(view->header.stamp.toSec(), view->horizontal, view->vertical);
  }
}

void PanelClient::onPixelGoal(std::uint64_t generation, const PtzPixelActionGoal::ConstPtr& goal)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (generation != generation_)
  {
    return;
  }
  PixelAim aim;
  aim.target = { goal->goal.u, goal->goal.v, goal->goal.box_width, goal->goal.box_height };
  aim.image_width = static_cast<int>(goal->goal.image_width);
  aim.image_height = static_cast<int>(goal->goal.image_height);
  if ((aim.image_width == 0 || aim.image_height == 0) && latest_frame_)
  {
    // A goal that leaves the size to the calibrated camera_info: the picture shown is the best guess of it.
    aim.image_width = latest_frame_->width;
    aim.image_height = latest_frame_->height;
  }
  aim.stamp = goal->goal.image_header.stamp.toSec();
  aim.goal_id = goal->goal_id.id;
  pixel_goals_.goalSent(aim, now());
}

void PanelClient::aimAtPixel(const ImageFrame& frame, const PixelBox& target)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if (!pixel_client_)
  {
    return;
  }
  PtzPixelGoal goal;
  goal.image_header.seq = frame.seq;
  goal.image_header.stamp = ros::Time(frame.stamp_sec, frame.stamp_nsec);
  goal.image_header.frame_id = frame.frame_id;
  goal.u = target.u;
  goal.v = target.v;
  goal.box_width = target.width;
  goal.box_height = target.height;
  goal.image_width = static_cast<std::uint32_t>(frame.width);
  goal.image_height = static_cast<std::uint32_t>(frame.height);
  pixel_client_->sendGoal(goal);
  jogging_ = false;  // the pixel goal preempts the velocity goal
}

}  // namespace ptz_action_server::panel
