/**
 * \file
 * \brief One fixture per device backend and transport, for the backend contract suite: the emulator, a backend
 * configured for it, and what the contract needs to know of the protocol (how its commands look, how its link
 * breaks, what it refuses).
 */
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "ptz_action_server/core/device/device_backend.h"
#include "ptz_action_server/core/sim/sim_device_model.h"

namespace ptz_action_server
{
/// A command as the emulator received it, sorted into what the contract cares about.
struct DeviceCommand
{
  enum class Kind
  {
    MOVE,   ///< a position goal's command (or a velocity goal's, on protocols that aim a target)
    STOP,   ///< a stop or halt
    QUERY,  ///< a state poll, a subscription, a state request
    OTHER,  ///< set-up, speeds, modes
  };
  TimePoint at;
  Kind kind = Kind::OTHER;
  std::string text;   ///< readable, for failure messages
  bool aims = false;  ///< the command carries a pan it aims at (pan)
  double pan = 0.0;   ///< rad, the contract's sign
};

std::string describe(const std::vector<DeviceCommand>& commands);

/// A device backend against its emulator over one transport.
class DeviceFixture
{
public:
  virtual ~DeviceFixture() = default;

  /// A new backend configured for the emulator (not started). Device backends are DeviceBackends.
  virtual std::unique_ptr<DeviceBackend> makeBackend() = 0;

  /// Everything the emulator received since the last clearCommands(), oldest first.
  virtual std::vector<DeviceCommand> commands() const = 0;
  virtual void clearCommands() = 0;
  /// The emulator's own state: pan, tilt (rad) and zoom (X, or 1 without zoom).
  virtual PtzSample deviceState() const = 0;
  /// True once the emulator has read all the backend sends at start-up, so the cases see only their own commands.
  /// By default the link coming up tells (the device answers the last of it); see PanTilt for a device that does not.
  virtual bool startupReceived() const
  {
    return true;
  }

  /// The device stops answering (it reads and ignores everything).
  virtual void setSilent(bool silent) = 0;
  /// The link vanishes as it does on this transport: a port unplugged, a connection closed, a device gone.
  virtual void breakLink() = 0;
  /// The link can come back (the port replugged, the device listening again).
  virtual void restoreLink() = 0;
  /// True where breakLink() closes something the backend notices at once (a port, a connection); false for UDP,
  /// where only the silence tells.
  virtual bool breaksAtOnce() const
  {
    return true;
  }
  /// A word of lastLinkLoss() when breakLink() ended the goal.
  virtual std::string linkLossWords() const = 0;

  /// Gives the emulated device \p faults (a stalled axis, a lag, a reported offset); false when this emulator cannot
  /// (the contract cases that need faults then fail: every emulator must).
  virtual bool setFaults(const SimFaults& faults)
  {
    (void)faults;
    return false;
  }
  /// Makes every reply of the device one that never ends (bytes without a terminator or a frame: see
  /// DevicePort::setEndless()), or ends them again; false when this emulator cannot (the case skips).
  virtual bool setEndlessReplies(bool endless)
  {
    (void)endless;
    return false;
  }
  /// How long the device may take to answer a request before the backend gives up on it (the most its reply deadline
  /// learns, wire time aside), for SimFaults::reply_delay; 0 for devices that push their state unasked (the case
  /// skips).
  virtual double replyDeadline() const
  {
    return 0.0;
  }
  /// Makes the device send every state \p copies times (1: normally), a flood; false where it cannot (a device that
  /// only answers requests, or a serial line, whose baud rate bounds what it carries).
  virtual bool setFlood(unsigned copies)
  {
    (void)copies;
    return false;
  }
  /// Makes the emulated device accept every command and silently ignore \p axis from now on (it stays where it is),
  /// or obey it again (setFaults()).
  bool ignoreAxis(Axis axis, bool ignore);

  /// Makes the device refuse a goal: fills \p goal with one it refuses and returns the words its refusal carries,
  /// or "" for protocols without refusals (Pelco-D, PanTilt).
  virtual std::string prepareRefusal(AxisValues& goal)
  {
    (void)goal;
    return {};
  }

  /// Checks the commands goTo(\p target) produced against the protocol's frames (gtest assertions).
  virtual void expectGoalCommands(const std::vector<DeviceCommand>& commands, const AxisValues& target) const = 0;
  /// How many recovery holds \p commands contain, beside those of a goal to \p target (by default: stops).
  virtual std::size_t holds(const std::vector<DeviceCommand>& commands, const AxisValues& target) const;

  /// A position goal at \p pan, \p tilt, with a zoom the device has (2x) or none (1x).
  virtual AxisValues goal(double pan, double tilt) const
  {
    return AxisValues{ { pan, tilt, 1.0 } };
  }
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
