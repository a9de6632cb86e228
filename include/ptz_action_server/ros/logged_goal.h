/**
 * \file
 * \brief A goal with no client to answer (a clicked point, a click on an image): the GoalSupervisor sees it as any
 * goal, and its end is logged.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/goal/goal_supervisor.h"

namespace ptz_action_server
{
/// How a kind of LoggedGoal names itself in the supervisor and the log.
struct LoggedGoalWording
{
  const char* action;  ///< the action name the supervisor and the log know it by
  const char* doing;   ///< "aiming at": what an accepted goal does to its target
  const char* done;    ///< "aimed at": what a succeeded goal did
};

/// A clicked point in rviz (look_at_clicked_point).
extern const LoggedGoalWording CLICKED_POINT_GOAL;
/// A click on an image (`<image topic>_mouse_left`).
extern const LoggedGoalWording IMAGE_CLICK_GOAL;

/**
 * \brief A goal from a topic. A rejection or an abort is logged as a warning with the reason, an acceptance as info,
 * a success or preemption at debug level.
 */
class LoggedGoal : public GoalHandle
{
public:
  /// \p id: unique among goals of \p wording; \p where: the target as the log shows it.
  LoggedGoal(const LoggedGoalWording& wording, std::string id, std::string where);

  const std::string& action() const override
  {
    return action_;
  }
  const std::string& id() const override
  {
    return id_;
  }
  void accept(const std::string& text) override;
  void reject(const std::string& text) override;
  void publishFeedback(const AxisValues&) override
  {
  }
  void succeed(const std::string& text) override;
  void abort(const std::string& text) override;
  void preempt(const std::string& text) override;

private:
  const LoggedGoalWording& wording_;
  const std::string action_;
  const std::string id_;
  const std::string where_;
};

}  // namespace ptz_action_server
