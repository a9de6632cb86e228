#include "bench_common.h"

#include <algorithm>
#include <chrono>
#include <cstdio>

#include "ptz_action_server/core/text.h"

namespace ptz_bench
{
std::int64_t monotonicNanoseconds()
{
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

double percentile(std::vector<double> values, double share)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  const std::size_t index = std::min(values.size() - 1, static_cast<std::size_t>(share * values.size()));
  return values[index];
}

std::string percentiles(const std::vector<double>& milliseconds)
{
  return ptz_action_server::formatText("p50 %.2f ms, p99 %.2f ms, max %.2f ms", percentile(milliseconds, 0.5),
                                       percentile(milliseconds, 0.99), percentile(milliseconds, 1.0));
}

void printTable(const std::string& title, const std::vector<Row>& rows)
{
  std::printf("\n%s\n\n| figure | value | target |\n|---|---|---|\n", title.c_str());
  for (const Row& row : rows)
  {
    std::printf("| %s | %s | %s |\n", row.figure.c_str(), row.value.c_str(), row.target.c_str());
  }
  std::fflush(stdout);
}

}  // namespace ptz_bench
