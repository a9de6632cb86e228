#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "ptz_action_server/core/motion/kinematics.h"

using namespace ptz_action_server;

namespace
{
std::string readShippedUrdf()
{
  std::ifstream file(std::string(PTZ_SOURCE_DIR) + "/urdf/ptz.urdf");
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

Eigen::Vector3d opticalAxis(const PtzKinematics& kinematics, double pan, double tilt)
{
  return kinematics.cameraInBase(pan, tilt).linear() * Eigen::Vector3d::UnitX();
}

const char* MINIMAL_URDF = R"(<robot name="r">
  <link name="base"/><link name="a"/><link name="b"/><link name="cam"/>
  <joint name="pan" type="%s"><parent link="base"/><child link="a"/><axis xyz="0 0 -1"/></joint>
  <joint name="tilt" type="revolute"><parent link="a"/><child link="b"/><axis xyz="0 -1 0"/>
    <limit lower="-1" upper="0.5" velocity="2" effort="1"/></joint>
  <joint name="cam_joint" type="fixed"><parent link="b"/><child link="cam"/></joint>
</robot>)";

std::string minimalUrdf(const char* pan_type)
{
  char text[1024];
  std::snprintf(text, sizeof(text), MINIMAL_URDF, pan_type);
  return text;
}

KinematicsNames minimalNames()
{
  KinematicsNames names;
  names.pan_joint = "pan";
  names.tilt_joint = "tilt";
  names.camera_link = "cam";
  return names;
}
}  // namespace

TEST(Kinematics, ShippedUrdfFollowsTheContractSigns)
{
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(readShippedUrdf());
  EXPECT_EQ(kinematics.baseFrame(), "ptz_base_link");
  EXPECT_EQ(kinematics.cameraFrame(), "ptz_camera_link");

  // Positive pan turns clockwise seen from above: the camera looks to the right (-y).
  const Eigen::Vector3d right = opticalAxis(kinematics, 0.5, 0.0);
  EXPECT_TRUE(right.isApprox(Eigen::Vector3d(std::cos(0.5), -std::sin(0.5), 0.0), 1e-9)) << right.transpose();
  // Positive tilt pitches up (+z).
  const Eigen::Vector3d up = opticalAxis(kinematics, 0.0, 0.3);
  EXPECT_TRUE(up.isApprox(Eigen::Vector3d(std::cos(0.3), 0.0, std::sin(0.3)), 1e-9)) << up.transpose();
}

TEST(Kinematics, ShippedUrdfLimitsAndFixedJoints)
{
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(readShippedUrdf());
  EXPECT_NEAR(kinematics.panJoint().limits.max, M_PI, 1e-8);
  EXPECT_NEAR(kinematics.tiltJoint().limits.min, -M_PI / 2, 1e-8);
  EXPECT_EQ(kinematics.fixedJoints().size(), 2u);
  // The optical frame has z forward, x right, y down.
  const Eigen::Isometry3d optical = kinematics.cameraInBase(0.0, 0.0) * [&] {
    for (const JointModel& joint : kinematics.fixedJoints())
    {
      if (joint.child_link == "ptz_camera_optical_frame")
      {
        return joint.transform(0.0);
      }
    }
    return Eigen::Isometry3d::Identity();
  }();
  EXPECT_TRUE((optical.linear() * Eigen::Vector3d::UnitZ()).isApprox(Eigen::Vector3d::UnitX(), 1e-6));
  EXPECT_TRUE((optical.linear() * Eigen::Vector3d::UnitX()).isApprox(-Eigen::Vector3d::UnitY(), 1e-6));
  EXPECT_TRUE((optical.linear() * Eigen::Vector3d::UnitY()).isApprox(-Eigen::Vector3d::UnitZ(), 1e-6));
}

TEST(Kinematics, CamerasOfOneUrdfShareOneParsedCopyAndOthersGetTheirOwn)
{
  // Two cameras named by one robot description (as nodelets in one manager) share the parse and its fixed joints.
  const PtzKinematics first = PtzKinematics::fromUrdf(minimalUrdf("continuous"), minimalNames());
  const PtzKinematics second = PtzKinematics::fromUrdf(minimalUrdf("continuous"), minimalNames());
  EXPECT_TRUE(first.sharesUrdfWith(second));
  EXPECT_EQ(&first.fixedJoints(), &second.fixedJoints());
  EXPECT_EQ(first.fixedJoints().size(), 1u);
  const PtzKinematics other = PtzKinematics::fromUrdf(readShippedUrdf());
  EXPECT_FALSE(other.sharesUrdfWith(first));
  EXPECT_EQ(other.fixedJoints().size(), 2u);  // its own joints, not the first text's
  EXPECT_NEAR(other.tiltJoint().limits.min, -M_PI / 2, 1e-8);
  EXPECT_NEAR(first.tiltJoint().limits.max, 0.5, 1e-9);
}

TEST(Kinematics, AimAlongInvertsTheForwardKinematics)
{
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(readShippedUrdf());
  for (double pan : { -3.0, -1.2, 0.0, 0.4, 2.9 })
  {
    for (double tilt : { -1.2, -0.3, 0.0, 0.7, 1.4 })
    {
      double solved_pan = 0.0;
      double solved_tilt = 0.0;
      ASSERT_TRUE(kinematics.aimAlong(opticalAxis(kinematics, pan, tilt), solved_pan, solved_tilt));
      EXPECT_NEAR(solved_pan, pan, 1e-7);
      EXPECT_NEAR(solved_tilt, tilt, 1e-7);
    }
  }
}

TEST(Kinematics, AimAtPutsThePointOnTheOpticalAxis)
{
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(readShippedUrdf());
  for (const Eigen::Vector3d& point : { Eigen::Vector3d(2, -2, 0), Eigen::Vector3d(-1, 0.5, 1.5),
                                        Eigen::Vector3d(0.3, 0.0, -0.5), Eigen::Vector3d(-3, -0.01, 0.12) })
  {
    double pan = 0.0;
    double tilt = 0.0;
    ASSERT_TRUE(kinematics.aimAt(point, pan, tilt)) << point.transpose();
    const Eigen::Vector3d in_camera = kinematics.cameraInBase(pan, tilt).inverse() * point;
    EXPECT_GT(in_camera.x(), 0.0);
    EXPECT_NEAR(in_camera.y(), 0.0, 1e-7);
    EXPECT_NEAR(in_camera.z(), 0.0, 1e-7);
  }
  double pan = 0.0;
  double tilt = 0.0;
  EXPECT_TRUE(kinematics.aimAt(Eigen::Vector3d(2, -2, 0.12), pan, tilt));
  EXPECT_GT(pan, 0.0);  // to the right is clockwise
}

TEST(Kinematics, ErrorsNameWhatIsWrong)
{
  EXPECT_NO_THROW(PtzKinematics::fromUrdf(minimalUrdf("continuous"), minimalNames()));
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(minimalUrdf("continuous"), minimalNames());
  EXPECT_DOUBLE_EQ(kinematics.tiltJoint().limits.max, 0.5);
  EXPECT_DOUBLE_EQ(kinematics.tiltJoint().max_velocity, 2.0);
  auto message = [](const std::string& urdf, const KinematicsNames& names) {
    try
    {
      PtzKinematics::fromUrdf(urdf, names);
    }
    catch (const ConfigError& error)
    {
      return std::string(error.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message(minimalUrdf("fixed"), minimalNames()), "URDF pan joint 'pan' must be revolute or continuous");
  KinematicsNames wrong = minimalNames();
  wrong.tilt_joint = "elevation";
  EXPECT_EQ(message(minimalUrdf("continuous"), wrong), "URDF has no tilt joint named 'elevation'");
  wrong = minimalNames();
  wrong.camera_link = "lens";
  EXPECT_EQ(message(minimalUrdf("continuous"), wrong), "URDF has no camera link named 'lens'");
  EXPECT_EQ(message("<robot", minimalNames()), "the URDF could not be parsed (see the urdfdom message above)");
  EXPECT_EQ(message("", minimalNames()), "the URDF is empty");
}

TEST(Kinematics, DirectionOfFollowsTheContractSigns)
{
  EXPECT_TRUE(directionOf(0.0, 0.0).isApprox(Eigen::Vector3d::UnitX(), 1e-12));
  // Positive pan looks to the right (-y), positive tilt up (+z).
  EXPECT_TRUE(directionOf(0.5, 0.0).isApprox(Eigen::Vector3d(std::cos(0.5), -std::sin(0.5), 0.0), 1e-12));
  EXPECT_TRUE(directionOf(0.0, 0.3).isApprox(Eigen::Vector3d(std::cos(0.3), 0.0, std::sin(0.3)), 1e-12));
  EXPECT_TRUE(directionOf(-M_PI / 2, 0.0).isApprox(Eigen::Vector3d::UnitY(), 1e-12));
  EXPECT_TRUE(directionOf(1.0, M_PI / 2).isApprox(Eigen::Vector3d::UnitZ(), 1e-12));
}

TEST(Kinematics, DirectionOfIsTheShippedCamerasOpticalAxisAndAimAlongInvertsIt)
{
  const PtzKinematics kinematics = PtzKinematics::fromUrdf(readShippedUrdf());
  for (double pan : { -2.5, -0.7, 0.0, 0.4, 3.0 })
  {
    for (double tilt : { -1.3, -0.2, 0.0, 0.6 })
    {
      const Eigen::Vector3d direction = directionOf(pan, tilt);
      EXPECT_NEAR(direction.norm(), 1.0, 1e-12);
      EXPECT_TRUE(direction.isApprox(opticalAxis(kinematics, pan, tilt), 1e-9)) << pan << ", " << tilt;
      double solved_pan = 0.0;
      double solved_tilt = 0.0;
      ASSERT_TRUE(kinematics.aimAlong(direction, solved_pan, solved_tilt));
      EXPECT_NEAR(solved_pan, pan, 1e-7);
      EXPECT_NEAR(solved_tilt, tilt, 1e-7);
    }
  }
}
