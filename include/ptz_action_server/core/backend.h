/**
 * \file
 * \brief The interface every device backend implements.
 */
#pragma once

#include <cstdint>
#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// A name/value pair a backend reports in the node's diagnostics.
using DiagnosticValue = std::pair<std::string, std::string>;

/// Appends counts as diagnostics values, in the order given.
inline void addCounts(std::vector<DiagnosticValue>& values,
                      std::initializer_list<std::pair<const char*, std::uint64_t>> counts)
{
  for (const auto& count : counts)
  {
    values.emplace_back(count.first, std::to_string(count.second));
  }
}

/// True when \p speed asks for a speed on some axis (PtzBackend::goToAtSpeed(): 0 is the backend's own speed).
inline bool asksSpeed(const AxisValues& speed)
{
  return speed[PAN] > 0.0 || speed[TILT] > 0.0 || speed[ZOOM] > 0.0;
}

/**
 * \brief A pan-tilt(-zoom) device, seen by the node.
 *
 * Threading contract (as ros_control's RobotHW states which calls may block):
 * - start() may block for a bounded time (opening a port, a handshake); it is called once, before any other call
 *   but name()/capabilities(), from the node's main thread.
 * - goTo(), moveAtVelocity(), stop(), aimInView(), sample(), lastFault(), lastLinkLoss() and diagnostics() never block
 *   on I/O:
 *   commands are queued to the backend's own I/O thread, and sample() returns the latest snapshot. They may be
 *   called from any thread.
 * - The sample listener, if the backend takes one, is called on the backend's own thread and must return at once.
 * - The destructor stops the I/O thread and joins it.
 *
 * Commands retarget the device from wherever it is: a goTo() while moving must not stop in between.
 */
class PtzBackend
{
public:
  virtual ~PtzBackend() = default;

  /// Short backend name, as used to load it ("sim", "flir", ...).
  virtual std::string name() const = 0;

  /// Limits, speeds and what each axis can do (AxisCapability). Valid after start(); backends that ask the device
  /// do so there, and say in AxisCapability::limitation what it lacks.
  virtual Capabilities capabilities() const = 0;

  /// Opens the device and starts the I/O thread. Throws BackendError with a reason when it cannot.
  virtual void start() = 0;

  /// Moves every present axis to \p position (pan, tilt in rad; zoom as X-factor). An axis given as NaN is left
  /// where it is: the goal leaves it alone on a device that cannot position or report it (see leavesAxisAlone()).
  virtual void goTo(const AxisValues& position) = 0;

  /**
   * \brief goTo() with each axis cruising at no more than \p speed (rad/s, X/s; 0: the backend's own speed, as goTo()).
   *
   * A backend whose device takes a speed with its absolute moves applies it on the axes its capabilities().speed
   * says (SpeedControl::DEVICE) and moves the others at its own speed; by default the speed is ignored (the node's
   * SpeedShapingBackend shapes the motion of the devices that take no speed).
   */
  virtual void goToAtSpeed(const AxisValues& position, const AxisValues& speed)
  {
    (void)speed;
    goTo(position);
  }

  /// Moves every present axis at \p velocity (rad/s, X/s) until stop(), another command or a limit.
  virtual void moveAtVelocity(const AxisValues& velocity) = 0;

  /// Decelerates every axis to rest where it is.
  virtual void stop() = 0;

  /// Centres \p target's point of the device's current picture by the device's own command, and with a box zooms so
  /// that it fills the view (capabilities().view_box_zoom; without it the box is only centred). Called only when
  /// capabilities().view_centre says the device can; by default it does nothing. Where it ends is the device's to
  /// say: the goal is judged on what it reports.
  virtual void aimInView(const ViewTarget& target)
  {
    (void)target;
  }

  /// The latest state of the device. Never blocks on I/O.
  virtual PtzSample sample() const = 0;

  /// Focus and iris (capabilities().lens says what the device has; the node checks a command with
  /// checkLensCommand() first). Never blocks on I/O; any thread. A lens command never ends or changes a goal.
  virtual void lens(const LensCommand& command)
  {
    (void)command;
  }
  /// The lens' latest modes, positions and fault count. Never blocks on I/O.
  virtual LensState lensState() const
  {
    return {};
  }
  /// Why the device last refused a lens command (the one that last incremented LensState::fault_count), or "".
  virtual std::string lastLensFault() const
  {
    return {};
  }

  /// Text of the most recent device fault (the one that last incremented PtzSample::fault_count).
  virtual std::string lastFault() const = 0;

  /// Why the link was last lost (the loss that last incremented PtzSample::link_losses, or the one under way), naming
  /// the link: "connection to 127.0.0.1:5500 closed", "no state from the FLIR PTU for 0.25 s". "" if never lost.
  virtual std::string lastLinkLoss() const
  {
    return {};
  }

  /// Called by the backend, on its own thread, each time its state may have changed on its own: a state report from
  /// the device, or the end of a simulated motion. It must not block (the node posts a verdict check).
  using SampleListener = std::function<void()>;

  /// Asks to be told of new state through \p listener. Called once, before start(). A backend that cannot tell
  /// returns false; goals on it are judged on the node's 10 Hz tick only.
  virtual bool setSampleListener(SampleListener listener)
  {
    (void)listener;
    return false;
  }

  /// What the backend had to warn its user about since the last call, oldest first, each text once: a guess it had to
  /// make, a device that contradicts itself, a controller it took over from. Any thread; never blocks on I/O. The
  /// node logs each one (ROS_WARN) and keeps them in its diagnostics.
  virtual std::vector<std::string> takeWarnings()
  {
    return {};
  }

  /// Appends link details and counters (dropped frames and the like) for the node's diagnostics.
  virtual void diagnostics(std::vector<DiagnosticValue>& values) const
  {
    (void)values;
  }
};

}  // namespace ptz_action_server
