#include "ptz_action_server/core/types.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>

#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
const char* unitOf(Axis axis)
{
  return axis == ZOOM ? "X" : "rad";
}

double ViewTarget::magnification() const
{
  const double share = std::max(box_width, box_height);
  return share > 0.0 ? 1.0 / share : 1.0;
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

bool parseNumber(const std::string& text, double& value)
{
  if (text.empty() || text.size() > 64 || std::isspace(static_cast<unsigned char>(text[0])))
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  const double parsed = std::strtod(text.c_str(), &end);
  if (end != text.c_str() + text.size() || errno != 0 || !std::isfinite(parsed) ||
      text.find_first_of("xXnNiI") != std::string::npos)  // no hex floats, nan or inf
  {
    return false;
  }
  value = parsed;
  return true;
}

}  // namespace ptz_action_server
