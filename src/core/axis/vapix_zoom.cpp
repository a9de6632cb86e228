/**
 * \file
 * \brief The VAPIX zoom: the table from VAPIX zoom values to X-factors, the camera's zoom attributes
 * (`query=attributes&group=zoom`) and the model families' usual optical zoom. The replies, limits, position, info=1 and
 * the product are vapix_codec.cpp's.
 */
#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "ptz_action_server/core/axis/vapix_codec.h"
#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"
#include "vapix_codec_internal.h"

namespace ptz_action_server
{
namespace vapix
{
namespace
{
// A zoom table's X-factors: optical magnifications, plus digital zoom, are well inside these.
constexpr double ZOOM_FACTOR_MIN = 0.01;
constexpr double ZOOM_FACTOR_MAX = 100000.0;
constexpr double ZOOM_FACTOR_MIN_STEP = 1e-5;  ///< relative, between two points of the table

/// The rules of a zoom table (see ZoomTable); \p text names point \p index in the message. "" or what is wrong.
template <typename PointText>
std::string checkPoints(const std::vector<std::pair<double, double>>& points, PointText text)
{
  for (std::size_t index = 0; index < points.size(); ++index)
  {
    const double value = points[index].first;
    const double factor = points[index].second;
    if (!(factor >= ZOOM_FACTOR_MIN && factor <= ZOOM_FACTOR_MAX) || !(value >= ZOOM_VALUE_MIN - 1.0) ||
        !(value <= ZOOM_VALUE_MAX))
    {
      return formatText("point %zu '%s': X must be %g..%g and the value 0..%g", index + 1, text(index).c_str(),
                        ZOOM_FACTOR_MIN, ZOOM_FACTOR_MAX, ZOOM_VALUE_MAX);
    }
    if (index > 0 && (value <= points[index - 1].first || factor <= points[index - 1].second))
    {
      return formatText("point %zu '%s': values and X must increase", index + 1, text(index).c_str());
    }
    // X steps below 10 parts in a million round away: a value between them could not be read back from its X.
    if (index > 0 && factor < points[index - 1].second * (1.0 + ZOOM_FACTOR_MIN_STEP))
    {
      return formatText("point %zu '%s': X must grow by at least %g %% from the point before", index + 1,
                        text(index).c_str(), ZOOM_FACTOR_MIN_STEP * 100.0);
    }
  }
  if (points.size() < 2)
  {
    return "a zoom table needs at least two VALUE:X points";
  }
  return {};
}
}  // namespace

std::string ZoomTable::parse(const std::string& text, ZoomTable& table)
{
  std::vector<std::pair<double, double>> points;
  std::vector<std::string> texts;
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
    points.emplace_back(value, factor);
    texts.push_back(point.substr(0, 40));
    if (points.size() > MAX_POINTS)
    {
      return formatText("more than %zu points", MAX_POINTS);
    }
  }
  const std::string problem = checkPoints(points, [&](std::size_t index) { return texts[index]; });
  if (problem.empty())
  {
    table.points_ = std::move(points);
  }
  return problem;
}

std::string ZoomTable::fromPoints(std::vector<std::pair<double, double>> points, ZoomTable& table)
{
  if (points.size() > MAX_POINTS)
  {
    return formatText("more than %zu points", MAX_POINTS);
  }
  const std::string problem = checkPoints(
      points, [&](std::size_t index) { return formatText("%.10g:%.10g", points[index].first, points[index].second); });
  if (problem.empty())
  {
    table.points_ = std::move(points);
  }
  return problem;
}

ZoomTable ZoomTable::linear(double max_optical, double max_digital)
{
  ZoomTable table;
  std::vector<std::pair<double, double>> points = { { ZOOM_VALUE_MIN, 1.0 }, { ZOOM_VALUE_OPTICAL_MAX, max_optical } };
  if (std::isfinite(max_digital) && max_digital > 1.0)
  {
    points.emplace_back(ZOOM_VALUE_MAX, max_optical * max_digital);
  }
  if (!std::isfinite(max_optical) || !fromPoints(std::move(points), table).empty())
  {
    return ZoomTable();
  }
  return table;
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
  if (!(value > points_.front().first))
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
      return std::clamp(low.second + share * (high.second - low.second), low.second, high.second);
    }
  }
  return points_.back().second;
}

double ZoomTable::toValue(double factor) const
{
  if (!(factor > points_.front().second))
  {
    return points_.front().first;
  }
  for (std::size_t index = 1; index < points_.size(); ++index)
  {
    const auto& low = points_[index - 1];
    const auto& high = points_[index];
    if (factor <= high.second)
    {
      const double share = (factor - low.second) / (high.second - low.second);
      return std::clamp(low.first + share * (high.first - low.first), low.first, high.first);
    }
  }
  return points_.back().first;
}

std::string readZoomAttributes(const std::string& body, int camera, ZoomAttributes& attributes)
{
  attributes = ZoomAttributes();
  Reply error;
  if (parseReply(body, error).empty() && error.error)
  {
    attributes.refused = true;
    attributes.refusal = error.error_text;
    return {};
  }
  const std::string section_header = "Attributes for camera ";
  bool in_section = true;  // lines before any header belong to the only camera there is
  bool sections = false;
  bool found = false;
  std::size_t start = 0;
  std::size_t line_number = 0;
  while (start < body.size())
  {
    std::size_t end = body.find('\n', start);
    end = end == std::string::npos ? body.size() : end;
    const std::string line = trimmed(body.substr(start, end - start));
    start = end + 1;
    ++line_number;
    if (line.empty())
    {
      continue;
    }
    if (line.rfind(section_header, 0) == 0)
    {
      double number = 0.0;
      sections = true;
      in_section = parseNumber(trimmed(line.substr(section_header.size())), number) && number == camera;
      found = found || in_section;
      continue;
    }
    const std::size_t equals = line.find('=');
    const std::string key = equals == std::string::npos ? std::string() : trimmed(line.substr(0, equals));
    if (!validKey(key))
    {
      attributes = ZoomAttributes();
      return formatText("line %zu '%.40s' is neither 'Attributes for camera N' nor name=value", line_number,
                        line.c_str());
    }
    if (!in_section)
    {
      continue;
    }
    const std::string value = trimmed(line.substr(equals + 1));
    std::string problem;
    if (key == "maxOpticalZoomMag" && !(parseNumber(value, attributes.max_optical) && attributes.max_optical >= 1.0))
    {
      problem = "maxOpticalZoomMag '" + value.substr(0, 40) + "' is not a magnification";
    }
    else if (key == "maxDigitalZoomMag" &&
             !(parseNumber(value, attributes.max_digital) && attributes.max_digital >= 1.0))
    {
      problem = "maxDigitalZoomMag '" + value.substr(0, 40) + "' is not a magnification";
    }
    else if (key == "zoomSteps")
    {
      attributes.steps.clear();
      std::size_t entry_start = 0;
      while (problem.empty() && entry_start <= value.size())
      {
        std::size_t entry_end = value.find(',', entry_start);
        entry_end = entry_end == std::string::npos ? value.size() : entry_end;
        const std::string entry = value.substr(entry_start, entry_end - entry_start);
        entry_start = entry_end + 1;
        double step_value = NAN;
        double step_zoom = NAN;
        std::size_t pair_start = 0;
        while (pair_start <= entry.size())
        {
          std::size_t pair_end = entry.find('|', pair_start);
          pair_end = pair_end == std::string::npos ? entry.size() : pair_end;
          const std::string pair = trimmed(entry.substr(pair_start, pair_end - pair_start));
          pair_start = pair_end + 1;
          const std::size_t pair_equals = pair.find('=');
          const std::string pair_key = pair.substr(0, std::min(pair_equals, pair.size()));
          const std::string pair_value = pair_equals == std::string::npos ? "" : trimmed(pair.substr(pair_equals + 1));
          if (pair_key == "value" && !parseNumber(pair_value, step_value))
          {
            step_value = NAN;
            break;
          }
          if (pair_key == "zoom" && !parseNumber(pair_value, step_zoom))
          {
            step_zoom = NAN;
            break;
          }
        }
        if (std::isnan(step_value) || std::isnan(step_zoom))
        {
          problem =
              formatText("zoomSteps entry %zu '%.40s' has no numbers value= and zoom=", attributes.steps.size() + 1,
                         trimmed(entry).c_str());
        }
        else if (attributes.steps.size() >= MAX_POINTS)
        {
          problem = formatText("zoomSteps has more than %zu entries", MAX_POINTS);
        }
        else
        {
          attributes.steps.emplace_back(step_value, step_zoom);
        }
      }
    }
    if (!problem.empty())
    {
      attributes = ZoomAttributes();
      return problem;
    }
  }
  if (sections && !found)
  {
    attributes = ZoomAttributes();
    return formatText("no attributes for camera %d", camera);
  }
  return {};
}

std::string zoomTableOf(const ZoomAttributes& attributes, ZoomTable& table)
{
  if (!attributes.steps.empty())
  {
    return ZoomTable::fromPoints(attributes.steps, table);
  }
  if (attributes.max_optical > 0.0)
  {
    table = ZoomTable::linear(attributes.max_optical, attributes.max_digital);
    return table.empty() ? formatText("maxOpticalZoomMag %g is no zoom", attributes.max_optical) : std::string();
  }
  return "no zoomSteps and no maxOpticalZoomMag";
}

const std::vector<FamilyZoom>& modelFamilyZooms()
{
  // The usual optical zoom of each PTZ family's data sheets; models within a family differ (hence the warning).
  static const std::vector<FamilyZoom> FAMILIES = {
    { "Q60", 30.0, "the Q60 PTZ domes (18X to 40X; Q6075-E 40X)" },
    { "Q61", 30.0, "the Q61 PTZ cameras (mostly 30X)" },
    { "Q62", 30.0, "the Q62 PTZ cameras (about 30X)" },
    { "Q63", 30.0, "the Q63 PTZ cameras (about 30X)" },
    { "V59", 30.0, "the V59 live-production PTZ cameras (30X)" },
    { "P56", 30.0, "the P56 PTZ cameras (21X to 32X)" },
    { "P55", 18.0, "the P55 PTZ domes (12X to 29X)" },
    { "P54", 18.0, "the P54 PTZ domes (18X)" },
    { "M55", 10.0, "the M55 PTZ cameras (10X)" },
  };
  return FAMILIES;
}

bool modelFamilyZoom(const std::string& product_number, FamilyZoom& zoom)
{
  if (product_number.size() < 3 || !std::isalpha(static_cast<unsigned char>(product_number[0])) ||
      !std::isdigit(static_cast<unsigned char>(product_number[1])) ||
      !std::isdigit(static_cast<unsigned char>(product_number[2])))
  {
    return false;
  }
  std::string family = product_number.substr(0, 3);
  family[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(family[0])));
  for (const FamilyZoom& known : modelFamilyZooms())
  {
    if (known.family == family)
    {
      zoom = known;
      return true;
    }
  }
  return false;
}

}  // namespace vapix
}  // namespace ptz_action_server
