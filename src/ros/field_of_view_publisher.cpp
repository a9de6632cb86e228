#include "ptz_action_server/ros/field_of_view_publisher.h"

#include <utility>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
FieldOfViewPublisher::FieldOfViewPublisher(ros::NodeHandle node_handle, const FieldOfViewSettings& settings,
                                           std::shared_ptr<PtzBackend> backend, const std::string& camera_frame)
  : settings_(settings), model_(settings_.model.value()), backend_(std::move(backend))
{
  field_of_view_message_.header.frame_id = camera_frame;
  field_of_view_publisher_.advertise<ptz_action_server::FieldOfView>(node_handle, "field_of_view", 10);
  if (!settings_.camera_info_topic.empty())
  {
    camera_info_publisher_ =
        node_handle.advertise<sensor_msgs::CameraInfo>(settings_.camera_info_topic + "_zoomed", 10);
    camera_info_subscriber_ =
        node_handle.subscribe(settings_.camera_info_topic, 10, &FieldOfViewPublisher::onCameraInfo, this);
  }
}

bool FieldOfViewPublisher::publish(const ros::Time& stamp, double zoom)
{
  if (!field_of_view_publisher_.listened())
  {
    return false;
  }
  const FieldOfViewAngles angles = model_.at(zoom);
  field_of_view_message_.header.stamp = stamp;
  field_of_view_message_.horizontal = angles.horizontal;
  field_of_view_message_.vertical = angles.vertical;
  field_of_view_message_.zoom = zoom;
  return field_of_view_publisher_.publish(field_of_view_message_);
}

void FieldOfViewPublisher::onCameraInfo(const sensor_msgs::CameraInfo::ConstPtr& info)
{
  // The zoom now, not the one of the last tick: sample() only reads the backend's snapshot.
  const double zoom = backend_->sample().position[ZOOM];
  {
    std::lock_guard<std::mutex> lock(calibration_mutex_);
    if (info->K[0] > 0.0 && info->K[4] > 0.0 && info->width > 0 && info->height > 0)
    {
      PinholeIntrinsics intrinsics;
      intrinsics.width = static_cast<int>(info->width);
      intrinsics.height = static_cast<int>(info->height);
      intrinsics.fx = info->K[0];
      intrinsics.fy = info->K[4];
      intrinsics.cx = info->K[2];
      intrinsics.cy = info->K[5];
      calibration_ = CalibratedIntrinsics{ intrinsics, settings_.camera_info_zoom };
    }
    else
    {
      calibration_.reset();
    }
  }
  camera_info_message_ = *info;  // assigning into the kept message reuses its strings' and D's storage
  rescale(camera_info_message_, model_.focalScale(settings_.camera_info_zoom, zoom));
  camera_info_publisher_.publish(camera_info_message_);
}

std::optional<CalibratedIntrinsics> FieldOfViewPublisher::calibration() const
{
  std::lock_guard<std::mutex> lock(calibration_mutex_);
  return calibration_;
}

void FieldOfViewPublisher::rescale(sensor_msgs::CameraInfo& info, const FocalScale& scale)
{
  // K = [fx s cx; 0 fy cy; 0 0 1]; P = [fx' s cx' Tx; 0 fy' cy' Ty; 0 0 1 0], with Tx = -fx' B and Ty = -fy' B
  // (stereo baseline B): the focal terms scale, the principal point stays.
  info.K[0] *= scale.x;
  info.K[1] *= scale.x;
  info.K[4] *= scale.y;
  info.P[0] *= scale.x;
  info.P[1] *= scale.x;
  info.P[3] *= scale.x;
  info.P[5] *= scale.y;
  info.P[7] *= scale.y;
}

}  // namespace ptz_action_server
