/**
 * \file
 * \brief Pan-tilt kinematics from a URDF: joint transforms for tf, and the pan/tilt that aim the camera.
 *
 * Plain urdfdom and Eigen, no ROS: the node broadcasts what this computes, and the core tests check the contract's
 * sign conventions against it directly.
 */
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// One URDF joint, reduced to what tf needs.
struct JointModel
{
  std::string name;
  std::string parent_link;
  std::string child_link;
  Eigen::Isometry3d origin = Eigen::Isometry3d::Identity();  ///< parent link -> joint frame at q = 0
  Eigen::Vector3d axis = Eigen::Vector3d::UnitZ();           ///< unit rotation axis in the joint frame
  bool revolute = false;                                     ///< false: fixed
  AxisRange limits{ -M_PI, M_PI };                           ///< URDF lower/upper (continuous: +-pi)
  double max_velocity = 0.0;                                 ///< URDF velocity limit (0: none)

  /// Parent link -> child link at joint value \p q (ignored for fixed joints).
  Eigen::Isometry3d transform(double q) const;
};

/**
 * \brief Unit vector of the direction \p pan, \p tilt (rad) in the contract's convention, in the axes they are
 * measured in: pan 0, tilt 0 is +x, positive pan turns clockwise seen from above (towards -y), positive tilt up (+z).
 *
 * PtzKinematics::aimAlong() takes it back to the camera's own pan and tilt, once rotated into the base frame.
 */
Eigen::Vector3d directionOf(double pan, double tilt);

/// Names the node looks for in the URDF.
struct KinematicsNames
{
  std::string pan_joint = "ptz_pan_joint";
  std::string tilt_joint = "ptz_tilt_joint";
  std::string camera_link = "ptz_camera_link";  ///< its x axis is the optical axis (REP-103)
};

/**
 * \brief The chain base -> pan joint -> tilt joint -> camera link of a URDF.
 *
 * Every joint between the base and the camera other than pan and tilt must be fixed.
 */
class PtzKinematics
{
public:
  /// Parses \p urdf_xml. Throws ConfigError naming what is missing or malformed. Cameras whose robot_description
  /// is the same text share one parsed copy of it (its model and fixed joints) for as long as one of them lives.
  static PtzKinematics fromUrdf(const std::string& urdf_xml, const KinematicsNames& names = KinematicsNames());
  /// True when this and \p other were made from the same parsed URDF.
  bool sharesUrdfWith(const PtzKinematics& other) const
  {
    return urdf_ == other.urdf_;
  }

  const JointModel& panJoint() const
  {
    return pan_;
  }
  const JointModel& tiltJoint() const
  {
    return tilt_;
  }
  /// Every fixed joint of the URDF (the node publishes them once as static transforms).
  const std::vector<JointModel>& fixedJoints() const;
  /// The parent link of the pan joint: the frame pan and tilt are measured in.
  const std::string& baseFrame() const
  {
    return pan_.parent_link;
  }
  const std::string& cameraFrame() const
  {
    return camera_link_;
  }

  /// Pose of the camera link in the base frame at \p pan, \p tilt.
  Eigen::Isometry3d cameraInBase(double pan, double tilt) const;

  /// Pan and tilt whose camera x axis is parallel to \p direction (base frame). False if none is found.
  bool aimAlong(const Eigen::Vector3d& direction, double& pan, double& tilt) const;

  /// Pan and tilt whose optical axis passes through \p point (base frame), camera offsets included.
  bool aimAt(const Eigen::Vector3d& point, double& pan, double& tilt) const;

private:
  /// One joint of the chain from the base to the camera link.
  struct ChainJoint
  {
    JointModel joint;
    bool is_pan = false;
    bool is_tilt = false;
  };

  template <class TargetInCamera>
  bool solveAim(TargetInCamera target_in_camera, double& pan, double& tilt) const;

  JointModel pan_;
  JointModel tilt_;
  struct ParsedUrdf;
  /// One URDF, parsed once per process however many cameras it names: its fixed joints, for the static transforms.
  std::shared_ptr<const ParsedUrdf> urdf_;
  std::vector<ChainJoint> chain_;  ///< from the base to the camera link
  std::string camera_link_;
};

}  // namespace ptz_action_server
