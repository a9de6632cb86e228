#include "ptz_action_server/core/device/reply_timing.h"

#include <algorithm>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
ReplyTiming::ReplyTiming(double floor) : floor_(floor), ceiling_(CEILING * floor), deadline_(floor)
{
}

bool ReplyTiming::answered(double seconds)
{
  latest_[next_] = std::max(0.0, seconds);
  next_ = (next_ + 1) % ANSWERS;
  ++answers_;
  const auto count = static_cast<std::ptrdiff_t>(std::min<std::uint64_t>(answers_, ANSWERS));
  const auto begin = latest_.begin();
  const double longest = *std::max_element(begin, begin + count);
  std::array<double, ANSWERS> ordered = latest_;  // on the stack: no allocation per answer
  std::nth_element(ordered.begin(), ordered.begin() + count / 2, ordered.begin() + count);
  median_.store(ordered[static_cast<std::size_t>(count / 2)], std::memory_order_relaxed);
  longest_.store(longest, std::memory_order_relaxed);
  const double learnt = std::clamp(MARGIN * longest, floor_, ceiling_);
  return deadline_.exchange(learnt, std::memory_order_relaxed) != learnt;
}

void ReplyTiming::diagnostics(std::vector<DiagnosticValue>& values) const
{
  values.emplace_back("reply deadline (s, learnt)", formatText("%.3f", deadline()));
  values.emplace_back("reply deadline bounds (s)", formatText("%.3f to %.3f", floor_, ceiling_));
  values.emplace_back("answer time median / longest (ms, latest answers)",
                      answers_ == 0 ? std::string("none yet") :
                                      formatText("%.0f / %.0f", 1e3 * typical(), 1e3 * longest()));
}

}  // namespace ptz_action_server
