// ptz_aim_marker: an interactive marker around the camera that aims it. Drag the ring about z (pan) or the ring about
// the camera's y (tilt) in rviz; the node sends move_ptz/position_abs goals while dragging (at most ~rate per second)
// and one when the drag ends. Otherwise the marker follows ptz_state. Runs in the camera's namespace, as the node does.
//
// Parameters (private): base_frame (ptz_base_link), camera_link (ptz_camera_link): the marker's frame and the link it
// sits on; scale (0.15 m, 0.01..100); rate (4 goals/s while dragging, 0..100; 0: only on release).
#include <cmath>
#include <string>

#include <actionlib/client/simple_action_client.h>
#include <interactive_markers/interactive_marker_server.h>
#include <ros/ros.h>
#include <tf2_ros/buffer.h>
#include <tf2_ros/transform_listener.h>
#include <visualization_msgs/InteractiveMarker.h>
#include <visualization_msgs/InteractiveMarkerFeedback.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzState.h"
#include "ptz_action_server/core/types.h"
#include "ptz_action_server/panel/panel_model.h"
#include "ptz_action_server/ros/param_reader.h"

namespace
{
using ptz_action_server::panel::Aim;
using ptz_action_server::panel::Quaternion;
using visualization_msgs::InteractiveMarkerControl;
using visualization_msgs::InteractiveMarkerFeedback;

constexpr const char* MARKER = "aim";
constexpr double FOLLOW_TOLERANCE = 1e-3;  // rad: smaller changes of ptz_state do not move the marker

geometry_msgs::Quaternion toMessage(const Quaternion& q)
{
  geometry_msgs::Quaternion message;
  message.x = q.x;
  message.y = q.y;
  message.z = q.z;
  message.w = q.w;
  return message;
}

/// A ring control about the axis its orientation turns x onto.
InteractiveMarkerControl ring(const std::string& name, double x, double y, double z, double w, uint8_t mode)
{
  InteractiveMarkerControl control;
  control.name = name;
  const double norm = std::sqrt(x * x + y * y + z * z + w * w);
  control.orientation.x = x / norm;
  control.orientation.y = y / norm;
  control.orientation.z = z / norm;
  control.orientation.w = w / norm;
  control.orientation_mode = mode;
  control.interaction_mode = InteractiveMarkerControl::ROTATE_AXIS;
  return control;
}

/// The node's parameters, read and checked once.
struct AimMarkerConfig
{
  std::string base_frame;   ///< the marker's frame
  std::string camera_link;  ///< where it sits
  double scale = 0.15;      ///< m
  double rate = 4.0;        ///< goals per second while dragging; 0: only on release

  static AimMarkerConfig load(const ptz_action_server::ParamReader& params)
  {
    AimMarkerConfig config;
    config.base_frame = params.text("base_frame", "ptz_base_link");
    config.camera_link = params.text("camera_link", "ptz_camera_link");
    config.scale = params.number("scale", config.scale, 0.01, 100.0);
    config.rate = params.number("rate", config.rate, 0.0, 100.0);
    return config;
  }
};

class AimMarker
{
public:
  explicit AimMarker(const AimMarkerConfig& config)
    : base_frame_(config.base_frame)
    , camera_link_(config.camera_link)
    , scale_(config.scale)
    , limiter_(config.rate > 0.0 ? 1.0 / config.rate : 0.0)
    , client_(node_, "move_ptz/position_abs", false)
    , server_("aim_marker")
    , listener_(buffer_)
  {
    insertMarker();
    state_subscriber_ = node_.subscribe("ptz_state", 1, &AimMarker::onState, this);
  }

private:
  void insertMarker()
  {
    visualization_msgs::InteractiveMarker marker;
    marker.header.frame_id = base_frame_;
    marker.name = MARKER;
    marker.description = "aim " + node_.getNamespace();
    marker.scale = static_cast<float>(scale_);
    marker.pose.orientation.w = 1.0;

    // The optical axis, always shown.
    InteractiveMarkerControl axis;
    axis.name = "optical_axis";
    axis.always_visible = true;
    axis.interaction_mode = InteractiveMarkerControl::NONE;
    visualization_msgs::Marker arrow;
    arrow.type = visualization_msgs::Marker::ARROW;
    arrow.scale.x = scale_ * 1.2;
    arrow.scale.y = scale_ * 0.05;
    arrow.scale.z = scale_ * 0.05;
    arrow.color.r = 1.0f;
    arrow.color.g = 0.6f;
    arrow.color.b = 0.1f;
    arrow.color.a = 0.9f;
    axis.markers.push_back(arrow);
    marker.controls.push_back(axis);
    // Pan: about the base frame's z, the ring stays level. Tilt: about the camera's own y, turning with the pan.
    marker.controls.push_back(ring("pan", 0.0, 1.0, 0.0, 1.0, InteractiveMarkerControl::FIXED));
    marker.controls.push_back(ring("tilt", 0.0, 0.0, 1.0, 1.0, InteractiveMarkerControl::INHERIT));

    server_.insert(marker, [this](const InteractiveMarkerFeedback::ConstPtr& feedback) { onFeedback(feedback); });
    server_.applyChanges();
  }

  void onFeedback(const InteractiveMarkerFeedback::ConstPtr& feedback)
  {
    switch (feedback->event_type)
    {
      case InteractiveMarkerFeedback::MOUSE_DOWN:
        dragging_ = true;
        limiter_.reset();
        break;
      case InteractiveMarkerFeedback::POSE_UPDATE:
        if (dragging_ && limiter_.allow(ros::WallTime::now().toSec()))
        {
          sendGoal(feedback->pose.orientation);
        }
        break;
      case InteractiveMarkerFeedback::MOUSE_UP:
        dragging_ = false;
        sendGoal(feedback->pose.orientation);
        break;
      default:
        break;
    }
  }

  void sendGoal(const geometry_msgs::Quaternion& orientation)
  {
    const Aim aim =
        ptz_action_server::panel::aimOfOrientation({ orientation.x, orientation.y, orientation.z, orientation.w });
    ptz_action_server::PtzGoal goal;
    goal.pan = static_cast<float>(aim.pan);
    goal.tilt = static_cast<float>(aim.tilt);
    // Keep the zoom where it is (1, which every device takes, until a ptz_state says otherwise).
    goal.zoom = static_cast<float>(std::isfinite(zoom_) ? zoom_ : 1.0);
    client_.sendGoal(goal);
  }

  void onState(const ptz_action_server::PtzState& state)
  {
    zoom_ = state.zoom;
    if (dragging_ || !std::isfinite(state.pan) || !std::isfinite(state.tilt))
    {
      return;
    }
    geometry_msgs::Pose pose;
    pose.orientation = toMessage(ptz_action_server::panel::orientationOfAim({ state.pan, state.tilt }));
    try
    {
      const geometry_msgs::TransformStamped camera = buffer_.lookupTransform(base_frame_, camera_link_, ros::Time(0));
      pose.position.x = camera.transform.translation.x;
      pose.position.y = camera.transform.translation.y;
      pose.position.z = camera.transform.translation.z;
    }
    catch (const tf2::TransformException&)
    {
      pose.position = last_position_;  // no tf yet: where it was
    }
    const bool moved =
        std::abs(state.pan - shown_.pan) > FOLLOW_TOLERANCE || std::abs(state.tilt - shown_.tilt) > FOLLOW_TOLERANCE ||
        std::abs(pose.position.x - last_position_.x) > 1e-4 || std::abs(pose.position.y - last_position_.y) > 1e-4 ||
        std::abs(pose.position.z - last_position_.z) > 1e-4;
    if (moved || !shown_any_)
    {
      shown_ = { state.pan, state.tilt };
      shown_any_ = true;
      last_position_ = pose.position;
      server_.setPose(MARKER, pose);
      server_.applyChanges();
    }
  }

  ros::NodeHandle node_;
  std::string base_frame_;
  std::string camera_link_;
  double scale_;
  ptz_action_server::panel::RateLimiter limiter_;
  actionlib::SimpleActionClient<ptz_action_server::PtzAction> client_;
  interactive_markers::InteractiveMarkerServer server_;
  tf2_ros::Buffer buffer_;
  tf2_ros::TransformListener listener_;
  ros::Subscriber state_subscriber_;
  bool dragging_ = false;
  double zoom_ = 1.0;
  Aim shown_;
  bool shown_any_ = false;
  geometry_msgs::Point last_position_;
};
}  // namespace

int main(int argc, char** argv)
{
  ros::init(argc, argv, "ptz_aim_marker");
  const ros::NodeHandle private_handle("~");
  AimMarkerConfig config;
  try
  {
    config = AimMarkerConfig::load(ptz_action_server::ParamReader(private_handle));
  }
  catch (const ptz_action_server::ConfigError& error)
  {
    ROS_FATAL("configuration error: %s", error.what());
    return 1;
  }
  AimMarker marker(config);
  ros::spin();
  return 0;
}
