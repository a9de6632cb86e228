#include "ptz_action_server/ros/pixel_goals.h"

#include <cmath>
#include <limits>
#include <utility>

namespace ptz_action_server
{
PixelConfig PixelConfig::load(const ParamReader& params, const std::optional<FieldOfViewModel>& field_of_view)
{
  PixelConfig config;
  config.image_upside_down = params.flag("image_upside_down", config.image_upside_down);
  config.image_topic_set = params.has("image_topic");
  config.image_topic = params.text("image_topic", config.image_topic);
  config.lens = field_of_view;
  const std::string way = params.choice("pixel_aim", pixelAimWayName(config.aim_way), { "auto", "computed", "device" });
  parsePixelAimWay(way, config.aim_way);
  return config;
}

PixelGoals::PixelGoals(const PtzKinematics& kinematics, const Capabilities& limits, const PoseRecorder& poses,
                       const PixelConfig& config, CalibrationSource calibration, std::string camera_info_topic)
  : kinematics_(kinematics)
  , limits_(limits)
  , poses_(poses)
  , config_(config)
  , calibration_(std::move(calibration))
  , camera_info_topic_(std::move(camera_info_topic))
{
}

ConvertedGoal PixelGoals::convert(const PixelGoal& goal, const ros::Time& stamp, const PtzSample& current) const
{
  const PoseLookup pose = poses_.at(stamp);
  PixelCamera camera;
  camera.field_of_view = config_.lens ? &*config_.lens : nullptr;
  camera.image_upside_down = config_.image_upside_down;
  if (calibration_)
  {
    camera.calibration = calibration_();
  }
  const PixelAimChoice choice = choosePixelAim(config_.aim_way, goal, pose, current, camera, limits_);
  if (!choice.error.empty())
  {
    return ConvertedGoal::rejected(choice.error);
  }
  if (choice.device)
  {
    ConvertedGoal converted;
    converted.command.view = choice.target;
    converted.command.values.fill(std::numeric_limits<double>::quiet_NaN());  // the device's to know, told at the end
    converted.command.note = choice.note;
    return converted;
  }
  if (!pose.found())
  {
    return ConvertedGoal::rejected(pose.error);
  }
  std::string notes;
  if (calibration_ && !camera.calibration)
  {
    notes = "no calibrated camera_info on " + camera_info_topic_ +
            " yet: the pixels of the field of view, principal point at the centre";
  }
  const PixelAim aim = aimAtPixel(goal, pose.pose, camera, kinematics_, limits_);
  if (!aim.ok())
  {
    return ConvertedGoal::rejected(aim.error);
  }
  ConvertedGoal converted;
  GoalCommand& command = converted.command;
  command.values = { { aim.pan, aim.tilt, aim.zoom } };
  if (std::isnan(aim.zoom))
  {
    // The zoom stays where it is; 0 leaves it alone on a device that cannot position or report it (and is ignored on
    // one without zoom, as the seed says).
    const AxisCapability& zoom = limits_.axes[ZOOM];
    command.values[ZOOM] = zoom.present && zoom.absolute && zoom.feedback ? current.position[ZOOM] : 0.0;
  }
  if (!aim.notes.empty())
  {
    notes += (notes.empty() ? "" : "; ") + aim.notes;
  }
  command.note = std::move(notes);
  return converted;
}

}  // namespace ptz_action_server
