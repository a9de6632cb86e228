/**
 * \file
 * \brief libFuzzer target: the VAPIX reply reader, the position and limits readers and the zoom table on arbitrary
 * text. Whatever reads, reads consistently: a zoom table maps every value inside it and back.
 */
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "ptz_action_server/core/axis/vapix_codec.h"

using namespace ptz_action_server::vapix;

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
  return 0;
}
