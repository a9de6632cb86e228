/**
 * \file
 * \brief Keeps a detected target in view: a detector's boxes, seen from the camera's pose when their image was taken,
 * become the target's direction, and a velocity (or position) command that holds it at the image centre.
 *
 * The core of a detection-tracking goal (PtzTrackDetections), without ROS: the ROS layer converts each Detections
 * message into ImageDetections, hands it to observe() with the node's PoseHistory, and calls step() at the tracking
 * rate; step() says what to command, when the target is lost, and the feedback.
 */
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "ptz_action_server/core/goal/goal_supervisor.h"
#include "ptz_action_server/core/motion/frame_tracker.h"
#include "ptz_action_server/core/motion/kinematics.h"
#include "ptz_action_server/core/motion/pixel_aim.h"
#include "ptz_action_server/core/motion/pose_history.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// One box a detector found (a Detection message). Pixels as camera_info's K: (0, 0) the centre of the top-left pixel.
struct ImageDetection
{
  std::string id;       ///< the detector's name for it ("" if none)
  double score = 0.0;   ///< higher is better
  double u = 0.0;       ///< px, column of the target's centre
  double v = 0.0;       ///< px, row
  double width = 0.0;   ///< px, the box; 0 x 0: a point
  double height = 0.0;  ///< px
};

/// What a detector found in one image (a Detections message).
struct ImageDetections
{
  HeaderStamp stamp{};  ///< the image's header stamp
  int width = 0;        ///< px of the image
  int height = 0;       ///< px
  std::vector<ImageDetection> detections;
};

/// How a detection-tracking goal follows its target: the goal's fields and the node's steering.
struct DetectionTrackerConfig
{
  /// The node's ~track/ settings: rate (Hz the node calls step()), gain, feed_forward (false: position commands
  /// always; true: velocity commands where pan and tilt take them), max_extrapolation. Its timeout is not used.
  FrameTrackerConfig steering;
  std::string target_id;       ///< only detections of this id count; "": any
  double zoom_fraction = 0.0;  ///< in (0, 1]: the zoom that makes the box's larger side this part of the view; 0: leave
  double dead_zone = 0.0;      ///< in [0, 1): part of the half image around the centre the target may be in uncorrected
  double max_speed = 0.0;      ///< rad/s on pan and tilt, at most (below the device's own); 0: the device's
  double lost_timeout = 1.0;   ///< s without a matching detection before the target is lost; > 0
};

/// "" or what is wrong with \p config (a goal's rejection): a zoom fraction, dead zone, speed or timeout out of range.
std::string findBadTrackingConfig(const DetectionTrackerConfig& config);

/// What observe() did with an image's detections.
enum class DetectionUse
{
  USED,      ///< one of them is the target: its direction is the newest
  NO_MATCH,  ///< none of them has the goal's id (or there were none)
  STALE,     ///< the image is not newer than the newest image used: ignored
  DROPPED,   ///< the target's direction is unknown: the camera's pose at the image's stamp (the pose history does
             ///< not reach it), the intrinsics, or every matching box is unusable (a centre off the image)
};

/// observe()'s answer.
struct DetectionObservation
{
  DetectionUse use = DetectionUse::NO_MATCH;
  std::string problem;  ///< DROPPED: why (for a throttled warning); else ""
};

/// What became of the images a tracker was given.
struct DetectionCounts
{
  std::uint64_t images = 0;
  std::uint64_t used = 0;
  std::uint64_t no_match = 0;
  std::uint64_t stale = 0;
  std::uint64_t dropped = 0;
};

/// Where a tracking goal is.
enum class TrackingState
{
  WAITING,   ///< no matching detection yet, and the lost timeout has not passed: command nothing
  TRACKING,  ///< steer with the step's command
  LOST,      ///< no matching detection for the lost timeout: end the goal (hold, or go to the lost preset)
};

/// A tracking goal's feedback.
struct TrackingFeedback
{
  double pan_error = 0.0;      ///< rad: the target's aim now (carried forward from its detections) minus the pan
  double tilt_error = 0.0;     ///< rad
  double u_error = 0.0;        ///< px: the newest detection used, its centre minus the principal point of its image
  double v_error = 0.0;        ///< px
  double detection_age = 0.0;  ///< s, header clock: now minus the stamp of the newest detection's image; NaN: none yet
  std::string target_id;       ///< the newest detection's id
};

/// What step() says to do.
struct TrackingStep
{
  TrackingState state = TrackingState::WAITING;
  GoalCommand command;  ///< TRACKING: for GoalSupervisor::steer()
  AxisValues aim{};     ///< TRACKING: the aim it steers to (steer()'s aim: the feedback's remaining angles)
  TrackingFeedback feedback;
  std::string lost_reason;  ///< LOST: why, for the result ("no detection of 'person' for 1.02 s (...)")
};

/**
 * \brief Follows the target a detector finds in the camera's images.
 *
 * Each image's detections are seen from the camera's pose when the image was taken (PoseHistory::at() of its stamp)
 * through the intrinsics at that pose's zoom (aimAtPixel(), as a click on the image would be), so neither the
 * detector's latency nor the camera's own motion meanwhile shifts the target. The target is the detection with the
 * goal's id (any id without one): at first the best-scoring one, then the one nearest the target's direction
 * carried forward to the image's stamp. Its aim (pan and tilt, image stamp) goes into a FrameTracker, which measures
 * its angular rate and carries it forward to the moment of each command: velocity commands of that rate plus gain
 * times the error where pan and tilt take velocities (and FrameTrackerConfig::feed_forward), the aim as a position
 * goal otherwise; speeds capped at the goal's max_speed and the device's.
 *
 * Dead zone: while the target (carried forward to now, seen in the current view) stays within dead_zone of the half
 * image of the centre, the error is not corrected (the feed-forward goes on, so a moving target is still followed;
 * position commands hold the camera where it is); once it leaves the zone it is corrected until within half of it.
 *
 * Zoom (zoom_fraction > 0, on a zoom that goes to positions and reports them): once a box's larger side spans a part
 * of its image more than ZOOM_BAND off the fraction, the zoom aim becomes the one at which it spans the fraction
 * (aimAtPixel()'s box zoom, within the zoom range); zooming in waits for the target to be within the central half of
 * the image. Otherwise the zoom is left where it is.
 *
 * Lost: no detection matching for lost_timeout (on the core's clock) since the last one, or since the start.
 *
 * Not thread-safe: the node's main thread owns it (the PoseHistory it reads is thread-safe).
 */
class DetectionTracker
{
public:
  /// A detection's box spanning the zoom fraction to within this factor either way (0.2: 0.8 to 1.2 times) leaves the
  /// zoom alone: the zoom does not hunt after every box's noise.
  static constexpr double ZOOM_BAND = 0.2;

  /// \p camera's field of view (a pointer) must outlive the tracker. \p limits are the node's (device and URDF).
  /// \p start is when the goal started: the lost timeout counts from it until a first detection matches. Throws
  /// ConfigError with findBadTrackingConfig()'s text.
  DetectionTracker(const PtzKinematics& kinematics, const Capabilities& limits, const PixelCamera& camera,
                   const DetectionTrackerConfig& config, TimePoint start);

  /// One image's detections, received at \p now; \p history gives the camera's pose at the image's stamp.
  DetectionObservation observe(const ImageDetections& image, const PoseHistory& history, TimePoint now);

  /// What to do at \p now (the core's clock), the camera being at \p current and \p stamp being now on the header
  /// clock (ros::Time::now()).
  TrackingStep step(const PtzSample& current, HeaderStamp stamp, TimePoint now);

  /// True: step() commands velocities; false: positions.
  bool velocityCommands() const
  {
    return velocity_;
  }
  const DetectionCounts& counts() const
  {
    return counts_;
  }
  const DetectionTrackerConfig& config() const
  {
    return config_;
  }

private:
  /// A matching detection's aim, or why it has none.
  struct Candidate
  {
    const ImageDetection* detection = nullptr;
    PixelAim aim;
  };

  /// The candidate to follow: the best score first, then the nearest the target's direction at \p stamp.
  const Candidate* choose(const std::vector<Candidate>& candidates, HeaderStamp stamp, double image_pan) const;
  /// The zoom aim from the chosen \p detection of \p image seen at \p pose.
  void holdZoom(const ImageDetection& detection, const ImageDetections& image, const AxisValues& pose);
  /// True while the error is to be corrected (the dead zone's hysteresis), the target at \p aim and the camera at
  /// \p current.
  bool correcting(const AxisValues& aim, const PtzSample& current);
  /// The zoom part of \p step's command and aim.
  void steerZoom(const PtzSample& current, TrackingStep& step) const;
  /// "lost: ..." with what happened since the last match.
  std::string lostReason(double silent_for) const;

  const PtzKinematics kinematics_;
  const Capabilities limits_;
  const PixelCamera camera_;
  const DetectionTrackerConfig config_;
  const bool velocity_;
  FrameTracker tracker_;
  TimePoint start_;
  std::vector<Candidate> candidates_;  ///< observe()'s, its capacity reused

  HeaderStamp last_stamp_{};  ///< the newest image used
  ImageDetection last_;       ///< the newest detection used
  double last_u_error_ = 0.0;
  double last_v_error_ = 0.0;
  int last_width_ = 0;  ///< px of the newest image used
  int last_height_ = 0;
  double zoom_aim_;          ///< X; NaN: none (leave the zoom)
  bool correcting_ = false;  ///< it left the dead zone and is not yet back within half of it

  DetectionCounts counts_;
  DetectionCounts at_last_match_;  ///< counts_ when the newest detection was used
  std::string last_problem_;       ///< why the newest dropped image was dropped
};

}  // namespace ptz_action_server
