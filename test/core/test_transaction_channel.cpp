/**
 * \file
 * \brief The request/reply channel of the line protocols (FLIR, Pelco-D, VISCA) on an injected clock: one request on
 * the wire at a time, urgent requests, late replies never taken one request behind, and the reply deadline learnt from
 * the device's answers (a late answer before the next request went out is the overdue request's, and teaches it).
 *
 * The channel's timers run in real time (the test runs its io_context by hand, so nothing fires unless it does); the
 * times it measures and its drain are the injected clock's, so the answer times here are exact.
 */
#include <gtest/gtest.h>

#include <chrono>

#include "ptz_action_server/core/device/transaction_channel.h"

using namespace ptz_action_server;

namespace
{
constexpr double WAIT = 10.0;

/// Runs \p context until \p condition holds (or the deadline passes).
bool runUntil(boost::asio::io_context& context, const std::function<bool()>& condition)
{
  const TimePoint deadline = addSeconds(SteadyClock::now(), WAIT);
  while (!condition() && SteadyClock::now() < deadline)
  {
    context.restart();
    context.run_one_for(std::chrono::milliseconds(20));
  }
  return condition();
}

/// A reply that answers requests of \p tag only (a protocol whose replies say what they answer).
std::function<bool(const TransactionChannel::Request&)> answersTag(int tag)
{
  return [tag](const TransactionChannel::Request& on_wire) { return on_wire.tag == tag; };
}

TEST(ReplyTiming, LearnsHalfAgainTheLongestOfTheLatestAnswersBetweenItsFloorAndTwiceIt)
{
  ReplyTiming timing(0.1);
  EXPECT_DOUBLE_EQ(timing.deadline(), 0.1);
  EXPECT_DOUBLE_EQ(timing.ceiling(), 0.2);
  EXPECT_FALSE(timing.answered(0.005)) << "a fast device keeps the floor";
  EXPECT_DOUBLE_EQ(timing.deadline(), 0.1);
  // A PTZOptics G2's pan-tilt answers (88 to 123 ms) among its zoom answers (26 to 58 ms).
  for (double answer : { 0.088, 0.026, 0.123, 0.058, 0.101 })
  {
    timing.answered(answer);
  }
  EXPECT_NEAR(timing.deadline(), 1.5 * 0.123, 1e-12);
  EXPECT_DOUBLE_EQ(timing.longest(), 0.123);
  EXPECT_DOUBLE_EQ(timing.typical(), 0.088);
  EXPECT_TRUE(timing.answered(0.19));
  EXPECT_DOUBLE_EQ(timing.deadline(), 0.2) << "never past the ceiling";
  // The slow answers leave the window: back to the floor.
  for (std::size_t answer = 0; answer < ReplyTiming::ANSWERS; ++answer)
  {
    timing.answered(0.01);
  }
  EXPECT_DOUBLE_EQ(timing.deadline(), 0.1);
  std::vector<DiagnosticValue> values;
  timing.diagnostics(values);
  EXPECT_EQ(values.at(0), DiagnosticValue("reply deadline (s, learnt)", "0.100"));
  EXPECT_EQ(values.at(1), DiagnosticValue("reply deadline bounds (s)", "0.100 to 0.200"));
  EXPECT_EQ(values.at(2), DiagnosticValue("answer time median / longest (ms, latest answers)", "10 / 10"));
}

TEST(TransactionChannel, RunsOnTheInjectedClock)
{
  // A clock that stands still, far from the steady clock: the drain after a timeout ends when *it* says so.
  boost::asio::io_context context;
  ManualClock clock(TimePoint(std::chrono::hours(1000)));
  std::vector<std::string> written;
  int timeouts = 0;
  TransactionChannel channel(
      context, clock, [&](const std::string& bytes) { written.push_back(bytes); }, 0.01,
      [&](const TransactionChannel::Request&) { ++timeouts; });
  channel.queue({ "A", 1, true, 0 });
  channel.queue({ "B", 2, true, 0 });
  EXPECT_EQ(written, (std::vector<std::string>{ "A" }));  // one on the wire at a time
  ASSERT_TRUE(runUntil(context, [&] { return timeouts == 1; }));

  // Draining: B waits until the injected clock passes the drain time (a deadline after A's), however long the steady
  // clock runs meanwhile (this shows nothing happening for a while).
  context.restart();
  context.run_for(std::chrono::milliseconds(100));
  EXPECT_EQ(written.size(), 1u) << "B went out while the injected clock still said \"draining\"";
  clock.advance(0.02);
  channel.queue({ "C", 3, true, 0 });  // any activity pumps the queue once the drain is over
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written.back(), "B");
  // A's answer now would come one request behind: for B, as the device answers in order.
  const std::optional<TransactionChannel::Request> answered = channel.complete();
  ASSERT_TRUE(answered.has_value());
  EXPECT_EQ(answered->tag, 2);
  EXPECT_EQ(channel.lateRepliesTaken(), 0u);
}

/// A channel on a ManualClock whose reply deadline starts at \p floor s (learning up to twice that), its writes and
/// timeouts kept.
class ChannelOnManualClock : public ::testing::Test
{
protected:
  explicit ChannelOnManualClock(double floor = 1.0)
    : channel_{ context_, clock_, [this](const std::string& bytes) { written_.push_back(bytes); }, floor,
                [this](const TransactionChannel::Request& lost) { lost_.push_back(lost.tag); } }
  {
  }

  /// Runs the channel's timers (in real time) until the request on the wire is overdue.
  void untilOverdue()
  {
    const std::size_t before = lost_.size();
    ASSERT_TRUE(runUntil(context_, [&] { return lost_.size() > before; }));
  }
  /// Sends \p tag and has it answered \p seconds later (on the injected clock), in time.
  void answerIn(int tag, double seconds)
  {
    channel_.queue({ "Q", tag, true, 0 });
    clock_.advance(seconds);
    ASSERT_TRUE(channel_.complete(answersTag(tag)).has_value());
  }

  boost::asio::io_context context_;
  ManualClock clock_;
  std::vector<std::string> written_;
  std::vector<int> lost_;
  TransactionChannel channel_;
};

TEST_F(ChannelOnManualClock, AnUrgentRequestGoesOutAheadOfTheQueue)
{
  TransactionChannel& channel = channel_;
  std::vector<std::string>& written = written_;
  channel.queue({ "A", 1, true, 0 });
  channel.queue({ "B", 2, true, 0 });
  channel.sendUrgent({ "HALT", 3, true, 0 });
  EXPECT_EQ(written, (std::vector<std::string>{ "A", "HALT" }));
  EXPECT_EQ(channel.complete()->tag, 1);  // the device answers in order: A first, then the halt
  EXPECT_EQ(channel.complete()->tag, 3);
  EXPECT_EQ(written.back(), "B");
}

TEST_F(ChannelOnManualClock, AReplyThatDoesNotAnswerTheRequestOnTheWireLeavesItWaitingForItsOwn)
{
  // A reply later than the drain, on a device whose replies say what they answer: it must not take the place of the
  // reply of the request now on the wire, or every reply from then on would be matched one request behind.
  TransactionChannel& channel = channel_;
  std::vector<std::string>& written = written_;
  channel.queue({ "PAN?", 1, true, 0 });
  channel.queue({ "TILT?", 2, true, 0 });
  // The pan answer came: the tilt question goes out.
  ASSERT_EQ(channel.complete(answersTag(1))->tag, 1);
  EXPECT_EQ(written.back(), "TILT?");
  // A late pan answer (of a question before) is dropped, and the tilt question is still the one on the wire.
  EXPECT_FALSE(channel.complete(answersTag(1)).has_value());
  EXPECT_EQ(channel.lateReplies(), 1u);
  const std::optional<TransactionChannel::Request> tilt = channel.complete(answersTag(2));
  ASSERT_TRUE(tilt.has_value());
  EXPECT_EQ(tilt->tag, 2);
}

/// A reply deadline of 20 ms to start with: a timeout comes soon in real time.
class ShortDeadline : public ChannelOnManualClock
{
protected:
  ShortDeadline() : ChannelOnManualClock(0.02)
  {
  }
};

TEST_F(ShortDeadline, ALateAnswerBeforeTheNextRequestWentOutIsTheOverdueRequestsAndTeachesTheDeadline)
{
  // A PTZOptics G2 at start: its first answers come later than the configured deadline. Before, such an answer was
  // dropped as late and the next request waited out the drain; on a device whose every answer is that late, nothing
  // was ever answered.
  channel_.queue({ "PAN?", 1, true, 0 });
  channel_.queue({ "ZOOM?", 2, true, 0 });
  untilOverdue();
  EXPECT_EQ(lost_, (std::vector<int>{ 1 }));
  clock_.advance(0.025);  // past the deadline of 20 ms, within its ceiling of 40 ms
  const std::optional<TransactionChannel::Request> pan = channel_.complete(answersTag(1));
  ASSERT_TRUE(pan.has_value());
  EXPECT_EQ(pan->tag, 1);
  EXPECT_EQ(channel_.lateRepliesTaken(), 1u);
  EXPECT_EQ(channel_.lateReplies(), 0u);
  // The overdue request answered, nothing late can follow: the next goes out at once, and the deadline has learnt.
  EXPECT_EQ(written_.back(), "ZOOM?");
  EXPECT_NEAR(channel_.replyDeadline(), 1.5 * 0.025, 1e-9);
  EXPECT_NEAR(channel_.timing().longest(), 0.025, 1e-9);
  // An answer as slow is now in time.
  clock_.advance(0.025);
  ASSERT_TRUE(channel_.complete(answersTag(2)).has_value());
  EXPECT_EQ(channel_.timeouts(), 1u);
}

TEST_F(ShortDeadline, WhileDrainingAReplyThatCannotAnswerTheOverdueRequestIsDropped)
{
  channel_.queue({ "PAN?", 1, true, 0 });
  untilOverdue();
  clock_.advance(0.025);
  EXPECT_FALSE(channel_.complete(answersTag(2)).has_value());  // the late answer of an earlier zoom question
  EXPECT_EQ(channel_.lateReplies(), 1u);
  ASSERT_TRUE(channel_.complete(answersTag(1)).has_value());  // still awaited
  EXPECT_EQ(channel_.lateRepliesTaken(), 1u);
}

TEST_F(ShortDeadline, AnAnswerLaterThanTheCeilingIsNeverTakenAndTheNextRequestStillWaitsOutTheDrain)
{
  // Learn the ceiling first (40 ms): the drain after a timeout then lasts until twice the ceiling.
  answerIn(1, 0.04);
  ASSERT_NEAR(channel_.replyDeadline(), 0.04, 1e-9);
  channel_.queue({ "PAN?", 1, true, 0 });
  channel_.queue({ "ZOOM?", 2, true, 0 });
  untilOverdue();
  clock_.advance(0.05);  // past the ceiling, before the drain ends
  EXPECT_FALSE(channel_.complete(answersTag(1)).has_value());
  EXPECT_EQ(channel_.lateReplies(), 1u);
  EXPECT_EQ(written_.back(), "PAN?") << "the next request went out while a reply could still come";
  clock_.advance(0.04);  // the drain is over
  channel_.queue({ "TILT?", 3, true, 0 });
  EXPECT_EQ(written_.back(), "ZOOM?");
}

TEST_F(ShortDeadline, OnceAnotherRequestWentOutALateAnswerIsNeverTakenForTheOverdueOne)
{
  // A halt goes out while the position question is overdue: a position answer from now on could be a late one, and is
  // not taken, so no reply is ever matched one request behind.
  channel_.queue({ "PAN?", 1, true, 0 });
  untilOverdue();
  channel_.sendUrgent({ "HALT", 3, true, 0 });
  clock_.advance(0.025);
  EXPECT_FALSE(channel_.complete(answersTag(1)).has_value());
  EXPECT_EQ(channel_.lateRepliesTaken(), 0u);
}

TEST_F(ShortDeadline, ARequestSentAfterRequestsWithoutReplyHasItsDeadlineBeginOnceTheDeviceHasReadThem)
{
  // A device that takes 30 ms over each request (answered or not), such as a Pelco-D camera without general replies
  // given a goal's three frames: the question after them is answered after the device has read them all.
  for (int answer = 0; answer < 3; ++answer)
  {
    answerIn(1, 0.03);
  }
  ASSERT_NEAR(channel_.timing().typical(), 0.03, 1e-9);
  const std::uint64_t learnt = channel_.timing().answers();
  for (int frame = 0; frame < 3; ++frame)
  {
    channel_.queue({ "SET", 0, false, 0 });
  }
  channel_.queue({ "PAN?", 1, true, 0 });
  ASSERT_EQ(written_.back(), "PAN?");
  // Its deadline (40 ms) begins after the frames' typical 90 ms, capped at the ceiling (40 ms): no timeout within the
  // first 60 ms, where it would have come at 40 ms. A timer never fires early, however busy the machine.
  context_.restart();
  context_.run_for(std::chrono::milliseconds(60));
  EXPECT_TRUE(lost_.empty()) << "the question timed out before the device could have read it";
  clock_.advance(0.07);
  ASSERT_TRUE(channel_.complete(answersTag(1)).has_value());
  EXPECT_EQ(channel_.timing().answers(), learnt) << "a time measured from a guessed start was learnt";
  // Without frames before it, the next question's deadline begins when it goes out.
  channel_.queue({ "PAN?", 1, true, 0 });
  untilOverdue();
}

}  // namespace
