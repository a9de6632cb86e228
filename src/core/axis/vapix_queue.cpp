#include "ptz_action_server/core/axis/vapix_queue.h"

#include <cmath>

#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace vapix
{
std::string queueParametersPath(int camera)
{
  return formatText("%s?action=list&group=root.PTZ.Various.V%d", PARAM_PATH, camera);
}

std::string readQueueSettings(const std::string& body, int camera, QueueSettings& settings)
{
  settings = QueueSettings();
  if (body.find("Error") != std::string::npos && body.find("CtlQueueing") == std::string::npos)
  {
    std::string words = body.substr(0, body.find_first_of("\r\n"));
    return "no CtlQueueing parameter (" + words + ")";
  }
  Reply reply;
  const std::string problem = parseReply(body, reply);
  if (!problem.empty())
  {
    return problem;
  }
  const std::string prefix = formatText("root.PTZ.Various.V%d.", camera);
  const std::string* queueing = reply.find(prefix + "CtlQueueing");
  if (queueing == nullptr)
  {
    return "no " + prefix + "CtlQueueing in the answer";
  }
  if (*queueing != "true" && *queueing != "false")
  {
    return prefix + "CtlQueueing '" + *queueing + "' is neither true nor false";
  }
  settings.queueing = *queueing == "true";
  const std::string* poll_time = reply.find(prefix + "CtlQueuePollTime");
  double value = 0.0;
  if (poll_time != nullptr && parseNumber(*poll_time, value) && value > 0.0 && std::isfinite(value))
  {
    settings.poll_time = value;
  }
  return "";
}

std::string readQueueStatus(const std::string& body, QueueStatus& status)
{
  status = QueueStatus();
  const std::size_t start = body.find_first_not_of(" \t\r\n");
  if (start != std::string::npos && body.compare(start, 6, "Error:") == 0)
  {
    Reply reply;
    parseReply(body.substr(start), reply);
    return "the camera refused: " + (reply.error_text.empty() ? std::string("Error:") : reply.error_text);
  }
  // Three anchors, `<a name="N">`: position, seconds, period (the documentation's own example form).
  double numbers[3] = { 0.0, 0.0, 0.0 };
  std::size_t at = 0;
  for (double& number : numbers)
  {
    const std::size_t name = body.find("name=\"", at);
    if (name == std::string::npos)
    {
      return "not a queue answer (three <a name=\"...\"> expected): '" + body.substr(0, 80) + "'";
    }
    const std::size_t value_start = name + 6;
    const std::size_t value_end = body.find('"', value_start);
    if (value_end == std::string::npos || !parseNumber(body.substr(value_start, value_end - value_start), number) ||
        !std::isfinite(number))
    {
      return "not a number in the queue answer: '" + body.substr(value_start, 20) + "'";
    }
    at = value_end + 1;
  }
  if (numbers[0] < 0.0 || numbers[0] != std::floor(numbers[0]) || numbers[0] > 1000.0)
  {
    return formatText("queue position %g is not a position", numbers[0]);
  }
  status.position = static_cast<int>(numbers[0]);
  status.seconds = numbers[1];
  status.period = numbers[2] > 0.0 ? numbers[2] : 0.0;
  return "";
}

}  // namespace vapix
}  // namespace ptz_action_server
