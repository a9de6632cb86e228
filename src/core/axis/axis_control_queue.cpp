/**
 * \file
 * \brief AxisProtocol: the VAPIX PTZ control queue (VAPIX PTZ API, "Queuing API"). With `CtlQueueing=true` a channel
 * moves only for the client that holds PTZ control; the others' commands do not move it. The rest of the protocol is
 * in axis_protocol.cpp.
 */
#include <algorithm>

#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace
{
/// s between control requests, whatever the camera says: not a flood, and never so rare that control lapses.
constexpr double MIN_RENEW = 1.0;
constexpr double MAX_RENEW = 30.0;
}  // namespace

void AxisProtocol::findControlQueue()
{
  control_held_ = false;
  queue_poll_time_ = 0.0;
  std::string text;
  if (settings_.control_queue != AxisControlQueue::AUTO)
  {
    control_queue_ = settings_.control_queue == AxisControlQueue::ON;
    text = control_queue_ ? "on (control_queue: on)" : "off (control_queue: off)";
  }
  else
  {
    // Informative: a camera that does not tell (old firmware, a user who may not read parameters) queues nothing.
    control_queue_ = false;
    std::string problem;
    std::string body;
    vapix::QueueSettings queue;
    if (exchange(vapix::queueParametersPath(settings_.camera), "the PTZ queue parameters", body, problem))
    {
      problem = vapix::readQueueSettings(body, settings_.camera, queue);
    }
    control_queue_ = problem.empty() && queue.queueing;
    queue_poll_time_ = queue.poll_time;
    text = !problem.empty() ? "off: " + problem + " (set axis/control_queue: on if the camera queues PTZ control)" :
           control_queue_   ? "on (CtlQueueing=true)" :
                              "off (CtlQueueing=false)";
  }
  std::lock_guard<std::mutex> lock(facts_mutex_);
  queue_text_ = text;
}

bool AxisProtocol::requestControl()
{
  control_asked_at_ = session_.now();
  ++counters_.control_requests;
  const std::string path = formatText("%s?control=request&camera=%d", vapix::QUEUE_PATH, settings_.camera);
  std::string problem;
  if (exchange(path, "'control=request'", body_, problem))
  {
    problem = vapix::readQueueStatus(body_, queue_status_);
    if (!problem.empty())
    {
      ++counters_.malformed;
    }
  }
  else if (problem.empty())
  {
    problem = "the link was lost";
  }
  queue_problem_ = problem.empty() ? "" : "ptzqueue.cgi control=request: " + problem;
  control_held_ = problem.empty() && queue_status_.position == 1;
  // Ask again when the camera says to, and well before control or our place in the queue runs out.
  double renew = queue_status_.period > 0.0 ? queue_status_.period : MAX_RENEW;
  if (control_held_ && queue_status_.seconds > 0.0)
  {
    renew = std::min(renew, queue_status_.seconds / 2.0);
  }
  if (queue_poll_time_ > 0.0)
  {
    renew = std::min(renew, queue_poll_time_ / 2.0);
  }
  renew_after_ = std::clamp(renew, MIN_RENEW, MAX_RENEW);
  const std::string text = control_held_ ? formatText("on: control is ours (%g s left, renewed every %g s)",
                                                      queue_status_.seconds, renew_after_) :
                                           "on: " + withoutControl();
  std::lock_guard<std::mutex> lock(facts_mutex_);
  queue_text_ = text;
  return control_held_;
}

bool AxisProtocol::haveControl()
{
  if (!control_queue_)
  {
    return true;
  }
  if (!control_held_ || secondsBetween(control_asked_at_, session_.now()) >= renew_after_)
  {
    requestControl();
  }
  return control_held_;
}

std::string AxisProtocol::withoutControl() const
{
  if (!queue_problem_.empty())
  {
    return "PTZ control is queued on this Axis camera (CtlQueueing) and could not be had: " + queue_problem_;
  }
  if (queue_status_.position == 0)
  {
    return "PTZ control is queued on this Axis camera (CtlQueueing) and it did not put us in its queue";
  }
  return formatText("PTZ control is queued on this Axis camera (CtlQueueing) and another client holds it: we are "
                    "number %d in its queue, %s",
                    queue_status_.position,
                    queue_status_.seconds < 0.0 ? "with no end in sight (a client with infinite control)" :
                                                  formatText("about %g s from control", queue_status_.seconds).c_str());
}

void AxisProtocol::shutdown()
{
  if (!control_queue_ || !control_held_ || !session_.connected())
  {
    return;
  }
  std::string problem;
  exchange(formatText("%s?control=drop&camera=%d", vapix::QUEUE_PATH, settings_.camera), "'control=drop'", body_,
           problem);
  control_held_ = false;
}

}  // namespace ptz_action_server
