#include "ptz_action_server/ros/sim_camera_publisher.h"

#include <algorithm>
#include <chrono>
#include <cmath>

#include <sensor_msgs/image_encodings.h>

namespace ptz_action_server
{
namespace
{
/// s the idle thread waits for a (dis)connect callback before it looks again; shutdown wakes it at once.
constexpr double IDLE_WAIT = 3600.0;
/// s a new tf listener may take to hear the frames before a missing one is logged.
constexpr double TF_WARM_UP = 3.0;
constexpr double TF_CACHE_TIME = 2.0;  ///< s of tf kept: the frames are looked up at their latest
}  // namespace

SimCameraPublisher::SimCameraPublisher(const ros::NodeHandle& node_handle, const SimCameraSettings& settings,
                                       const PtzKinematics& kinematics, std::shared_ptr<PtzBackend> backend)
  : settings_(settings)
  , lens_(settings_.lens.value())
  , kinematics_(kinematics)
  , backend_(std::move(backend))
  , node_handle_(node_handle)
{
  node_handle_.setCallbackQueue(&queue_);
  markers_.resize(settings_.frames.size());
  for (std::size_t index = 0; index < markers_.size(); ++index)
  {
    markers_[index].name = settings_.frames[index];
  }
  reported_missing_.assign(markers_.size(), false);

  image_.header.frame_id = settings_.frame_id;
  image_.width = static_cast<std::uint32_t>(settings_.width);
  image_.height = static_cast<std::uint32_t>(settings_.height);
  image_.encoding = sensor_msgs::image_encodings::RGB8;
  image_.step = image_.width * 3;
  info_.header.frame_id = settings_.frame_id;
  info_.width = image_.width;
  info_.height = image_.height;
  info_.distortion_model = "plumb_bob";
  info_.D.assign(5, 0.0);
  info_.R = { 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 };

  // The callbacks only wake the thread (they run on its queue): it reads the subscriber count itself.
  const auto woken = [](const image_transport::SingleSubscriberPublisher&) {};
  const auto info_woken = [](const ros::SingleSubscriberPublisher&) {};
  transport_ = std::make_unique<image_transport::ImageTransport>(node_handle_);
  publisher_ = transport_->advertiseCamera("image_raw", 1, woken, woken, info_woken, info_woken);
  thread_ = std::thread([this] { run(); });
}

SimCameraPublisher::~SimCameraPublisher()
{
  stopping_ = true;
  queue_.disable();  // wakes the thread's wait
  thread_.join();
  stopListening();
  publisher_.shutdown();
}

bool SimCameraPublisher::watched() const
{
  return publisher_.getNumSubscribers() > 0;
}

void SimCameraPublisher::run()
{
  using Clock = std::chrono::steady_clock;
  const auto period = std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(1.0 / settings_.rate));
  Clock::time_point next = Clock::now();
  while (!stopping_)
  {
    if (!watched())
    {
      stopListening();
      queue_.callAvailable(ros::WallDuration(IDLE_WAIT));
      next = Clock::now();
      continue;
    }
    listen();
    const Clock::time_point now = Clock::now();
    if (now < next)
    {
      // Until the frame is due: tf's messages, and a subscriber leaving, wake the wait.
      queue_.callAvailable(ros::WallDuration(std::chrono::duration<double>(next - now).count()));
      continue;
    }
    publishFrame();
    // On a grid of the period; a frame that took longer than that skips the ones it missed.
    next += period;
    if (next <= Clock::now())
    {
      next = Clock::now() + period;
    }
  }
}

void SimCameraPublisher::listen()
{
  if (tf_listener_ || markers_.empty())
  {
    return;
  }
  tf_buffer_ = std::make_unique<tf2_ros::Buffer>(ros::Duration(TF_CACHE_TIME));
  // No thread of its own: its messages come on this thread's queue.
  tf_listener_ = std::make_unique<tf2_ros::TransformListener>(*tf_buffer_, node_handle_, false);
  listening_since_ = ros::WallTime::now();
  reported_missing_.assign(markers_.size(), false);
}

void SimCameraPublisher::stopListening()
{
  tf_listener_.reset();
  tf_buffer_.reset();
}

void SimCameraPublisher::updateMarkers()
{
  if (!tf_buffer_)
  {
    return;
  }
  const bool warmed_up = (ros::WallTime::now() - listening_since_).toSec() >= TF_WARM_UP;
  for (std::size_t index = 0; index < markers_.size(); ++index)
  {
    SceneMarker& marker = markers_[index];
    try
    {
      const geometry_msgs::Vector3 position =
          tf_buffer_->lookupTransform(kinematics_.baseFrame(), marker.name, ros::Time(0)).transform.translation;
      marker.position = Eigen::Vector3d(position.x, position.y, position.z);
      marker.present = true;
      reported_missing_[index] = false;
    }
    catch (const tf2::TransformException& error)
    {
      marker.present = false;
      if (warmed_up && !reported_missing_[index])
      {
        reported_missing_[index] = true;
        ROS_WARN("camera: frame '%s' is not drawn: %s", marker.name.c_str(), error.what());
      }
    }
  }
}

void SimCameraPublisher::publishFrame()
{
  const PtzSample sample = backend_->sample();
  const double pan = sample.position[PAN];
  const double tilt = sample.position[TILT];
  if (!std::isfinite(pan) || !std::isfinite(tilt))
  {
    if (!reported_unknown_pose_)
    {
      reported_unknown_pose_ = true;
      ROS_WARN("camera: the device reports no pan or tilt: no image until it does");
    }
    return;
  }
  // A device without zoom reports 1 (the contract); the lens model clamps below its wide end.
  const double zoom = std::isfinite(sample.position[ZOOM]) ? sample.position[ZOOM] : 1.0;
  const PinholeIntrinsics intrinsics = intrinsicsFor(lens_.at(zoom), settings_.width, settings_.height);
  updateMarkers();
  // The pixels' buffer is made when the first image is, not before: a camera nobody watches costs no memory for it.
  image_.data.resize(static_cast<std::size_t>(image_.step) * image_.height);
  cv::Mat image(settings_.height, settings_.width, CV_8UC3, image_.data.data(), image_.step);
  renderer_.render(kinematics_.cameraInBase(pan, tilt), intrinsics, markers_, image);

  const ros::Time stamp = toRosTime(sample.stamp);
  image_.header.stamp = stamp;
  info_.header.stamp = stamp;
  info_.K = { intrinsics.fx, 0.0, intrinsics.cx, 0.0, intrinsics.fy, intrinsics.cy, 0.0, 0.0, 1.0 };
  info_.P = { intrinsics.fx, 0.0, intrinsics.cx, 0.0, 0.0, intrinsics.fy, intrinsics.cy, 0.0, 0.0, 0.0, 1.0, 0.0 };
  publisher_.publish(image_, info_);
}

ros::Time SimCameraPublisher::toRosTime(TimePoint stamp) const
{
  // As the state tick stamps joint_states: the sample's age taken from ROS time now.
  const double age = std::max(0.0, secondsBetween(stamp, clock_.now()));
  return ros::Time::now() - ros::Duration(age);
}

}  // namespace ptz_action_server
