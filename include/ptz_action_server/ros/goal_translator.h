/**
 * \file
 * \brief What each action's goal asks the device for: contract angles, tf frames and presets turned into a
 * GoalCommand, or the reason to reject the goal.
 */
#pragma once

#include <optional>
#include <string>

#include <Eigen/Geometry>
#include <geometry_msgs/PointStamped.h>

#include "ptz_action_server/PtzAction.h"
#include "ptz_action_server/PtzFrameAction.h"
#include "ptz_action_server/PtzPixelAction.h"
#include "ptz_action_server/PtzPresetAction.h"
#include "ptz_action_server/PtzRelToAction.h"
#include "ptz_action_server/PtzSpeedAction.h"
#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/ros/action_kind.h"
#include "ptz_action_server/ros/frame_listener.h"
#include "ptz_action_server/ros/pixel_goals.h"
#include "ptz_action_server/ros/preset_services.h"

namespace ptz_action_server
{
/**
 * \brief Converts the node's goals into the GoalSupervisor's commands, against the device's current sample, before
 * they are submitted.
 *
 * Frames are looked up once, at the latest transform, without waiting (a frame goal that must wait for tf waits
 * before it is converted: FrameGoalHold). One thread: the node's main queue.
 */
class GoalTranslator
{
public:
  /// \p frames, \p presets and \p pixels must outlive the translator. \p limits are the node's.
  GoalTranslator(const PtzKinematics& kinematics, const Capabilities& limits, const FrameListener& frames,
                 const PresetServices& presets, const PixelGoals& pixels);

  /// The tf frame a goal is expressed in, which it may have to wait for (FrameGoalHold); none for a goal without
  /// one.
  template <class Goal>
  static std::optional<std::string> frameOf(const Goal&)
  {
    return std::nullopt;
  }
  static std::optional<std::string> frameOf(const PtzRelToGoal& goal)
  {
    return goal.frame_id;
  }
  static std::optional<std::string> frameOf(const PtzFrameGoal& goal)
  {
    return goal.frame_id;
  }

  /// Each returns the goal's command, or the reason to reject it; \p current is the device's state.
  ConvertedGoal convert(const PtzGoal& goal, ActionKind kind, const PtzSample& current) const;
  ConvertedGoal convert(const PtzRelToGoal& goal, ActionKind kind, const PtzSample& current) const;
  ConvertedGoal convert(const PtzFrameGoal& goal, ActionKind kind, const PtzSample& current) const;
  ConvertedGoal convert(const PtzPresetGoal& goal, ActionKind kind, const PtzSample& current) const;
  /// position_abs with the goal's speed (GoalCommand::speed).
  ConvertedGoal convert(const PtzSpeedGoal& goal, ActionKind kind, const PtzSample& current) const;
  /// A pixel of an image: the camera's pose at the image's stamp (PixelGoals).
  ConvertedGoal convert(const PtzPixelGoal& goal, ActionKind kind, const PtzSample& current) const;
  /// A clicked point: the optical axis through it, the zoom where it is.
  ConvertedGoal convert(const geometry_msgs::PointStamped& point, const PtzSample& current) const;

  /// What an action's result says besides `success`, from its goal's conversion: nothing for most.
  template <class Result>
  static void fillResult(Result&, const ConvertedGoal&)
  {
  }
  /// Where a pixel goal aimed (its command before the limits: pan, tilt in rad, zoom in X, 0 where it is left alone);
  /// NaN when it was refused before it had an aim.
  static void fillResult(PtzPixelResult& result, const ConvertedGoal& converted);

private:
  /// The transform from \p frame_id to the base frame, looked up once without waiting; "" or the reason.
  std::string lookupFrame(const std::string& frame_id, Eigen::Isometry3d& frame_in_base) const;

  const PtzKinematics& kinematics_;
  const Capabilities& limits_;
  const FrameListener& frames_;
  const PresetServices& presets_;
  const PixelGoals& pixels_;
};

}  // namespace ptz_action_server
