#include <gtest/gtest.h>

#include <cmath>
#include <memory>

#include "ptz_action_server/core/mounted_backend.h"
#include "ptz_action_server/core/sim/sim_backend.h"

using namespace ptz_action_server;

namespace
{
constexpr double RESOLUTION_TOLERANCE = 1e-3;  // rad: the sim quantises to ~0.0009

/// A simulated device with asymmetric limits, seen through a mount, on a hand-driven clock.
class MountedBackendTest : public ::testing::Test
{
protected:
  std::shared_ptr<SimBackend> makeDevice()
  {
    SimDeviceConfig config = SimDeviceConfig::defaults();
    config.axes[PAN].range = AxisRange{ -1.0, 2.0 };
    config.axes[TILT].range = AxisRange{ -0.5, 1.2 };
    device_ = std::make_shared<SimBackend>(config, clock_);
    return device_;
  }

  MountedBackend& mount(bool inverted, double pan_offset)
  {
    mounted_ = std::make_unique<MountedBackend>(makeDevice(), MountConfig{ inverted, pan_offset });
    mounted_->start();
    return *mounted_;
  }

  std::shared_ptr<ManualClock> clock_ = std::make_shared<ManualClock>();
  std::shared_ptr<SimBackend> device_;
  std::unique_ptr<MountedBackend> mounted_;
};
}  // namespace

TEST_F(MountedBackendTest, InvertedGoalsTurnTheDeviceTheOtherWay)
{
  MountedBackend& backend = mount(true, 0.0);
  backend.goTo({ 0.4, 0.3, 5.0 });
  clock_->advance(5.0);
  const PtzSample device = device_->sample();
  EXPECT_NEAR(device.position[PAN], -0.4, RESOLUTION_TOLERANCE);
  EXPECT_NEAR(device.position[TILT], -0.3, RESOLUTION_TOLERANCE);
  EXPECT_DOUBLE_EQ(device.position[ZOOM], 5.0);  // zoom is not mounted

  const PtzSample contract = backend.sample();
  EXPECT_NEAR(contract.position[PAN], 0.4, RESOLUTION_TOLERANCE);
  EXPECT_NEAR(contract.position[TILT], 0.3, RESOLUTION_TOLERANCE);
  EXPECT_DOUBLE_EQ(contract.position[ZOOM], 5.0);
  EXPECT_EQ(contract.stamp, device.stamp);
  EXPECT_EQ(contract.link_up, device.link_up);
}

TEST_F(MountedBackendTest, InvertedVelocitiesAreMirroredBothWays)
{
  MountedBackend& backend = mount(true, 0.0);
  backend.moveAtVelocity({ 0.5, -0.2, 1.0 });
  clock_->advance(0.6);
  const PtzSample device = device_->sample();
  EXPECT_LT(device.velocity[PAN], 0.0);
  EXPECT_GT(device.velocity[TILT], 0.0);
  EXPECT_GT(device.velocity[ZOOM], 0.0);
  const PtzSample contract = backend.sample();
  EXPECT_DOUBLE_EQ(contract.velocity[PAN], -device.velocity[PAN]);
  EXPECT_DOUBLE_EQ(contract.velocity[TILT], -device.velocity[TILT]);
  EXPECT_DOUBLE_EQ(contract.velocity[ZOOM], device.velocity[ZOOM]);
  EXPECT_GT(contract.position[PAN], 0.0);
  EXPECT_LT(contract.position[TILT], 0.0);
}

TEST_F(MountedBackendTest, InvertedLimitsSwapAndNegateTheirEnds)
{
  const Capabilities capabilities = mount(true, 0.0).capabilities();
  EXPECT_DOUBLE_EQ(capabilities.axes[PAN].range.min, -2.0);
  EXPECT_DOUBLE_EQ(capabilities.axes[PAN].range.max, 1.0);
  EXPECT_DOUBLE_EQ(capabilities.axes[TILT].range.min, -1.2);
  EXPECT_DOUBLE_EQ(capabilities.axes[TILT].range.max, 0.5);
  const Capabilities device = device_->capabilities();
  EXPECT_DOUBLE_EQ(capabilities.axes[ZOOM].range.min, device.axes[ZOOM].range.min);
  EXPECT_DOUBLE_EQ(capabilities.axes[ZOOM].range.max, device.axes[ZOOM].range.max);
  EXPECT_DOUBLE_EQ(capabilities.axes[PAN].max_speed, device.axes[PAN].max_speed);
}

TEST_F(MountedBackendTest, PanOffsetShiftsGoalsStateAndLimits)
{
  MountedBackend& backend = mount(false, 0.5);
  const Capabilities capabilities = backend.capabilities();
  EXPECT_DOUBLE_EQ(capabilities.axes[PAN].range.min, -0.5);
  EXPECT_DOUBLE_EQ(capabilities.axes[PAN].range.max, 2.5);
  EXPECT_DOUBLE_EQ(capabilities.axes[TILT].range.min, -0.5);  // tilt has no offset
  EXPECT_DOUBLE_EQ(capabilities.axes[TILT].range.max, 1.2);

  // At rest at device pan 0 the contract reads the offset.
  EXPECT_NEAR(backend.sample().position[PAN], 0.5, 1e-12);
  backend.goTo({ 0.0, 0.2, 1.0 });
  clock_->advance(5.0);
  EXPECT_NEAR(device_->sample().position[PAN], -0.5, RESOLUTION_TOLERANCE);
  EXPECT_NEAR(backend.sample().position[PAN], 0.0, RESOLUTION_TOLERANCE);
  EXPECT_NEAR(backend.sample().position[TILT], 0.2, RESOLUTION_TOLERANCE);
}

TEST_F(MountedBackendTest, InvertedWithOffsetMapsPanThroughBoth)
{
  MountedBackend& backend = mount(true, 0.5);
  // contract = -device + 0.5: device [-1, 2] -> contract [-1.5, 1.5]
  const Capabilities capabilities = backend.capabilities();
  EXPECT_DOUBLE_EQ(capabilities.axes[PAN].range.min, -1.5);
  EXPECT_DOUBLE_EQ(capabilities.axes[PAN].range.max, 1.5);
  backend.goTo({ 1.0, 0.0, 1.0 });
  clock_->advance(5.0);
  EXPECT_NEAR(device_->sample().position[PAN], -0.5, RESOLUTION_TOLERANCE);
  EXPECT_NEAR(backend.sample().position[PAN], 1.0, RESOLUTION_TOLERANCE);
}

TEST_F(MountedBackendTest, MappingRoundTrips)
{
  for (bool inverted : { false, true })
  {
    for (double offset : { -2.0, 0.0, 0.7 })
    {
      const MountedBackend& backend = mount(inverted, offset);
      const AxisValues contract{ 0.3, -0.8, 7.0 };
      const AxisValues back = backend.toContract(backend.toDevice(contract));
      for (Axis axis : ALL_AXES)
      {
        EXPECT_NEAR(back[axis], contract[axis], 1e-12) << axisName(axis) << " inverted=" << inverted;
      }
      const AxisValues velocity{ 0.3, -0.8, 2.0 };
      EXPECT_EQ(backend.mapVelocity(backend.mapVelocity(velocity)), velocity);
    }
  }
}

TEST_F(MountedBackendTest, ForwardsTheRestAndReportsTheMount)
{
  MountedBackend& backend = mount(true, 0.25);
  EXPECT_EQ(backend.name(), "sim");
  backend.goTo({ 0.25 + 0.3, 0.0, 1.0 });
  clock_->advance(5.0);
  std::vector<DiagnosticValue> values;
  backend.diagnostics(values);
  const auto find = [&](const std::string& key) {
    for (const DiagnosticValue& value : values)
    {
      if (value.first == key)
      {
        return value.second;
      }
    }
    return std::string("(missing)");
  };
  EXPECT_EQ(find("mount"), "inverted");
  EXPECT_EQ(find("mount pan offset (rad)"), "0.2500");
  EXPECT_NEAR(std::stod(find("device pan (rad)")), -0.3, RESOLUTION_TOLERANCE);
  EXPECT_EQ(backend.lastFault(), device_->lastFault());
  EXPECT_EQ(backend.lastLinkLoss(), device_->lastLinkLoss());
  backend.moveAtVelocity({ 0.5, 0.0, 0.0 });
  clock_->advance(0.5);
  backend.stop();
  clock_->advance(5.0);
  EXPECT_FALSE(device_->sample().moving);
}

TEST(MountConfigTest, IdentityNeedsNoWrapperAndBadOffsetsAreRefused)
{
  auto device = std::make_shared<SimBackend>(SimDeviceConfig::defaults(), std::make_shared<ManualClock>());
  EXPECT_EQ(applyMount(device, MountConfig{}), device);
  EXPECT_NE(applyMount(device, MountConfig{ true, 0.0 }), device);
  EXPECT_NE(applyMount(device, MountConfig{ false, 0.1 }), device);
  EXPECT_THROW(MountedBackend(device, MountConfig{ false, std::nan("") }), ConfigError);
  EXPECT_THROW(MountedBackend(nullptr, MountConfig{ true, 0.0 }), ConfigError);
}

TEST(MountConfigTest, DeviceLimitsAreTheInverseOfContractLimits)
{
  // A ceiling dome's URDF: tilt mostly downwards. The device, upside down, sees it mostly upwards.
  Capabilities urdf;
  urdf.axes[PAN].range = AxisRange{ -3.0, 2.5 };
  urdf.axes[TILT].range = AxisRange{ -1.5, 0.2 };
  const MountConfig mount{ true, 0.4 };
  const Capabilities device = deviceLimits(urdf, mount);
  EXPECT_DOUBLE_EQ(device.axes[PAN].range.min, -2.1);  // -(2.5 - 0.4)
  EXPECT_DOUBLE_EQ(device.axes[PAN].range.max, 3.4);   // -(-3.0 - 0.4)
  EXPECT_DOUBLE_EQ(device.axes[TILT].range.min, -0.2);
  EXPECT_DOUBLE_EQ(device.axes[TILT].range.max, 1.5);
  const Capabilities back = contractLimits(device, mount);
  for (Axis axis : { PAN, TILT })
  {
    EXPECT_NEAR(back.axes[axis].range.min, urdf.axes[axis].range.min, 1e-12) << axisName(axis);
    EXPECT_NEAR(back.axes[axis].range.max, urdf.axes[axis].range.max, 1e-12) << axisName(axis);
  }
}
