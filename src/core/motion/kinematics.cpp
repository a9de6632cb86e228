#include "ptz_action_server/core/motion/kinematics.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>

#include <urdf_model/model.h>
#include <urdf_parser/urdf_parser.h>

namespace ptz_action_server
{
namespace
{
constexpr int MAX_AIM_ITERATIONS = 50;
constexpr double AIM_TOLERANCE = 1e-10;  ///< rad of remaining aiming error
constexpr double JACOBIAN_STEP = 1e-6;   ///< rad, for the numerical Jacobian
constexpr double MIN_TARGET_DISTANCE = 1e-6;
constexpr int GRID_PAN_STEPS = 16;
constexpr int GRID_TILT_STEPS = 8;

double wrapAngle(double angle)
{
  return std::remainder(angle, 2.0 * M_PI);
}

JointModel toJointModel(const urdf::Joint& joint)
{
  JointModel model;
  model.name = joint.name;
  model.parent_link = joint.parent_link_name;
  model.child_link = joint.child_link_name;
  const urdf::Pose& pose = joint.parent_to_joint_origin_transform;
  model.origin = Eigen::Translation3d(pose.position.x, pose.position.y, pose.position.z) *
                 Eigen::Quaterniond(pose.rotation.w, pose.rotation.x, pose.rotation.y, pose.rotation.z);
  model.revolute = joint.type == urdf::Joint::REVOLUTE || joint.type == urdf::Joint::CONTINUOUS;
  if (model.revolute)
  {
    const Eigen::Vector3d axis(joint.axis.x, joint.axis.y, joint.axis.z);
    if (axis.norm() < 1e-9)
    {
      throw ConfigError("URDF joint '" + joint.name + "' has a zero axis");
    }
    model.axis = axis.normalized();
  }
  if (joint.type == urdf::Joint::REVOLUTE && joint.limits)
  {
    model.limits = AxisRange{ joint.limits->lower, joint.limits->upper };
    model.max_velocity = joint.limits->velocity;
  }
  return model;
}

JointModel requireRevolute(const urdf::ModelInterface& model, const std::string& name, const char* role)
{
  const urdf::JointConstSharedPtr joint = model.getJoint(name);
  if (!joint)
  {
    throw ConfigError(std::string("URDF has no ") + role + " joint named '" + name + "'");
  }
  if (joint->type != urdf::Joint::REVOLUTE && joint->type != urdf::Joint::CONTINUOUS)
  {
    throw ConfigError(std::string("URDF ") + role + " joint '" + name + "' must be revolute or continuous");
  }
  return toJointModel(*joint);
}
}  // namespace

Eigen::Vector3d directionOf(double pan, double tilt)
{
  return Eigen::Vector3d(std::cos(tilt) * std::cos(pan), -std::cos(tilt) * std::sin(pan), std::sin(tilt));
}

Eigen::Isometry3d JointModel::transform(double q) const
{
  if (!revolute)
  {
    return origin;
  }
  return origin * Eigen::AngleAxisd(q, axis);
}

struct PtzKinematics::ParsedUrdf
{
  urdf::ModelInterfaceSharedPtr model;
  std::vector<JointModel> fixed_joints;
};

PtzKinematics PtzKinematics::fromUrdf(const std::string& urdf_xml, const KinematicsNames& names)
{
  if (urdf_xml.empty())
  {
    throw ConfigError("the URDF is empty");
  }
  // Keyed by the text itself: a robot's description is parsed once for every camera in the process that it names.
  static std::mutex cache_mutex;
  static std::map<std::string, std::weak_ptr<const ParsedUrdf>> cache;
  std::shared_ptr<const ParsedUrdf> parsed;
  {
    std::lock_guard<std::mutex> lock(cache_mutex);
    for (auto entry = cache.begin(); entry != cache.end();)  // forget the texts no camera uses any more
    {
      entry = entry->second.expired() ? cache.erase(entry) : std::next(entry);
    }
    parsed = cache[urdf_xml].lock();
    if (!parsed)
    {
      auto fresh = std::make_shared<ParsedUrdf>();
      fresh->model = urdf::parseURDF(urdf_xml);
      if (!fresh->model)
      {
        cache.erase(urdf_xml);
        throw ConfigError("the URDF could not be parsed (see the urdfdom message above)");
      }
      for (const auto& entry : fresh->model->joints_)
      {
        if (entry.second->type == urdf::Joint::FIXED)
        {
          fresh->fixed_joints.push_back(toJointModel(*entry.second));
        }
      }
      parsed = fresh;
      cache[urdf_xml] = parsed;
    }
  }
  const urdf::ModelInterface* model = parsed->model.get();
  PtzKinematics kinematics;
  kinematics.urdf_ = parsed;
  kinematics.pan_ = requireRevolute(*model, names.pan_joint, "pan");
  kinematics.tilt_ = requireRevolute(*model, names.tilt_joint, "tilt");
  kinematics.camera_link_ = names.camera_link;

  // Walk up from the camera link to the pan joint's parent; pan and tilt must be on the way, the rest fixed.
  urdf::LinkConstSharedPtr link = model->getLink(names.camera_link);
  if (!link)
  {
    throw ConfigError("URDF has no camera link named '" + names.camera_link + "'");
  }
  while (link && link->name != kinematics.pan_.parent_link)
  {
    const urdf::JointConstSharedPtr joint = link->parent_joint;
    if (!joint)
    {
      throw ConfigError("URDF camera link '" + names.camera_link + "' is not below the pan joint '" + names.pan_joint +
                        "'");
    }
    ChainJoint step;
    step.joint = toJointModel(*joint);
    step.is_pan = joint->name == names.pan_joint;
    step.is_tilt = joint->name == names.tilt_joint;
    if (!step.is_pan && !step.is_tilt && joint->type != urdf::Joint::FIXED)
    {
      throw ConfigError("URDF joint '" + joint->name + "' between the base and the camera must be fixed");
    }
    kinematics.chain_.push_back(step);
    link = model->getLink(joint->parent_link_name);
  }
  std::reverse(kinematics.chain_.begin(), kinematics.chain_.end());
  const bool has_tilt = std::any_of(kinematics.chain_.begin(), kinematics.chain_.end(),
                                    [](const ChainJoint& step) { return step.is_tilt; });
  if (!has_tilt || kinematics.chain_.empty() || !kinematics.chain_.front().is_pan)
  {
    throw ConfigError("URDF chain from '" + kinematics.pan_.parent_link + "' to '" + names.camera_link +
                      "' must start at the pan joint and pass the tilt joint");
  }
  return kinematics;
}

const std::vector<JointModel>& PtzKinematics::fixedJoints() const
{
  static const std::vector<JointModel> none;
  return urdf_ ? urdf_->fixed_joints : none;
}

Eigen::Isometry3d PtzKinematics::cameraInBase(double pan, double tilt) const
{
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  for (const ChainJoint& step : chain_)
  {
    pose = pose * step.joint.transform(step.is_pan ? pan : (step.is_tilt ? tilt : 0.0));
  }
  return pose;
}

template <class TargetInCamera>
bool PtzKinematics::solveAim(TargetInCamera target_in_camera, double& pan, double& tilt) const
{
  // Aiming error: azimuth and elevation of the target seen from the camera; both zero when aimed.
  auto error = [&](double p, double t, Eigen::Vector2d& out) {
    const Eigen::Vector3d target = target_in_camera(cameraInBase(p, t));
    if (target.norm() < MIN_TARGET_DISTANCE)
    {
      return false;
    }
    out = Eigen::Vector2d(std::atan2(target.y(), target.x()), std::atan2(target.z(), target.head<2>().norm()));
    return true;
  };
  // Start from the best pose of a coarse grid, so Newton converges to the upright branch (|tilt| <= pi/2) even
  // for targets behind the camera.
  Eigen::Vector2d angles(0.0, 0.0);
  double best_alignment = -2.0;
  for (int pan_step = -GRID_PAN_STEPS / 2; pan_step < GRID_PAN_STEPS / 2; ++pan_step)
  {
    for (int tilt_step = -GRID_TILT_STEPS / 2; tilt_step <= GRID_TILT_STEPS / 2; ++tilt_step)
    {
      const double p = pan_step * 2.0 * M_PI / GRID_PAN_STEPS;
      const double t = tilt_step * M_PI / (GRID_TILT_STEPS + 1);
      const Eigen::Vector3d target = target_in_camera(cameraInBase(p, t));
      const double alignment = target.x() / std::max(target.norm(), MIN_TARGET_DISTANCE);
      if (alignment > best_alignment)
      {
        best_alignment = alignment;
        angles = Eigen::Vector2d(p, t);
      }
    }
  }
  Eigen::Vector2d residual;
  for (int iteration = 0; iteration < MAX_AIM_ITERATIONS; ++iteration)
  {
    if (!error(angles.x(), angles.y(), residual))
    {
      return false;
    }
    if (residual.norm() < AIM_TOLERANCE)
    {
      pan = wrapAngle(angles.x());
      tilt = angles.y();
      return true;
    }
    Eigen::Matrix2d jacobian;
    for (int column = 0; column < 2; ++column)
    {
      Eigen::Vector2d shifted = angles;
      shifted[column] += JACOBIAN_STEP;
      Eigen::Vector2d shifted_residual;
      if (!error(shifted.x(), shifted.y(), shifted_residual))
      {
        return false;
      }
      Eigen::Vector2d difference = shifted_residual - residual;
      difference.x() = wrapAngle(difference.x());
      jacobian.col(column) = difference / JACOBIAN_STEP;
    }
    if (std::abs(jacobian.determinant()) < 1e-12)
    {
      return false;
    }
    angles -= jacobian.inverse() * residual;
    angles.x() = wrapAngle(angles.x());
  }
  return false;
}

bool PtzKinematics::aimAlong(const Eigen::Vector3d& direction, double& pan, double& tilt) const
{
  if (direction.norm() < MIN_TARGET_DISTANCE)
  {
    return false;
  }
  const Eigen::Vector3d unit = direction.normalized();
  return solveAim([&](const Eigen::Isometry3d& camera) { return Eigen::Vector3d(camera.linear().transpose() * unit); },
                  pan, tilt);
}

bool PtzKinematics::aimAt(const Eigen::Vector3d& point, double& pan, double& tilt) const
{
  return solveAim([&](const Eigen::Isometry3d& camera) { return Eigen::Vector3d(camera.inverse() * point); }, pan,
                  tilt);
}

}  // namespace ptz_action_server
