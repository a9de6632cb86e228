/**
 * \file
 * \brief The VAPIX PTZ control queue (VAPIX PTZ API, "Queuing API"): whether a video channel queues PTZ control
 * (param.cgi `root.PTZ.Various.V<n>.CtlQueueing`, `CtlQueuePollTime`) and what `ptzqueue.cgi?control=request|query`
 * answers (`<a name="pos"></a><a name="seconds"></a><a name="period"></a>`, or an `Error:` body).
 *
 * Pure functions: golden replies test them, and the fuzzer feeds them anything.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/axis/vapix_codec.h"

namespace ptz_action_server
{
namespace vapix
{
constexpr const char* QUEUE_PATH = "/axis-cgi/com/ptzqueue.cgi";

/// `/axis-cgi/param.cgi?action=list&group=root.PTZ.Various.V<camera>`: the channel's queue parameters.
std::string queueParametersPath(int camera);

/// A channel's queue parameters.
struct QueueSettings
{
  bool queueing = false;   ///< CtlQueueing=true: only the client that holds control may move the camera
  double poll_time = 0.0;  ///< CtlQueuePollTime, s a client in the queue may stay silent (0: not given)
};
/// Reads `root.PTZ.Various.V<camera>.CtlQueueing` (required: "true" or "false") and `...CtlQueuePollTime` from a
/// param.cgi list \p body; "" or what is wrong (a firmware without the parameter answers `# Error: ...`).
std::string readQueueSettings(const std::string& body, int camera, QueueSettings& settings);

/// What `control=request` or `control=query` answered.
struct QueueStatus
{
  int position = 0;      ///< 1: control is ours; 2..: our place in the queue; 0: not in the queue
  double seconds = 0.0;  ///< position 1: control time left; else the wait for it; -1: cannot be estimated
  double period = 0.0;   ///< s until the client should ask again to keep its place
};
/// Reads a queue answer; "" or what is wrong (an `Error:` body gives the camera's words).
std::string readQueueStatus(const std::string& body, QueueStatus& status);

}  // namespace vapix
}  // namespace ptz_action_server
