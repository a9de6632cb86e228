#include "ptz_action_server/core/mavlink/mavlink_messages.h"

namespace ptz_action_server
{
namespace mavlink
{
std::string toString(Result result)
{
  static const char* const NAMES[] = { "ACCEPTED",         "TEMPORARILY_REJECTED",
                                       "DENIED",           "UNSUPPORTED",
                                       "FAILED",           "IN_PROGRESS",
                                       "CANCELLED",        "COMMAND_LONG_ONLY",
                                       "COMMAND_INT_ONLY", "COMMAND_UNSUPPORTED_MAV_FRAME" };
  const auto value = static_cast<std::size_t>(result);
  if (value < sizeof(NAMES) / sizeof(NAMES[0]))
  {
    return NAMES[value];
  }
  return "result " + std::to_string(value);
}

}  // namespace mavlink
}  // namespace ptz_action_server
