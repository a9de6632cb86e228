/**
 * \file
 * \brief Pixel goals (click to centre, drag to zoom) turned into position commands, from the camera's pose when the
 * image was taken.
 */
#pragma once

#include <functional>
#include <optional>
#include <string>

#include <ros/time.h>

#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/motion/field_of_view.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/motion/pixel_aim.h"
#include "ptz_action_server/core/motion/pixel_aim_choice.h"
#include "ptz_action_server/ros/param_reader.h"
#include "ptz_action_server/ros/pose_recorder.h"

namespace ptz_action_server
{
/// How the node aims at pixels: ~image_upside_down, ~image_topic, and the lens of the pictures.
struct PixelConfig
{
  /// The picture shows the world turned by half a turn (a camera mounted upside down that does not turn its picture
  /// itself): a click right of the centre then means left.
  bool image_upside_down = false;
  /// Clicks on <image_topic>_mouse_left centre their pixel (rqt_image_view's convention); "": none.
  std::string image_topic;
  bool image_topic_set = false;  ///< ~image_topic was given; else the simulated camera's image_raw when it draws
  /// The pictures' field of view: the node's (~field_of_view), or the simulated camera's lens when it draws without
  /// one. None: pixel goals are refused, naming the parameters to set.
  std::optional<FieldOfViewModel> lens;
  /// ~pixel_aim: who aims at a pixel, the node or the device's own command (choosePixelAim()).
  PixelAimWay aim_way = PixelAimWay::AUTO;

  /// Reads ~image_upside_down, ~image_topic and ~pixel_aim; the lens is \p field_of_view.
  static PixelConfig load(const ParamReader& params, const std::optional<FieldOfViewModel>& field_of_view);
};

/**
 * \brief Converts a pixel of an image into the position command that centres it (and for a box, the zoom that fills
 * the view with it): the camera's pose at the image's stamp (the pose history), the picture's pixels (the calibrated
 * camera_info, else the lens at that pose's zoom), aimAtPixel(), and the zoom left where it is when the goal has no
 * box. Or, as ~pixel_aim and choosePixelAim() decide, a view command the device aims with its own command
 * (GoalCommand::view: VAPIX center / areazoom, ONVIF RelativeMove in TranslationSpaceFov).
 *
 * The command is checked and clamped by the GoalSupervisor like a position_abs goal. One thread (the node's main
 * queue); the history and the calibration may be fed from others.
 */
class PixelGoals
{
public:
  /// The calibrated camera_info, if any (FieldOfViewPublisher::calibration()).
  using CalibrationSource = std::function<std::optional<CalibratedIntrinsics>()>;

  /// \p poses must outlive the converter. \p limits are the node's. \p calibration may be empty (no camera_info
  /// topic); \p camera_info_topic names it in the notes.
  PixelGoals(const PtzKinematics& kinematics, const Capabilities& limits, const PoseRecorder& poses,
             const PixelConfig& config, CalibrationSource calibration, std::string camera_info_topic);

  /// The command that centres \p goal's pixel of the image stamped \p stamp, against the device's \p current state:
  /// pan, tilt (rad) and zoom (X; 0: left alone on a device that cannot position it), or why there is none.
  ConvertedGoal convert(const PixelGoal& goal, const ros::Time& stamp, const PtzSample& current) const;

private:
  const PtzKinematics& kinematics_;
  const Capabilities& limits_;
  const PoseRecorder& poses_;
  const PixelConfig config_;
  const CalibrationSource calibration_;
  const std::string camera_info_topic_;
};

}  // namespace ptz_action_server
