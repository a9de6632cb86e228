/**
 * \file
 * \brief Link supervision in one place: the state deadline, losses with their reason, the start-up wait and "up or
 * down". DeviceSession, the joint_topics backend and the sim backend use it; none of them keeps its own copy.
 */
#pragma once

#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>

#include "ptz_action_server/core/counter.h"
#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/**
 * \brief Decides whether a device's link is up, counts every loss with its reason, and lets start() wait for the first
 * time it is up.
 *
 * The link is up while it is connected, the owner has said ready() on this connection, a valid report (a state, or an
 * answer without one) came within state_timeout, and not only impossible states came for state_timeout. A link that
 * has no connections of its own (topics, a simulation) calls connected() and ready() once.
 *
 * Every transition from up to down is one loss, with the reason: the connection's own ("connection to ... closed"),
 * or "no <state source> for 0.50 s", or "only impossible <state source> for 0.50 s (<why>)". A silence counts as a loss
 * as soon as check() sees it, whoever calls it (a timer, sample(), a late report): a report after a silence ends that
 * silence as a loss first.
 *
 * Time comes from the injected Clock (tests drive a ManualClock); only waitForStartup() waits in real time.
 *
 * Not thread-safe: the owner guards it with its own mutex, the one it hands waitForStartup() (as MotionEstimator, it
 * is a part of its owner's snapshot). losses() alone may be read from any thread.
 */
class LinkSupervisor
{
public:
  /// What check() found.
  enum class Loss
  {
    NONE,        ///< no new loss (up, or already counted)
    SILENCE,     ///< no valid report for state_timeout
    IMPOSSIBLE,  ///< nothing but impossible states for state_timeout: the owner may forget its plausibility reference
  };
  /// What refresh() found.
  enum class Rise
  {
    NONE,       ///< nothing changed (still down, or up already)
    FIRST,      ///< up for the first time since construction (start-up is over)
    RECOVERED,  ///< up again after a loss: the owner holds the device where it is, once
  };

  /// \p state_timeout: s a link may go without a valid report (infinity: a link without a deadline).
  LinkSupervisor(double state_timeout, std::shared_ptr<const Clock> clock);

  /// What losses name: "no <silent> for 0.50 s", "only impossible <impossible> for 0.50 s (...)".
  void name(const std::string& silent, const std::string& impossible);
  double stateTimeout() const
  {
    return state_timeout_;
  }
  /// The state deadline is \p state_timeout s from now on (a device whose replies take longer gets longer), for the
  /// report under way too.
  void setStateTimeout(double state_timeout)
  {
    state_timeout_ = state_timeout;
  }

  // ---------------------------------------------------------------- the connection

  /// A new connection: not up until ready() and a report on it; the impossible states before it are forgotten.
  void connected();
  /// The connection closed: a loss with \p reason if the link was up.
  void disconnected(const std::string& reason);
  /// The owner knows the device on this connection (its set-up is done).
  void ready();

  // ---------------------------------------------------------------- reports (each check()s first)

  /// A possible state: keeps the link alive and ends any run of impossible ones.
  void stateReported();
  /// A valid answer without a state: keeps the link alive (a run of impossible states goes on).
  void aliveReported();
  /// A state dropped as impossible, and why. Only impossible states for state_timeout lose the link.
  void impossibleReported(const std::string& why);

  /// Counts a loss if the link was up and is not any more (the deadline passed); says which.
  Loss check();
  /// Marks the link up if it now is and was not (call after a report or ready()); says whether it rose, and how.
  /// Wakes waitForStartup() the first time.
  Rise refresh();
  /// Up now: connected, ready, a valid report within state_timeout, not only impossible states. No side effect (call
  /// check() first to count a loss the deadline made).
  bool up() const;

  /// Losses so far (any thread).
  std::uint64_t losses() const
  {
    return losses_.value();
  }
  /// Why the link was last lost ("" if it never was).
  const std::string& lastLoss() const
  {
    return last_loss_;
  }
  /// Why the reports since the last possible state were dropped ("" if none was).
  const std::string& impossibleReason() const
  {
    return impossible_;
  }

  // ---------------------------------------------------------------- start-up

  /// The device cannot be used as configured: waitForStartup() ends at once, with \p problem.
  void failStartup(const std::string& problem);
  const std::string& startupProblem() const
  {
    return startup_problem_;
  }
  /// The link has been up at least once.
  bool everUp() const
  {
    return ever_up_;
  }
  /**
   * \brief Waits up to \p timeout s (real time) until the link is first up or start-up failed.
   *
   * \p lock holds the owner's mutex (the one guarding this object); it is released while waiting. True once the link
   * has been up and no start-up problem was given; false otherwise (see startupProblem(), impossibleReason()).
   */
  bool waitForStartup(std::unique_lock<std::mutex>& lock, double timeout);

private:
  /// Nothing but impossible states came for state_timeout.
  bool onlyImpossible(TimePoint now) const;
  bool upAt(TimePoint now) const;
  void lose(const std::string& reason);

  double state_timeout_;
  const std::shared_ptr<const Clock> clock_;
  std::string silent_ = "state";
  std::string impossible_subject_ = "states";
  std::condition_variable startup_changed_;

  bool connected_ = false;
  bool ready_ = false;
  bool has_report_ = false;       ///< a valid report arrived on this connection
  TimePoint last_report_at_{};    ///< the last valid report on this connection
  TimePoint last_position_at_{};  ///< the last possible state on this connection
  std::string impossible_;        ///< why the reports since the last possible state were dropped
  bool was_up_ = false;           ///< the link counted as up at the last check()/refresh()
  bool ever_up_ = false;
  bool recovery_owed_ = false;  ///< a loss happened: the next rise is a recovery
  Counter losses_;
  std::string last_loss_;
  std::string startup_problem_;
};

}  // namespace ptz_action_server
