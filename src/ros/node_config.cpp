#include "ptz_action_server/ros/node_config.h"

#include <algorithm>

namespace ptz_action_server
{
NodeConfig NodeConfig::load(const ParamReader& params)
{
  NodeConfig config;
  config.backend = params.text("backend", config.backend);
  config.clamp_goals = params.flag("clamp_goals", config.clamp_goals);
  config.publish_tf = params.flag("publish_tf", config.publish_tf);
  config.names.pan_joint = params.text("pan_joint", config.names.pan_joint);
  config.names.tilt_joint = params.text("tilt_joint", config.names.tilt_joint);
  config.names.camera_link = params.text("camera_link", config.names.camera_link);
  GoalMonitorConfig& monitor = config.monitor;
  monitor.tolerance[PAN] = params.number("tolerance/pan", monitor.tolerance[PAN], 1e-6, 0.5);
  monitor.tolerance[TILT] = params.number("tolerance/tilt", monitor.tolerance[TILT], 1e-6, 0.5);
  monitor.tolerance[ZOOM] = params.number("tolerance/zoom", monitor.tolerance[ZOOM], 1e-6, 10.0);
  monitor.stall_timeout = params.number("stall_timeout", monitor.stall_timeout, 0.05, 60.0);
  monitor.fixed_timeout = params.number("goal_timeout", monitor.fixed_timeout, 0.0, 3600.0);
  monitor.timeout_scale = params.number("goal_timeout_scale", monitor.timeout_scale, 1.0, 100.0);
  monitor.timeout_margin = params.number("goal_timeout_margin", monitor.timeout_margin, 0.0, 600.0);
  monitor.stop_timeout = params.number("stop_timeout", monitor.stop_timeout, 0.1, 60.0);
  config.action_queue_size = params.integer("action_queue_size", config.action_queue_size, 1, 100000);
  config.status_list_timeout = params.number("status_list_timeout", config.status_list_timeout, 0.1, 3600.0);
  config.frame_wait = params.number("frame_wait", config.frame_wait, 0.0, 60.0);
  config.status_hold = params.number("status_hold", config.status_hold, 0.0, 1.0);
  config.track.rate = params.number("track/rate", config.track.rate, 1.0, 200.0);
  config.track.gain = params.number("track/gain", config.track.gain, 0.0, 50.0);
  config.track.feed_forward = params.flag("track/feed_forward", config.track.feed_forward);
  config.track.timeout = params.number("track_timeout", config.track.timeout, 0.05, 3600.0);
  config.detection_tracking = DetectionTrackingSettings::load(params);
  config.frame_listen_time =
      params.number("frame_listen_time", config.frame_listen_time, std::max(config.frame_wait, 0.1), 1e6);
  config.mount = loadMountConfig(params);
  config.field_of_view = FieldOfViewSettings::load(params);
  config.presets = PresetConfig::load(params);
  config.lens = LensInterfaceConfig::load(params);
  config.tours = TourConfig::load(params, config.presets.file);
  config.look_at_clicked_point = LookAtClickedPointConfig::load(params);
  config.pixel = PixelConfig::load(params, config.field_of_view.model);
  config.cmd_velocity = VelocityTopicConfig::load(params);
  config.node_name = params.nodeHandle().getNamespace();
  return config;
}

}  // namespace ptz_action_server
