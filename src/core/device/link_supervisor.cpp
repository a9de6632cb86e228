#include "ptz_action_server/core/device/link_supervisor.h"

#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
LinkSupervisor::LinkSupervisor(double state_timeout, std::shared_ptr<const Clock> clock)
  : state_timeout_(state_timeout), clock_(std::move(clock))
{
}

void LinkSupervisor::name(const std::string& silent, const std::string& impossible)
{
  silent_ = silent;
  impossible_subject_ = impossible;
}

void LinkSupervisor::connected()
{
  connected_ = true;
  ready_ = false;
  has_report_ = false;
  impossible_.clear();
}

void LinkSupervisor::disconnected(const std::string& reason)
{
  if (was_up_)
  {
    lose(reason);
  }
  connected_ = false;
  ready_ = false;
  has_report_ = false;
}

void LinkSupervisor::ready()
{
  ready_ = true;
}

void LinkSupervisor::stateReported()
{
  check();  // a report after a silence ends that silence as a loss first
  const TimePoint now = clock_->now();
  impossible_.clear();
  last_report_at_ = now;
  last_position_at_ = now;
  has_report_ = true;
}

void LinkSupervisor::aliveReported()
{
  check();
  last_report_at_ = clock_->now();
  has_report_ = true;
}

void LinkSupervisor::impossibleReported(const std::string& why)
{
  check();
  impossible_ = why;
}

LinkSupervisor::Loss LinkSupervisor::check()
{
  const TimePoint now = clock_->now();
  if (!was_up_ || upAt(now))
  {
    return Loss::NONE;
  }
  if (onlyImpossible(now))
  {
    lose(formatText("only impossible %s for %.2f s (%s)", impossible_subject_.c_str(), state_timeout_,
                    impossible_.c_str()));
    return Loss::IMPOSSIBLE;
  }
  lose(formatText("no %s for %.2f s", silent_.c_str(), state_timeout_));
  return Loss::SILENCE;
}

LinkSupervisor::Rise LinkSupervisor::refresh()
{
  if (was_up_ || !upAt(clock_->now()))
  {
    return Rise::NONE;
  }
  was_up_ = true;
  if (!ever_up_)
  {
    ever_up_ = true;
    startup_changed_.notify_all();
    return Rise::FIRST;
  }
  const bool recovered = recovery_owed_;
  recovery_owed_ = false;
  return recovered ? Rise::RECOVERED : Rise::NONE;
}

bool LinkSupervisor::up() const
{
  return upAt(clock_->now());
}

bool LinkSupervisor::upAt(TimePoint now) const
{
  return connected_ && ready_ && has_report_ && secondsBetween(last_report_at_, now) <= state_timeout_ &&
         !onlyImpossible(now);
}

bool LinkSupervisor::onlyImpossible(TimePoint now) const
{
  return !impossible_.empty() && secondsBetween(last_position_at_, now) > state_timeout_;
}

void LinkSupervisor::lose(const std::string& reason)
{
  was_up_ = false;
  recovery_owed_ = true;
  ++losses_;
  last_loss_ = reason;
}

void LinkSupervisor::failStartup(const std::string& problem)
{
  startup_problem_ = problem;
  startup_changed_.notify_all();
}

bool LinkSupervisor::waitForStartup(std::unique_lock<std::mutex>& lock, double timeout)
{
  const bool settled =
      startup_changed_.wait_for(lock, toDuration(timeout), [this] { return ever_up_ || !startup_problem_.empty(); });
  return settled && startup_problem_.empty();
}

}  // namespace ptz_action_server
