/**
 * \file
 * \brief The field_of_view topic and the zoomed copy of the image driver's camera_info.
 */
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <ros/ros.h>
#include <sensor_msgs/CameraInfo.h>

#include "ptz_action_server/FieldOfView.h"
#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/motion/pixel_aim.h"
#include "ptz_action_server/ros/listened_publisher.h"
#include "ptz_action_server/ros/view_config.h"

namespace ptz_action_server
{
/**
 * \brief Publishes the field of view at the current zoom on each state tick and, if a camera_info topic is set,
 * republishes each camera_info rescaled for the zoom at that moment.
 *
 * Runs on the queue of the node handle it is given (the state publisher's): the camera_info callback stays off the
 * main queue. Both messages are kept and reused, so neither path allocates once the first camera_info is in. The
 * incoming camera_info's calibration is kept too, for aiming at its pixels (calibration()).
 */
class FieldOfViewPublisher
{
public:
  /// Advertises field_of_view and, with a camera_info topic, subscribes to it and advertises <topic>_zoomed, all in
  /// \p node_handle's namespace. \p settings must hold a model; field_of_view is stamped in \p camera_frame.
  FieldOfViewPublisher(ros::NodeHandle node_handle, const FieldOfViewSettings& settings,
                       std::shared_ptr<PtzBackend> backend, const std::string& camera_frame);

  /// One state tick: the field of view at \p zoom, stamped \p stamp (joint_states' stamp), if someone listens;
  /// returns whether it was sent.
  bool publish(const ros::Time& stamp, double zoom);

  /// The latest incoming camera_info's K (fx, fy, cx, cy) and size, calibrated at camera_info_zoom; none before one
  /// came, or while it holds no calibration (focal lengths or size not positive, as uncalibrated drivers send). Any
  /// thread.
  std::optional<CalibratedIntrinsics> calibration() const;

  /// Rescales \p info in place from \p scale: fx, fy (and skew, Tx, Ty) in K and P; principal point unchanged.
  static void rescale(sensor_msgs::CameraInfo& info, const FocalScale& scale);

private:
  void onCameraInfo(const sensor_msgs::CameraInfo::ConstPtr& info);

  const FieldOfViewSettings settings_;
  const FieldOfViewModel& model_;  ///< settings_.model's value
  const std::shared_ptr<PtzBackend> backend_;
  ListenedPublisher field_of_view_publisher_;
  ptz_action_server::FieldOfView field_of_view_message_;
  ros::Subscriber camera_info_subscriber_;
  ros::Publisher camera_info_publisher_;
  sensor_msgs::CameraInfo camera_info_message_;  ///< the rescaled copy, reused
  mutable std::mutex calibration_mutex_;
  std::optional<CalibratedIntrinsics> calibration_;  ///< of the latest incoming camera_info
};

}  // namespace ptz_action_server
