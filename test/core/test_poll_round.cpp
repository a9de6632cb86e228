/**
 * \file
 * \brief A poll round made of several answers (pan, then tilt, then zoom) is a state only when whole and unbroken.
 */
#include <gtest/gtest.h>

#include "ptz_action_server/core/device/poll_round.h"

using namespace ptz_action_server;

TEST(PollRound, AWholeRoundInOrderIsAState)
{
  PollRound round(3);
  EXPECT_FALSE(round.answered(0));
  EXPECT_FALSE(round.answered(1));
  EXPECT_TRUE(round.answered(2));
  // And the next round starts afresh.
  EXPECT_FALSE(round.answered(0));
  EXPECT_FALSE(round.answered(1));
  EXPECT_TRUE(round.answered(2));
}

TEST(PollRound, ARoundOfOneAnswerIsAStateAtEveryAnswer)
{
  PollRound round(1);
  EXPECT_TRUE(round.answered(0));
  EXPECT_TRUE(round.answered(0));
}

TEST(PollRound, ALossBetweenTheAnswersOfTwoRoundsMakesNoState)
{
  // The CI case: pan answered, then a silence took the zoom answer and the next pan question; the zoom answer after
  // it must not complete a state with the pan from before the silence.
  PollRound round(2);
  EXPECT_FALSE(round.answered(0));
  round.broken();
  EXPECT_FALSE(round.answered(1));
  EXPECT_FALSE(round.answered(0));
  EXPECT_TRUE(round.answered(1));
}

TEST(PollRound, AnAnswerOutOfTurnMakesNoState)
{
  PollRound round(3);
  EXPECT_FALSE(round.answered(0));
  EXPECT_FALSE(round.answered(2));  // the tilt answer went missing without a loss being seen
  EXPECT_FALSE(round.answered(1));
  EXPECT_FALSE(round.answered(2));
}

TEST(PollRound, ARoundStartedAgainDropsTheAnswersBefore)
{
  PollRound round(3);
  EXPECT_FALSE(round.answered(0));
  EXPECT_FALSE(round.answered(1));
  EXPECT_FALSE(round.answered(0));  // a new round: the old pan and tilt are left behind
  EXPECT_FALSE(round.answered(2));
  EXPECT_FALSE(round.answered(0));
  EXPECT_FALSE(round.answered(1));
  EXPECT_TRUE(round.answered(2));
}
