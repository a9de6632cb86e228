/**
 * \file
 * \brief libFuzzer target: the VAPIX reply reader, the position and limits readers, the zoom attributes, info=1 and
 * brand readers, the zoom table and the PTZ control queue's parameters and answers on arbitrary text. Whatever reads,
 * reads consistently: a zoom table maps every value inside it and back, and the attributes give a table or say why not.
 */
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/core/axis/vapix_queue.h"

using namespace ptz_action_server::vapix;

namespace
{
/// A table maps every value inside it into its X range and back.
void checkTable(const ZoomTable& table)
{
  for (double share : { 0.0, 0.3, 0.5, 1.0 })
  {
    const double value = table.minValue() + share * (table.maxValue() - table.minValue());
    const double factor = table.toFactor(value);
    if (!(factor >= table.minFactor() && factor <= table.maxFactor()) ||
        std::abs(table.toValue(factor) - value) > 1e-6 * std::max(1.0, std::abs(value)))
    {
      std::abort();
    }
  }
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  const std::string body(reinterpret_cast<const char*>(data), size);
  Reply reply;
  const std::string problem = parseReply(body, reply);
  if (!problem.empty() && (!reply.values.empty() || reply.error))
  {
    std::abort();  // a refused body leaves nothing behind
  }
  if (reply.error && reply.error_text.empty())
  {
    std::abort();
  }
  Position position;
  if (readPosition(reply, position).empty() && (!std::isfinite(position.pan) || std::abs(position.pan) > 360.0))
  {
    std::abort();
  }
  Limits limits;
  if (readLimits(reply, limits).empty() && !(limits.min_pan < limits.max_pan && limits.min_tilt < limits.max_tilt))
  {
    std::abort();
  }
  ZoomTable table;
  if (ZoomTable::parse(body, table).empty())
  {
    checkTable(table);
  }
  ZoomAttributes attributes;
  const std::string attributes_problem = readZoomAttributes(body, 1, attributes);
  if (!attributes_problem.empty() && (attributes.refused || !attributes.steps.empty() || attributes.max_optical != 0.0))
  {
    std::abort();  // a problem leaves nothing behind
  }
  ZoomTable camera_table;
  if (attributes_problem.empty() && !attributes.refused && zoomTableOf(attributes, camera_table).empty())
  {
    checkTable(camera_table);
  }
  const CommandList commands = readCommandList(body);
  for (const auto& command : commands.commands)
  {
    if (command.first.empty() || !commands.has(command.first))
    {
      std::abort();
    }
  }
  Product product;
  FamilyZoom family;
  if (readProduct(reply, product).empty() && modelFamilyZoom(product.number, family) &&
      ZoomTable::linear(family.max_optical).empty())
  {
    std::abort();
  }
  QueueSettings queue;
  if (readQueueSettings(body, 1, queue).empty() && !(queue.poll_time >= 0.0 && std::isfinite(queue.poll_time)))
  {
    std::abort();
  }
  QueueStatus status;
  if (!readQueueStatus(body, status).empty() ?
          status.position != 0 :
          status.position < 0 || !std::isfinite(status.seconds) || !(status.period >= 0.0))
  {
    std::abort();  // a problem leaves nothing behind; a status is whole
  }
  return 0;
}
