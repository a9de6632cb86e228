/**
 * \file
 * \brief One state from several answers asked one after the other (pan, then tilt, then zoom).
 */
#pragma once

#include <cstddef>

namespace ptz_action_server
{
/**
 * \brief Says when the answers of a poll round make one state: every answer came, each right after the one before it,
 * with no request lost in between.
 *
 * Without it, a round whose first answer came before a silence and whose last came after it makes one state of a pan
 * from before the silence and a zoom from after: a device that moved meanwhile seems to jump back, and its true
 * reports that follow look like a jump away (issue 22's CI: a VISCA camera dropped for 1.5 s after a recovery).
 *
 * Not thread-safe: the protocol's I/O thread owns it.
 */
class PollRound
{
public:
  /// A round of \p answers answers (1: every answer is a whole state).
  explicit PollRound(std::size_t answers) : answers_(answers)
  {
  }

  /// Answer \p index (0: the round's first) came; true when it completes the round.
  bool answered(std::size_t index)
  {
    next_ = index == 0 || index == next_ ? index + 1 : 0;
    if (next_ < answers_)
    {
      return false;
    }
    next_ = 0;
    return true;
  }

  /// A request was lost, an answer was unusable or the link went down: the answers so far make no state.
  void broken()
  {
    next_ = 0;
  }

private:
  std::size_t answers_;
  std::size_t next_ = 0;  ///< the index of the answer that continues the round
};

}  // namespace ptz_action_server
