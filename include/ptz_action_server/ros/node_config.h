/**
 * \file
 * \brief The node's own settings, read once from its parameters.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/goal/goal_monitor.h"
#include "ptz_action_server/core/motion/frame_tracker.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/mounted_backend.h"
#include "ptz_action_server/ros/detection_tracking.h"
#include "ptz_action_server/ros/lens_interface.h"
#include "ptz_action_server/ros/look_at_clicked_point.h"
#include "ptz_action_server/ros/velocity_topic.h"
#include "ptz_action_server/ros/param_reader.h"
#include "ptz_action_server/ros/pixel_goals.h"
#include "ptz_action_server/ros/preset_services.h"
#include "ptz_action_server/ros/tour_services.h"
#include "ptz_action_server/ros/view_config.h"

namespace ptz_action_server
{
/// The node's own settings (the backend reads its own under ~<backend>/).
struct NodeConfig
{
  std::string backend = "sim";       ///< plugin name; "sim" means "ptz_action_server/sim"
  bool clamp_goals = false;          ///< clamp out-of-range goals instead of rejecting them
  bool publish_tf = true;            ///< false: leave tf to robot_state_publisher (joint_states still published)
  KinematicsNames names;             ///< URDF joint and link names
  GoalMonitorConfig monitor;         ///< tolerances, stall and timeout rules
  int action_queue_size = 2000;      ///< actionlib goal/cancel subscriber and publisher queues
  double status_list_timeout = 1.0;  ///< s a finished goal stays in actionlib's status list (actionlib: 5)
  double frame_listen_time = 10.0;   ///< s the node keeps listening to tf after the last frame goal
  double frame_wait = 1.0;           ///< s a frame goal may wait for tf once the node starts listening
  FrameTrackerConfig track;          ///< how track_frame and track_detections goals steer
  DetectionTrackingSettings detection_tracking;  ///< track_detections' lost timeout and pose history
  double status_hold = 0.02;                     ///< s goal status changes wait after a new goal (StatusHold); 0: off
  MountConfig mount;                             ///< how the device is mounted; PtzNode wraps the backend with it
  /// The field_of_view topic and the zoomed camera_info.
  FieldOfViewSettings field_of_view;
  PresetConfig presets;                            ///< the presets file and home
  LensInterfaceConfig lens;                        ///< the focus and iris topics
  TourConfig tours;                                ///< the tours file, resuming tours, the idle return
  LookAtClickedPointConfig look_at_clicked_point;  ///< "look here" from rviz
  PixelConfig pixel;                               ///< aiming at pixels: the picture's lens, clicks on it
  VelocityTopicConfig cmd_velocity;                ///< the cmd/velocity stream
  /// The node's private namespace (/left/ptz_action_server): its name in the diagnostics, as a process or a nodelet.
  std::string node_name;

  /// Reads ~backend, ~clamp_goals, ~publish_tf, ~pan_joint, ~tilt_joint, ~camera_link, ~tolerance/*, ~stall_timeout,
  /// ~goal_timeout, ~goal_timeout_scale, ~goal_timeout_margin, ~stop_timeout, ~action_queue_size,
  /// ~status_list_timeout, ~frame_listen_time, ~frame_wait, ~track/rate, ~track/gain, ~track/feed_forward,
  /// ~track_timeout, ~track/lost_timeout, ~track/pose_history, ~status_hold, ~mount, ~pan_offset, ~field_of_view/*,
  /// ~camera_info_topic, ~camera_info_zoom, ~look_at_clicked_point, ~clicked_point_topic, ~image_upside_down,
  /// ~image_topic, ~cmd_velocity/*, the presets' (see PresetConfig::load) and the tours' (TourConfig::load).
  static NodeConfig load(const ParamReader& params);
};

}  // namespace ptz_action_server
