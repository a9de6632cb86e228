#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <memory>

#include "ptz_action_server/core/sim/sim_backend.h"
#include "wait_until.h"

using namespace ptz_action_server;

namespace
{
class SimBackendTest : public ::testing::Test
{
protected:
  SimBackendTest() : clock_(std::make_shared<ManualClock>()), backend_(SimDeviceConfig::defaults(), clock_)
  {
    backend_.start();
  }

  std::shared_ptr<ManualClock> clock_;
  SimBackend backend_;
};

bool onGrid(double value, double resolution)
{
  const double steps = value / resolution;
  return std::abs(steps - std::round(steps)) < 1e-6;
}
}  // namespace

TEST_F(SimBackendTest, ReachesTheGoalQuantisedToTheResolution)
{
  const double resolution = SimDeviceConfig::defaults().axes[PAN].resolution;
  backend_.goTo({ 0.5, -0.25, 6.0 });
  clock_->advance(0.2);
  PtzSample sample = backend_.sample();
  EXPECT_TRUE(sample.link_up);
  EXPECT_TRUE(sample.moving);
  EXPECT_TRUE(onGrid(sample.position[PAN], resolution)) << sample.position[PAN];
  clock_->advance(3.0);
  sample = backend_.sample();
  EXPECT_FALSE(sample.moving);
  EXPECT_NEAR(sample.position[PAN], 0.5, resolution / 2);
  EXPECT_NEAR(sample.position[TILT], -0.25, resolution / 2);
  EXPECT_TRUE(onGrid(sample.position[TILT], resolution));
  EXPECT_DOUBLE_EQ(sample.position[ZOOM], 6.0);
}

TEST_F(SimBackendTest, ZoomSlewsAtItsRate)
{
  backend_.goTo({ 0.0, 0.0, 9.0 });
  clock_->advance(0.5);
  EXPECT_NEAR(backend_.sample().position[ZOOM], 5.0, 1e-9);  // 1 + 8 X/s * 0.5 s
  EXPECT_NEAR(backend_.sample().velocity[ZOOM], 8.0, 1e-9);
}

TEST_F(SimBackendTest, StalledAxisFreezesAndIgnoresCommands)
{
  backend_.goTo({ 1.0, 1.0, 1.0 });
  clock_->advance(0.3);
  SimFaults faults;
  faults.stalled[TILT] = true;
  backend_.setFaults(faults, false);
  const double frozen = backend_.sample().position[TILT];
  EXPECT_GT(frozen, 0.05);
  backend_.goTo({ 0.0, -1.0, 1.0 });
  clock_->advance(2.0);
  const PtzSample sample = backend_.sample();
  EXPECT_DOUBLE_EQ(sample.position[TILT], frozen);
  EXPECT_NEAR(sample.position[PAN], 0.0, 1e-3);  // the other axes still obey
}

TEST_F(SimBackendTest, LagDelaysTheStartOfAMove)
{
  SimFaults faults;
  faults.lag = 0.5;
  backend_.setFaults(faults, false);
  backend_.goTo({ 1.0, 0.0, 1.0 });
  clock_->advance(0.45);
  EXPECT_FALSE(backend_.sample().moving);
  EXPECT_DOUBLE_EQ(backend_.sample().position[PAN], 0.0);
  clock_->advance(0.1);
  EXPECT_TRUE(backend_.sample().moving);
  EXPECT_GT(backend_.sample().position[PAN], 0.0);
}

TEST_F(SimBackendTest, DropoutFreezesStateLosesCommandsAndRecovers)
{
  backend_.goTo({ 2.0, 0.0, 1.0 });
  clock_->advance(0.5);
  EXPECT_EQ(backend_.sample().link_losses, 0u);
  EXPECT_EQ(backend_.lastLinkLoss(), "");
  backend_.setFaults(SimFaults{}, true);
  const PtzSample frozen = backend_.sample();
  EXPECT_FALSE(frozen.link_up);
  EXPECT_EQ(frozen.link_losses, 1u);
  EXPECT_EQ(backend_.lastLinkLoss(), "the simulated device dropped out");
  backend_.stop();  // lost: the device keeps going to 2.0
  clock_->advance(3.0);
  EXPECT_DOUBLE_EQ(backend_.sample().position[PAN], frozen.position[PAN]);
  EXPECT_FALSE(backend_.sample().link_up);

  backend_.setFaults(SimFaults{}, false);
  PtzSample sample = backend_.sample();
  EXPECT_TRUE(sample.link_up);
  EXPECT_EQ(sample.link_losses, 1u);  // the loss stays counted after the recovery
  EXPECT_NEAR(sample.position[PAN], 2.0, 1e-3);
  backend_.goTo({ -1.0, 0.0, 1.0 });
  clock_->advance(5.0);
  EXPECT_NEAR(backend_.sample().position[PAN], -1.0, 1e-3);

  std::vector<DiagnosticValue> values;
  backend_.diagnostics(values);
  ASSERT_FALSE(values.empty());
  EXPECT_EQ(values[1], DiagnosticValue("commands lost in dropout", "1"));
}

TEST_F(SimBackendTest, VelocityModeStopsAtTheLimit)
{
  backend_.moveAtVelocity({ -1.5, 0.0, 0.0 });
  clock_->advance(10.0);
  const PtzSample sample = backend_.sample();
  EXPECT_FALSE(sample.moving);
  EXPECT_NEAR(sample.position[PAN], -M_PI, 1e-3);
  EXPECT_GE(sample.position[PAN], -M_PI);
}

TEST_F(SimBackendTest, CapabilitiesComeFromTheConfig)
{
  SimDeviceConfig config = SimDeviceConfig::defaults();
  config.axes[ZOOM].present = false;
  config.axes[TILT].range = AxisRange{ -0.8, 0.5 };
  SimBackend backend(config, clock_);
  const Capabilities capabilities = backend.capabilities();
  EXPECT_FALSE(capabilities.axes[ZOOM].present);
  EXPECT_DOUBLE_EQ(capabilities.axes[TILT].range.min, -0.8);
  EXPECT_DOUBLE_EQ(capabilities.axes[PAN].max_speed, 1.5);
  EXPECT_DOUBLE_EQ(backend.sample().position[ZOOM], 1.0);  // no zoom reports 1
}

TEST(SimBackendListenerTest, TellsWhenEachMotionEndsAndNotInBetween)
{
  SimBackend backend(SimDeviceConfig::defaults());
  std::atomic<int> calls{ 0 };
  std::atomic<int> moving_when_told{ 0 };
  ASSERT_TRUE(backend.setSampleListener([&] {
    moving_when_told += backend.sample().moving ? 1 : 0;
    ++calls;
  }));
  backend.start();
  backend.goTo({ 0.2, 0.1, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return calls >= 1; }, 30.0));
  EXPECT_EQ(moving_when_told, 0) << "told before the motion had ended";
  EXPECT_NEAR(backend.sample().position[PAN], 0.2, 1e-3);
  backend.goTo({ -0.2, 0.0, 1.0 });
  ASSERT_TRUE(waitUntil([&] { return calls >= 2; }, 30.0));
  EXPECT_FALSE(backend.sample().moving);
  EXPECT_EQ(calls, 2) << "one call per motion: the thread sleeps in between";
  EXPECT_EQ(moving_when_told, 0);
}

TEST(SimBackendListenerTest, ARetargetBeforeTheEndMovesTheNotice)
{
  SimBackend backend(SimDeviceConfig::defaults());
  std::atomic<int> calls{ 0 };
  backend.setSampleListener([&] { ++calls; });
  backend.start();
  backend.goTo({ 1.0, 0.0, 1.0 });
  backend.goTo({ 0.1, 0.0, 1.0 });  // at once: the first motion never ends by itself
  ASSERT_TRUE(waitUntil([&] { return calls >= 1; }, 30.0));
  EXPECT_NEAR(backend.sample().position[PAN], 0.1, 1e-3);
  EXPECT_FALSE(backend.sample().moving);
  EXPECT_EQ(calls, 1);
}
