#include "ptz_action_server/ros/goal_translator.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <optional>

#include <tf2/exceptions.h>
#include <tf2_eigen/tf2_eigen.h>

#include "ptz_action_server/core/capabilities.h"
#include "ptz_action_server/core/goal/goal_validation.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
GoalTranslator::GoalTranslator(const PtzKinematics& kinematics, const Capabilities& limits, const FrameListener& frames,
                               const PresetServices& presets, const PixelGoals& pixels)
  : kinematics_(kinematics), limits_(limits), frames_(frames), presets_(presets), pixels_(pixels)
{
}

ConvertedGoal GoalTranslator::convert(const PtzGoal& goal, ActionKind kind, const PtzSample& current) const
{
  const AxisValues values{ { goal.pan, goal.tilt, goal.zoom } };
  ConvertedGoal converted;
  GoalCommand& command = converted.command;
  switch (kind)
  {
    case ActionKind::POSITION_REL: {
      std::string reason = findNonFinite(values, "offset");
      command.values = values;
      for (Axis axis : ALL_AXES)
      {
        const AxisCapability& capability = limits_.axes[axis];
        if (capability.present && capability.feedback)
        {
          command.values[axis] += current.position[axis];
        }
        else if (axis == ZOOM && !capability.present)
        {
          // The seed: "if the camera does not support zoom ... the zoom field is ignored".
          if (values[axis] != 0.0)
          {
            command.note =
                formatText("zoom offset %.4f X ignored: %s", values[axis],
                           capability.limitation.empty() ? "the device has no zoom" : capability.limitation.c_str());
          }
          command.values[axis] = 0.0;
        }
        else if (values[axis] != 0.0 && reason.empty())
        {
          reason = findUnsupported(limits_, axis, AxisRequest::OFFSET);
        }
        else
        {
          command.values[axis] = axis == ZOOM ? 0.0 : values[axis];  // zoom 0: left alone (leavesAxisAlone())
        }
      }
      converted.rejection = reason;
      break;
    }
    case ActionKind::VELOCITY:
      command.velocity = true;
      command.values = values;
      converted.rejection = findNonFinite(values, "velocity");
      break;
    default:
      command.values = values;
      converted.rejection = findNonFinite(values, "position");
  }
  return converted;
}

ConvertedGoal GoalTranslator::convert(const PtzRelToGoal& goal, ActionKind, const PtzSample&) const
{
  ConvertedGoal converted;
  GoalCommand& command = converted.command;
  std::string reason = findNonFinite({ { goal.pan, goal.tilt, goal.zoom } }, "position");
  Eigen::Isometry3d frame_in_base = Eigen::Isometry3d::Identity();
  if (reason.empty())
  {
    reason = lookupFrame(goal.frame_id, frame_in_base);
  }
  if (!reason.empty())
  {
    return ConvertedGoal::rejected(reason);
  }
  // The goal's pan and tilt follow the contract's convention in the axes of frame_id.
  const Eigen::Vector3d in_base = frame_in_base.linear() * directionOf(goal.pan, goal.tilt);
  command.values[ZOOM] = goal.zoom;
  if (!kinematics_.aimAlong(in_base, command.values[PAN], command.values[TILT]))
  {
    return ConvertedGoal::rejected("no pan and tilt aim the camera along that direction of '" + goal.frame_id + "'");
  }
  return converted;
}

ConvertedGoal GoalTranslator::convert(const PtzFrameGoal& goal, ActionKind kind, const PtzSample&) const
{
  ConvertedGoal converted;
  GoalCommand& command = converted.command;
  command.track = kind == ActionKind::TRACK_FRAME;
  std::string reason = findNonFinite({ { 0.0, 0.0, goal.zoom } }, "position");
  Eigen::Isometry3d frame_in_base = Eigen::Isometry3d::Identity();
  if (reason.empty())
  {
    reason = lookupFrame(goal.frame_id, frame_in_base);
  }
  if (!reason.empty())
  {
    return ConvertedGoal::rejected(reason);
  }
  command.values[ZOOM] = goal.zoom;
  if (!kinematics_.aimAt(frame_in_base.translation(), command.values[PAN], command.values[TILT]))
  {
    return ConvertedGoal::rejected("cannot point at the origin of '" + goal.frame_id +
                                   "': it is too close to the camera");
  }
  return converted;
}

ConvertedGoal GoalTranslator::convert(const PtzPresetGoal& goal, ActionKind, const PtzSample&) const
{
  const std::optional<AxisValues> pose = presets_.find(goal.name);
  if (!pose)
  {
    return ConvertedGoal::rejected("no preset named '" + goal.name + "'");
  }
  ConvertedGoal converted;
  converted.command.values = *pose;
  converted.command.speed.fraction = presets_.speed(goal.name);
  return converted;
}

ConvertedGoal GoalTranslator::convert(const PtzSpeedGoal& goal, ActionKind, const PtzSample&) const
{
  ConvertedGoal converted;
  GoalCommand& command = converted.command;
  command.values = { { goal.pan, goal.tilt, goal.zoom } };
  converted.rejection = findNonFinite(command.values, "position");
  command.speed.fraction = goal.speed;
  command.speed.rate = { { goal.pan_speed, goal.tilt_speed, 0.0 } };
  return converted;
}

ConvertedGoal GoalTranslator::convert(const PtzPixelGoal& goal, ActionKind, const PtzSample& current) const
{
  PixelGoal pixel;
  pixel.u = goal.u;
  pixel.v = goal.v;
  pixel.box_width = goal.box_width;
  pixel.box_height = goal.box_height;
  pixel.image_width = static_cast<int>(std::min<std::uint32_t>(goal.image_width, 1U << 30));
  pixel.image_height = static_cast<int>(std::min<std::uint32_t>(goal.image_height, 1U << 30));
  pixel.distance = goal.distance;
  return pixels_.convert(pixel, goal.image_header.stamp, current);
}

void GoalTranslator::fillResult(PtzPixelResult& result, const ConvertedGoal& converted)
{
  const AxisValues& aim = converted.command.values;
  const bool aimed = converted.rejection.empty();
  result.pan = aimed ? static_cast<float>(aim[PAN]) : std::numeric_limits<float>::quiet_NaN();
  result.tilt = aimed ? static_cast<float>(aim[TILT]) : std::numeric_limits<float>::quiet_NaN();
  result.zoom = aimed ? static_cast<float>(aim[ZOOM]) : std::numeric_limits<float>::quiet_NaN();
}

ConvertedGoal GoalTranslator::convert(const geometry_msgs::PointStamped& point, const PtzSample& current) const
{
  const Eigen::Vector3d in_frame(point.point.x, point.point.y, point.point.z);
  if (!in_frame.allFinite())
  {
    return ConvertedGoal::rejected("the point is not finite");
  }
  Eigen::Isometry3d frame_in_base = Eigen::Isometry3d::Identity();
  const std::string reason = lookupFrame(point.header.frame_id, frame_in_base);
  if (!reason.empty())
  {
    return ConvertedGoal::rejected(reason);
  }
  ConvertedGoal converted;
  GoalCommand& command = converted.command;
  // The zoom stays where it is (0: left alone on a device that cannot position or report it).
  const AxisCapability& zoom = limits_.axes[ZOOM];
  command.values[ZOOM] = zoom.present && zoom.absolute && zoom.feedback ? current.position[ZOOM] : 0.0;
  if (!kinematics_.aimAt(frame_in_base * in_frame, command.values[PAN], command.values[TILT]))
  {
    return ConvertedGoal::rejected("cannot point at it: it is too close to the camera");
  }
  return converted;
}

std::string GoalTranslator::lookupFrame(const std::string& frame_id, Eigen::Isometry3d& frame_in_base) const
{
  if (frame_id.empty())
  {
    return "frame_id is empty";
  }
  try
  {
    // Time 0: the latest transform, without waiting, so other goals are never held up.
    frame_in_base =
        tf2::transformToEigen(frames_.buffer().lookupTransform(kinematics_.baseFrame(), frame_id, ros::Time(0)));
  }
  catch (const tf2::TransformException& error)
  {
    return "frame '" + frame_id + "' is unknown to tf: " + error.what();
  }
  return {};
}

}  // namespace ptz_action_server
