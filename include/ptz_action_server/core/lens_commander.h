/**
 * \file
 * \brief The node's lens commands before they reach the backend: checked, and a velocity stream with a dead-man.
 */
#pragma once

#include <array>
#include <string>
#include <vector>

#include "ptz_action_server/core/backend.h"
#include "ptz_action_server/core/lens.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief Checks each lens command against the device's lens and sends it on; stops a focus (iris) velocity when its
 * stream stops, as a joystick's dead-man does.
 *
 * A velocity is a stream: each message renews it for velocity_timeout s, and only a new value reaches the backend (a
 * 20 Hz joystick stream sends the device one command, not twenty a second). A zero, a position, a mode or a one-push
 * of the same function ends the stream. One thread (the node's main thread); time is passed in.
 */
class LensCommander
{
public:
  /// \p backend must outlive the commander; \p lens is what it has (Capabilities::lens), \p name its name for texts.
  LensCommander(PtzBackend& backend, const LensCapabilities& lens, std::string name, double velocity_timeout);

  /// Sends \p command (or only renews a running velocity); returns "" or why it was refused (then nothing is sent).
  std::string command(const LensCommand& command, TimePoint now);
  /// Stops every velocity not renewed within velocity_timeout of \p now (TimePoint::max(): every one running);
  /// returns the functions it stopped.
  std::vector<LensFunction> expire(TimePoint now);
  /// When the next velocity runs out (TimePoint::max(): none runs).
  TimePoint nextDeadline() const;

  double velocityTimeout() const
  {
    return velocity_timeout_;
  }

private:
  PtzBackend& backend_;
  const LensCapabilities lens_;
  const std::string name_;
  const double velocity_timeout_;
  std::array<double, LENS_FUNCTION_COUNT> velocity_{ { 0.0, 0.0 } };  ///< the running velocity sent, 0: none
  std::array<TimePoint, LENS_FUNCTION_COUNT> deadline_{ { TimePoint::max(), TimePoint::max() } };
};

}  // namespace ptz_action_server
