/**
 * \file
 * \brief rostest client, mount (mount_inverted.test): an inverted device with a pan offset, seen through the contract.
 */
#include <diagnostic_msgs/DiagnosticArray.h>

#include "node_test.h"

namespace
{
constexpr double PAN_OFFSET = 0.2;  // as mount_inverted.test sets it

/// The device's own angles, as the node's diagnostics report them ("device pan (rad)", "device tilt (rad)").
class DeviceAngles
{
public:
  DeviceAngles()
  {
    subscriber_ = ros::NodeHandle().subscribe("/diagnostics", 100, &DeviceAngles::onDiagnostics, this);
  }

  /// Waits until the device reports \p pan and \p tilt (within TOLERANCE), or the deadline; false if it never does.
  bool waitFor(double pan, double tilt, double& last_pan, double& last_tilt)
  {
    const ros::WallTime deadline = ros::WallTime::now() + ros::WallDuration(GOAL_WAIT);
    while (ros::WallTime::now() < deadline)
    {
      {
        std::lock_guard<std::mutex> lock(mutex_);
        last_pan = pan_;
        last_tilt = tilt_;
      }
      if (std::abs(last_pan - pan) < TOLERANCE && std::abs(last_tilt - tilt) < TOLERANCE)
      {
        return true;
      }
      ros::WallDuration(0.05).sleep();
    }
    return false;
  }

private:
  void onDiagnostics(const diagnostic_msgs::DiagnosticArray::ConstPtr& array)
  {
    for (const auto& status : array->status)
    {
      for (const auto& value : status.values)
      {
        std::lock_guard<std::mutex> lock(mutex_);
        if (value.key == "device pan (rad)")
        {
          pan_ = std::stod(value.value);
        }
        else if (value.key == "device tilt (rad)")
        {
          tilt_ = std::stod(value.value);
        }
      }
    }
  }

  ros::Subscriber subscriber_;
  std::mutex mutex_;
  double pan_ = std::numeric_limits<double>::quiet_NaN();
  double tilt_ = std::numeric_limits<double>::quiet_NaN();
};

class MountTest : public NodeTest
{
};

TEST_F(MountTest, PositivePanTurnsTheInvertedDeviceNegativeAndTfClockwise)
{
  DeviceAngles device;
  ASSERT_EQ(moveTo(0.5, 0.0, 1.0), State::SUCCEEDED) << absolute_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(2));  // state and tf from a tick after the goal ended
  EXPECT_NEAR(observer_->latest().pan, 0.5, TOLERANCE);
  const sensor_msgs::JointState joints = observer_->latestJoints();
  ASSERT_EQ(joints.position.size(), 2u);
  EXPECT_NEAR(joints.position[0], 0.5, TOLERANCE);  // joint_states carry the contract's angles

  // The camera looks right (clockwise seen from above in ptz_base_link), as the contract says for any mount...
  Eigen::Vector3d axis;
  ASSERT_TRUE(opticalAxis(axis));
  EXPECT_NEAR(axis.x(), std::cos(0.5), TOLERANCE);
  EXPECT_NEAR(axis.y(), -std::sin(0.5), TOLERANCE);
  EXPECT_NEAR(axis.z(), 0.0, TOLERANCE);
  // ...which the upside-down device does by turning the other way in its own axes: device = -(pan - offset).
  double device_pan = 0.0;
  double device_tilt = 0.0;
  EXPECT_TRUE(device.waitFor(-(0.5 - PAN_OFFSET), 0.0, device_pan, device_tilt))
      << "device pan " << device_pan << ", tilt " << device_tilt;
}

TEST_F(MountTest, PositiveTiltLooksUpWhileTheInvertedDeviceTiltsDown)
{
  DeviceAngles device;
  ASSERT_EQ(moveTo(PAN_OFFSET, 0.3, 1.0), State::SUCCEEDED) << absolute_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(2));
  EXPECT_NEAR(observer_->latest().tilt, 0.3, TOLERANCE);
  EXPECT_NEAR(observer_->latestJoints().position.at(1), 0.3, TOLERANCE);
  Eigen::Vector3d axis;
  ASSERT_TRUE(opticalAxis(axis));
  EXPECT_NEAR(axis.x(), std::cos(PAN_OFFSET) * std::cos(0.3), TOLERANCE);
  EXPECT_NEAR(axis.z(), std::sin(0.3), TOLERANCE);  // up
  double device_pan = 0.0;
  double device_tilt = 0.0;
  EXPECT_TRUE(device.waitFor(0.0, -0.3, device_pan, device_tilt))
      << "device pan " << device_pan << ", tilt " << device_tilt;
}

TEST_F(MountTest, LimitsAreTheDevicesMirroredAndShifted)
{
  // Device pan [-1, 2] -> contract [-2 + 0.2, 1 + 0.2]; device tilt [-0.5, 1.2] -> contract [-1.2, 0.5].
  absolute_->sendGoal(makePtzGoal(1.5, 0.0, 1.0));
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::REJECTED);
  EXPECT_NE(absolute_->getState().getText().find("pan 1.5000 rad is outside the limits [-1.8000, 1.2000]"),
            std::string::npos)
      << absolute_->getState().getText();

  absolute_->sendGoal(makePtzGoal(0.0, 0.8, 1.0));
  ASSERT_TRUE(absolute_->waitForResult(ros::Duration(GOAL_WAIT)));
  EXPECT_EQ(absolute_->getState(), State::REJECTED);
  EXPECT_NE(absolute_->getState().getText().find("tilt 0.8000 rad is outside the limits [-1.2000, 0.5000]"),
            std::string::npos)
      << absolute_->getState().getText();

  // Beyond the device's own limits in contract numbers, but inside the mirrored ones: taken and reached.
  EXPECT_EQ(moveTo(-1.5, -0.8, 1.0), State::SUCCEEDED) << absolute_->getState().getText();
  ASSERT_TRUE(observer_->waitTicks(2));
  EXPECT_NEAR(observer_->latest().pan, -1.5, TOLERANCE);
  EXPECT_NEAR(observer_->latest().tilt, -0.8, TOLERANCE);
}

TEST_F(MountTest, PositivePanVelocityTurnsTheInvertedDeviceNegative)
{
  DeviceAngles device;
  ASSERT_EQ(moveTo(PAN_OFFSET, 0.0, 1.0), State::SUCCEEDED) << absolute_->getState().getText();
  double device_pan = 0.0;
  double device_tilt = 0.0;
  ASSERT_TRUE(device.waitFor(0.0, 0.0, device_pan, device_tilt));

  velocity_->sendGoal(makePtzGoal(0.3, 0.0, 0.0));
  EXPECT_TRUE(observer_->waitFor([](const PtzState& state) { return state.pan > PAN_OFFSET + 0.2; }, GOAL_WAIT))
      << "ptz_state pan " << observer_->latest().pan;
  velocity_->cancelGoal();
  ASSERT_TRUE(velocity_->waitForResult(ros::Duration(GOAL_WAIT)));
  ASSERT_TRUE(observer_->waitTicks(2));
  const double pan = observer_->latest().pan;
  EXPECT_GT(pan, PAN_OFFSET + 0.2);
  // The device went the other way by as much.
  EXPECT_TRUE(device.waitFor(-(pan - PAN_OFFSET), 0.0, device_pan, device_tilt))
      << "device pan " << device_pan << ", contract pan " << pan;
}

}  // namespace
