#include "ptz_action_server/core/axis/vapix_codec.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace vapix
{
namespace
{
// A zoom table's X-factors: optical magnifications, plus digital zoom, are well inside these.
constexpr double ZOOM_FACTOR_MIN = 0.01;
constexpr double ZOOM_FACTOR_MAX = 100000.0;
constexpr double ZOOM_FACTOR_MIN_STEP = 1e-6;  ///< relative, between two points of the table

std::string trimmed(const std::string& text)
{
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
  {
    return {};
  }
  return text.substr(first, text.find_last_not_of(" \t\r\n") - first + 1);
}

bool validKey(const std::string& key)
{
  return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '.';
  });
}

/// Reads the numbers \p keys name into \p values; "" or the first missing or bad one.
std::string readNumbers(const Reply& reply, std::initializer_list<std::pair<const char*, double*>> keys)
{
  for (const auto& key : keys)
  {
    const std::string* text = reply.find(key.first);
    if (text == nullptr)
    {
      return std::string("no ") + key.first;
    }
    if (!parseNumber(*text, *key.second))
    {
      return std::string(key.first) + " '" + *text + "' is not a number";
    }
  }
  return {};
}
}  // namespace

const std::string* Reply::find(const std::string& key) const
{
  for (const auto& value : values)
  {
    if (value.first == key)
    {
      return &value.second;
    }
  }
  return nullptr;
}

std::string parseReply(const std::string& body, Reply& reply)
{
  reply = Reply();
  const std::string text = trimmed(body);
  if (text.rfind("Error:", 0) == 0)
  {
    reply.error = true;
    std::size_t start = 6;
    while (start <= text.size())
    {
      std::size_t end = text.find('\n', start);
      end = end == std::string::npos ? text.size() : end;
      const std::string line = trimmed(text.substr(start, end - start));
      if (!line.empty())
      {
        reply.error_text += (reply.error_text.empty() ? "" : "; ") + line;
      }
      start = end + 1;
    }
    if (reply.error_text.empty())
    {
      reply.error_text = "(no reason given)";
    }
    return {};
  }
  std::size_t start = 0;
  std::size_t line_number = 0;
  while (start < text.size())
  {
    std::size_t end = text.find('\n', start);
    end = end == std::string::npos ? text.size() : end;
    const std::string line = trimmed(text.substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line.empty())
    {
      continue;
    }
    const std::size_t equals = line.find('=');
    const std::string key = equals == std::string::npos ? std::string() : trimmed(line.substr(0, equals));
    if (!validKey(key))
    {
      reply.values.clear();
      return formatText("line %zu '%.40s' is not key=value", line_number, line.c_str());
    }
    reply.values.emplace_back(key, trimmed(line.substr(equals + 1)));
  }
  return {};
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

std::string readPosition(const Reply& reply, Position& position)
{
  Position read;
  std::string problem = readNumbers(reply, { { "pan", &read.pan }, { "tilt", &read.tilt } });
  if (problem.empty() && reply.find("zoom") != nullptr)
  {
    problem = readNumbers(reply, { { "zoom", &read.zoom } });
  }
  if (problem.empty() && (std::abs(read.pan) > 360.0 || std::abs(read.tilt) > 180.0))
  {
    problem = formatText("pan %g or tilt %g degrees is out of any range", read.pan, read.tilt);
  }
  if (problem.empty())
  {
    position = read;
  }
  return problem;
}

std::string readLimits(const Reply& reply, Limits& limits)
{
  Limits read;
  std::string problem = readNumbers(reply, { { "MinPan", &read.min_pan },
                                             { "MaxPan", &read.max_pan },
                                             { "MinTilt", &read.min_tilt },
                                             { "MaxTilt", &read.max_tilt } });
  if (problem.empty() && reply.find("MinZoom") != nullptr)
  {
    problem = readNumbers(reply, { { "MinZoom", &read.min_zoom }, { "MaxZoom", &read.max_zoom } });
    read.has_zoom = true;
  }
  if (problem.empty() &&
      !(read.min_pan < read.max_pan && read.min_tilt < read.max_tilt && read.min_zoom <= read.max_zoom &&
        read.min_pan >= -360.0 && read.max_pan <= 360.0 && read.min_tilt >= -180.0 && read.max_tilt <= 180.0))
  {
    problem = formatText("limits pan [%g, %g], tilt [%g, %g], zoom [%g, %g] make no sense", read.min_pan, read.max_pan,
                         read.min_tilt, read.max_tilt, read.min_zoom, read.max_zoom);
  }
  if (problem.empty())
  {
    limits = read;
  }
  return problem;
}

std::string ZoomTable::parse(const std::string& text, ZoomTable& table)
{
  std::vector<std::pair<double, double>> points;
  std::size_t start = 0;
  const std::string body = trimmed(text);
  while (start <= body.size() && !body.empty())
  {
    std::size_t end = body.find(',', start);
    end = end == std::string::npos ? body.size() : end;
    const std::string point = trimmed(body.substr(start, end - start));
    start = end + 1;
    const std::size_t colon = point.find(':');
    double value = 0.0;
    double factor = 0.0;
    if (colon == std::string::npos || !parseNumber(point.substr(0, colon), value) ||
        !parseNumber(point.substr(colon + 1), factor))
    {
      return formatText("point %zu '%.40s' is not VALUE:X", points.size() + 1, point.c_str());
    }
    if (!(factor >= ZOOM_FACTOR_MIN && factor <= ZOOM_FACTOR_MAX) || value < ZOOM_VALUE_MIN - 1.0 ||
        value > ZOOM_VALUE_MAX)
    {
      return formatText("point %zu '%.40s': X must be %g..%g and the value 0..%g", points.size() + 1, point.c_str(),
                        ZOOM_FACTOR_MIN, ZOOM_FACTOR_MAX, ZOOM_VALUE_MAX);
    }
    if (!points.empty() && (value <= points.back().first || factor <= points.back().second))
    {
      return formatText("point %zu '%.40s': values and X must increase", points.size() + 1, point.c_str());
    }
    // Interpolation is geometric: X steps below a part in a million round away and the value cannot be read back.
    if (!points.empty() && factor < points.back().second * (1.0 + ZOOM_FACTOR_MIN_STEP))
    {
      return formatText("point %zu '%.40s': X must grow by at least %g %% from the point before", points.size() + 1,
                        point.c_str(), ZOOM_FACTOR_MIN_STEP * 100.0);
    }
    points.emplace_back(value, factor);
    if (points.size() > 1000)
    {
      return "more than 1000 points";
    }
  }
  if (points.size() < 2)
  {
    return "a zoom table needs at least two VALUE:X points";
  }
  table.points_ = std::move(points);
  return {};
}

std::string ZoomTable::toText() const
{
  std::string text;
  for (const auto& point : points_)
  {
    text += formatText("%s%g:%g", text.empty() ? "" : ",", point.first, point.second);
  }
  return text;
}

double ZoomTable::toFactor(double value) const
{
  if (value <= points_.front().first)
  {
    return points_.front().second;
  }
  for (std::size_t index = 1; index < points_.size(); ++index)
  {
    const auto& low = points_[index - 1];
    const auto& high = points_[index];
    if (value <= high.first)
    {
      const double share = (value - low.first) / (high.first - low.first);
      // Clamped: pow may land an ulp outside the segment, and the table's ends must stay its ends.
      return std::clamp(low.second * std::pow(high.second / low.second, share), low.second, high.second);
    }
  }
  return points_.back().second;
}

double ZoomTable::toValue(double factor) const
{
  if (factor <= points_.front().second)
  {
    return points_.front().first;
  }
  for (std::size_t index = 1; index < points_.size(); ++index)
  {
    const auto& low = points_[index - 1];
    const auto& high = points_[index];
    if (factor <= high.second)
    {
      const double share = std::log(factor / low.second) / std::log(high.second / low.second);
      return std::clamp(low.first + share * (high.first - low.first), low.first, high.first);
    }
  }
  return points_.back().first;
}

void appendAbsoluteMove(std::string& out, double pan_deg, double tilt_deg, double zoom_value, int speed)
{
  out += formatText("pan=%.4f&tilt=%.4f", pan_deg, tilt_deg);
  if (zoom_value >= ZOOM_VALUE_MIN)
  {
    out += formatText("&zoom=%.0f", std::round(zoom_value));
  }
  out += formatText("&speed=%d", std::clamp(speed, 1, 100));
}

void appendContinuousMove(std::string& out, int pan, int tilt, int zoom, bool with_zoom)
{
  out += formatText("continuouspantiltmove=%d,%d", std::clamp(pan, -100, 100), std::clamp(tilt, -100, 100));
  if (with_zoom)
  {
    out += formatText("&continuouszoommove=%d", std::clamp(zoom, -100, 100));
  }
}

}  // namespace vapix
}  // namespace ptz_action_server
