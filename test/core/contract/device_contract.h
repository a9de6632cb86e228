/**
 * \file
 * \brief The backend contract suite's fixture: every device backend, over every transport it supports, against its
 * emulator (a DeviceFixture: the protocol's harness and what the contract expects of it).
 *
 * A new device joins by adding a fixture to allDeviceFixtures(). The cases never assert how fast something took on
 * the test's clock: they assert what the backend reported (a link that was still "up" after its deadline fails,
 * wherever the test thread was), and they wait on conditions with generous deadlines. Their sections:
 * test_device_contract.cpp (goals, cancel, refusals, axes), test_device_contract_links.cpp (silence and broken links)
 * and test_device_contract_faults.cpp (impossible states, endless and slow replies, floods).
 */
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>

#include "../goal_supervisor_fixture.h"
#include "../wait_until.h"
#include "device_fixtures.h"
#include "ptz_action_server/core/goal/goal_monitor.h"

namespace ptz_action_server
{
constexpr double WAIT = 15.0;           ///< s: generous, for a loaded machine
constexpr double DEADLINE_SLACK = 0.3;  ///< s a late report may stretch the state timeout (loaded I/O thread)

class DeviceContract : public ::testing::TestWithParam<FixtureMaker>
{
protected:
  void SetUp() override
  {
    device_ = GetParam().make();
    harness_ = &device_->harness();
    backend_ = device_->makeBackend();
    backend_->start();
    ASSERT_TRUE(waitUntil([&] { return backend_->sample().link_up; }, WAIT)) << "the link never came up";
    ASSERT_TRUE(waitUntil([&] { return harness_->startupReceived(); }, WAIT)) << "the start-up never reached the "
                                                                                 "device";
  }

  double stateTimeout() const
  {
    return backend_->session().config().state_timeout;
  }

  bool atRest(const AxisValues& target) const
  {
    const PtzSample sample = backend_->sample();
    const Capabilities capabilities = backend_->capabilities();
    for (Axis axis : ALL_AXES)
    {
      if (capabilities.axes[axis].present &&
          std::abs(sample.position[axis] - target[axis]) > 2e-3 * (axis == ZOOM ? 10 : 1))
      {
        return false;
      }
    }
    return sample.link_up && !sample.moving;
  }

  bool waitForRest(const AxisValues& target)
  {
    return waitUntil([&] { return atRest(target); }, WAIT);
  }

  /// Starts a long goal (2.6 rad: inside every device's pan range, far enough for a busy test thread to act well
  /// before the device gets there) and waits until the device moves fast towards it.
  AxisValues startLongGoal()
  {
    const AxisValues far = device_->goal(2.6, 0.0);
    backend_->goTo(far);
    EXPECT_TRUE(waitUntil([&] { return harness_->deviceState().position[PAN] > 0.5; }, WAIT));
    return far;
  }

  /// Feeds samples to \p monitor until it ends the goal; remembers the last sample that still said "link up".
  GoalVerdict superviseUntilFinal(GoalMonitor& monitor)
  {
    GoalVerdict verdict;
    waitUntil(
        [&] {
          const PtzSample sample = backend_->sample();
          if (sample.link_up)
          {
            last_up_at_ = sample.stamp;
          }
          verdict = monitor.update(sample, SteadyClock::now());
          return verdict.phase != GoalPhase::ACTIVE;
        },
        WAIT);
    return verdict;
  }

  GoalMonitor monitorFor(const AxisValues& target, const GoalMonitorConfig& config = GoalMonitorConfig()) const
  {
    return GoalMonitor::forPosition(target, backend_->sample(), backend_->capabilities(), config, SteadyClock::now());
  }

  std::unique_ptr<DeviceFixture> device_;
  DeviceHarness* harness_ = nullptr;  ///< device_'s
  std::unique_ptr<DeviceBackend> backend_;
  TimePoint last_up_at_{};
};

/// A position goal the node's supervisor runs on the backend, to its end; \p extra_margin s added to the goal timeout's
/// margin (goal_timeout_margin), as a user of a slow device sets it.
inline std::string runGoalToItsEnd(PtzBackend& backend, const AxisValues& target, double stall_timeout,
                                   double extra_margin = 0.0)
{
  GoalMonitorConfig config;
  config.stall_timeout = stall_timeout;
  config.timeout_margin += extra_margin;
  return goal_supervisor_test::runGoalToItsEnd(
      std::shared_ptr<PtzBackend>(&backend, [](PtzBackend*) {}),
      goal_supervisor_test::positionGoal(target[PAN], target[TILT], target[ZOOM]), config, WAIT);
}

}  // namespace ptz_action_server
