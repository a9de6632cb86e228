/**
 * \file
 * \brief One fixture per device backend and transport, for the backend contract suite: the protocol's harness (its
 * emulator, a backend configured for it, what the emulator received, classified: test/harness/) and what the contract
 * expects of the protocol beyond it (how a goal's commands look, how its link loss reads, what it refuses).
 */
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "harness/device_harness.h"

namespace ptz_action_server
{
/// "cmd | cmd | ...", for failure messages.
std::string describe(const std::vector<ClassifiedCommand>& commands);

/// A device backend against its emulator over one transport: its harness and the contract's expectations.
class DeviceFixture
{
public:
  virtual ~DeviceFixture() = default;

  /// The emulator and the backend's configuration.
  virtual DeviceHarness& harness() = 0;
  /// A new backend configured for the emulator (not started); a fixture may skip the running case here.
  virtual std::unique_ptr<DeviceBackend> makeBackend()
  {
    return harness().makeBackend();
  }

  /// A word of lastLinkLoss() when DeviceHarness::breakLink() ended the goal.
  virtual std::string linkLossWords() const = 0;
  /// How long the device may take to answer a request before the backend gives up on it (the most its reply deadline
  /// learns, wire time aside), for SimFaults::reply_delay; 0 for devices that push their state unasked (the case
  /// skips).
  virtual double replyDeadline() const
  {
    return 0.0;
  }
  /// Makes the emulated device accept every command and silently ignore \p axis from now on (it stays where it is),
  /// or obey it again (DeviceHarness::setFaults()).
  void ignoreAxis(Axis axis, bool ignore);

  /// Makes the device refuse a goal: fills \p goal with one it refuses and returns the words its refusal carries,
  /// or "" for protocols without refusals (Pelco-D, PanTilt).
  virtual std::string prepareRefusal(AxisValues& goal)
  {
    (void)goal;
    return {};
  }

  /// Checks the commands goTo(\p target) produced against the protocol's frames (gtest assertions).
  virtual void expectGoalCommands(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const = 0;
  /// How many recovery holds \p commands contain, beside those of a goal to \p target (by default: stops).
  virtual std::size_t holds(const std::vector<ClassifiedCommand>& commands, const AxisValues& target) const;

  /// A position goal at \p pan, \p tilt, with a zoom the device has (2x) or none (1x).
  virtual AxisValues goal(double pan, double tilt) const
  {
    return AxisValues{ { pan, tilt, 1.0 } };
  }
};

/// A fixture on a \p Harness of its own (its emulator and configuration at hand for the expectations).
template <class Harness>
class HarnessFixture : public DeviceFixture
{
public:
  template <class... Arguments>
  explicit HarnessFixture(Arguments&&... arguments) : harness_(std::forward<Arguments>(arguments)...)
  {
  }
  DeviceHarness& harness() override
  {
    return harness_;
  }

protected:
  Harness harness_;
};

/// A named way to make a fixture, for INSTANTIATE_TEST_SUITE_P.
struct FixtureMaker
{
  std::string name;
  std::function<std::unique_ptr<DeviceFixture>()> make;
};

/// Every device backend over every transport it supports: what the protocols' fixture files registered, by name.
std::vector<FixtureMaker> allDeviceFixtures();

/// Adds a protocol's fixtures to allDeviceFixtures(): a static object in its fixture file, so that adding a protocol's
/// fixture is listing its file in the protocol's registration (cmake/protocols.cmake), nothing else.
struct DeviceFixtureRegistration
{
  explicit DeviceFixtureRegistration(std::vector<FixtureMaker> fixtures);
};

}  // namespace ptz_action_server
