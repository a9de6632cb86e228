/**
 * \file
 * \brief A poll round made of several answers (pan, then tilt, then zoom) is a state only when whole and unbroken.
 */
#include <gtest/gtest.h>

#include <vector>

#include "ptz_action_server/core/device/poll_round.h"

using namespace ptz_action_server;

namespace
{
constexpr int LOST = -1;  ///< a request lost between two answers

/// What \p round says to each of \p events in turn (an answer's index, or LOST): true where a state is whole.
std::vector<bool> feed(PollRound& round, const std::vector<int>& events)
{
  std::vector<bool> whole;
  for (int event : events)
  {
    if (event == LOST)
    {
      round.broken();
      continue;
    }
    whole.push_back(round.answered(static_cast<std::size_t>(event)));
  }
  return whole;
}

TEST(PollRound, AWholeRoundInOrderIsAStateAndTheNextStartsAfresh)
{
  PollRound round(3);
  EXPECT_EQ(feed(round, { 0, 1, 2, 0, 1, 2 }), (std::vector<bool>{ false, false, true, false, false, true }));
}

TEST(PollRound, ARoundOfOneAnswerIsAStateAtEveryAnswer)
{
  PollRound round(1);
  EXPECT_EQ(feed(round, { 0, 0 }), (std::vector<bool>{ true, true }));
}

TEST(PollRound, ALossBetweenTheAnswersOfTwoRoundsMakesNoState)
{
  // The CI case: pan answered, then a silence took the zoom answer and the next pan question; the zoom answer after
  // it must not complete a state with the pan from before the silence.
  PollRound round(2);
  EXPECT_EQ(feed(round, { 0, LOST, 1, 0, 1 }), (std::vector<bool>{ false, false, false, true }));
}

TEST(PollRound, AnAnswerOutOfTurnMakesNoState)
{
  PollRound round(3);
  // The tilt answer went missing without a loss being seen.
  EXPECT_EQ(feed(round, { 0, 2, 1, 2 }), (std::vector<bool>{ false, false, false, false }));
}

TEST(PollRound, ARoundStartedAgainDropsTheAnswersBefore)
{
  PollRound round(3);
  // A new round after pan and tilt: they are left behind, and its own zoom answer comes out of turn.
  EXPECT_EQ(feed(round, { 0, 1, 0, 2 }), (std::vector<bool>{ false, false, false, false }));
}

}  // namespace
