#include <cmath>

#include <ros/console.h>

#include "ptz_action_server/core/types.h"
#include "ptz_action_server/ros/sim_camera_publisher.h"

namespace ptz_action_server
{
namespace
{
constexpr double DEFAULT_HORIZONTAL_FIELD = M_PI / 3.0;  ///< rad across at zoom 1 without a configured lens

/// ~camera/frames: a list of frame names.
std::vector<std::string> readFrames(const ParamReader& camera)
{
  XmlRpc::XmlRpcValue value;
  std::vector<std::string> frames;
  if (!camera.get("frames", value))
  {
    return frames;
  }
  const std::string shape = "a list of tf frame names, e.g. [ptz_demo_target]";
  if (value.getType() != XmlRpc::XmlRpcValue::TypeArray)
  {
    throw ConfigError("parameter " + camera.resolve("frames") + " must be " + shape);
  }
  for (int index = 0; index < value.size(); ++index)
  {
    if (value[index].getType() != XmlRpc::XmlRpcValue::TypeString || static_cast<std::string>(value[index]).empty())
    {
      throw ConfigError("parameter " + camera.resolve("frames") + ": item " + std::to_string(index) +
                        " is not a frame name; it must be " + shape);
    }
    std::string frame = static_cast<std::string>(value[index]);
    frames.push_back(frame.front() == '/' ? frame.substr(1) : frame);  // tf2 names have no leading slash
  }
  return frames;
}

/// The URDF's optical frame beside the camera link: PREFIXptz_camera_link's PREFIXptz_camera_optical_frame, or any
/// fixed child of the link with "optical" in its name; empty if there is none.
std::string opticalFrameOf(const PtzKinematics& kinematics)
{
  const std::string& link = kinematics.cameraFrame();
  const std::string suffix = "_link";
  std::string derived;
  if (link.size() > suffix.size() && link.compare(link.size() - suffix.size(), suffix.size(), suffix) == 0)
  {
    derived = link.substr(0, link.size() - suffix.size()) + "_optical_frame";
  }
  std::string any;
  for (const JointModel& joint : kinematics.fixedJoints())
  {
    if (joint.parent_link == link && joint.child_link == derived)
    {
      return derived;
    }
    if (joint.parent_link == link && any.empty() && joint.child_link.find("optical") != std::string::npos)
    {
      any = joint.child_link;
    }
  }
  return any;
}
}  // namespace

SimCameraSettings SimCameraSettings::load(const ParamReader& camera, bool enabled_by_default,
                                          const PtzKinematics& kinematics,
                                          const std::optional<FieldOfViewModel>& field_of_view)
{
  SimCameraSettings settings;
  settings.enabled = camera.flag("enabled", enabled_by_default);
  settings.width = camera.integer("width", settings.width, 16, 8192);
  settings.height = camera.integer("height", settings.height, 16, 8192);
  settings.rate = camera.number("rate", settings.rate, 0.1, 60.0);
  settings.frames = readFrames(camera);
  settings.render.marker_radius = camera.number("marker_radius", settings.render.marker_radius, 1e-4, 0.5);
  const std::string optical_frame = opticalFrameOf(kinematics);
  settings.frame_id = camera.text("frame_id", optical_frame);
  if (settings.enabled && settings.frame_id.empty())
  {
    throw ConfigError("the URDF has no optical frame beside " + kinematics.cameraFrame() + ": set " +
                      camera.resolve("frame_id") + " to the camera's optical frame (z forward, x right, y down)");
  }
  if (field_of_view)
  {
    settings.lens = field_of_view;
  }
  else
  {
    // Square pixels: the vertical angle whose tangent has the image's aspect.
    const double vertical =
        2.0 * std::atan(std::tan(DEFAULT_HORIZONTAL_FIELD / 2.0) * settings.height / settings.width);
    settings.lens = FieldOfViewModel::fromWideEnd({ DEFAULT_HORIZONTAL_FIELD, vertical });
    if (settings.enabled)
    {
      ROS_INFO("camera: no field_of_view configured: the simulated camera spans 60 degrees across at zoom 1, with "
               "square pixels (set ~field_of_view to change it)");
    }
  }
  return settings;
}

}  // namespace ptz_action_server
