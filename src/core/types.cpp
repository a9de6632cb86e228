#include "ptz_action_server/core/types.h"

#include <cstdarg>
#include <cstdio>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
const char* unitOf(Axis axis)
{
  return axis == ZOOM ? "X" : "rad";
}

const char* axisName(Axis axis)
{
  switch (axis)
  {
    case PAN:
      return "pan";
    case TILT:
      return "tilt";
    case ZOOM:
      return "zoom";
  }
  return "?";
}

std::string formatText(const char* pattern, ...)
{
  char buffer[512];
  va_list args;
  va_start(args, pattern);
  std::vsnprintf(buffer, sizeof(buffer), pattern, args);
  va_end(args);
  return buffer;
}

}  // namespace ptz_action_server
