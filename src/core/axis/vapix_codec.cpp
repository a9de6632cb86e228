/**
 * \file
 * \brief The VAPIX codec: the replies (`key=value` lines or `Error:`), the position, the limits, what info=1 offers,
 * the product, and the ptz.cgi arguments of moves. The zoom table and attributes are vapix_zoom.cpp's.
 */
#include "ptz_action_server/core/axis/vapix_codec.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"
#include "vapix_codec_internal.h"

namespace ptz_action_server
{
namespace vapix
{
namespace
{
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

std::string readPosition(const Reply& reply, Position& position)
{
  Position read;
  std::string problem = readNumbers(reply, { { "pan", &read.pan }, { "tilt", &read.tilt } });
  if (problem.empty() && reply.find("zoom") != nullptr)
  {
    problem = readNumbers(reply, { { "zoom", &read.zoom } });
    read.has_zoom = true;
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

bool CommandList::has(const std::string& name) const
{
  return std::any_of(commands.begin(), commands.end(), [&](const auto& command) { return command.first == name; });
}

bool CommandList::offers(const std::string& name, const std::string& value) const
{
  return std::any_of(commands.begin(), commands.end(), [&](const auto& command) {
    return command.first == name &&
           std::find(command.second.begin(), command.second.end(), value) != command.second.end();
  });
}

CommandList readCommandList(const std::string& body)
{
  CommandList list;
  Reply error;
  if (parseReply(body, error).empty() && error.error)
  {
    return list;
  }
  std::size_t start = 0;
  while (start < body.size() && list.commands.size() < MAX_POINTS)
  {
    std::size_t end = body.find('\n', start);
    end = end == std::string::npos ? body.size() : end;
    std::string line = trimmed(body.substr(start, end - start));
    start = end + 1;
    if (line.size() > 2 && line.front() == '{' && line.back() == '}')
    {
      line = trimmed(line.substr(1, line.size() - 2));  // {camera=[n]}: an optional argument
    }
    const std::size_t equals = line.find('=');
    const std::string name = equals == std::string::npos ? std::string() : trimmed(line.substr(0, equals));
    if (!validKey(name))
    {
      continue;  // "Available commands:" and anything else that names no command
    }
    std::vector<std::string> values;
    const std::string rest = trimmed(line.substr(equals + 1));
    if (rest.size() >= 2 && rest.front() == '{' && rest.find('}') != std::string::npos)
    {
      const std::string choices = rest.substr(1, rest.find('}') - 1);
      std::size_t choice_start = 0;
      while (choice_start <= choices.size())
      {
        std::size_t choice_end = choices.find('|', choice_start);
        choice_end = choice_end == std::string::npos ? choices.size() : choice_end;
        const std::string choice = trimmed(choices.substr(choice_start, choice_end - choice_start));
        choice_start = choice_end + 1;
        if (!choice.empty())
        {
          values.push_back(choice);
        }
      }
    }
    list.commands.emplace_back(name, std::move(values));
  }
  return list;
}

std::string readProduct(const Reply& reply, Product& product)
{
  const std::string* number = reply.find("root.Brand.ProdNbr");
  if (number == nullptr)
  {
    number = reply.find("Brand.ProdNbr");
  }
  if (number == nullptr || number->empty())
  {
    return "no root.Brand.ProdNbr";
  }
  const std::string* full_name = reply.find("root.Brand.ProdFullName");
  if (full_name == nullptr)
  {
    full_name = reply.find("Brand.ProdFullName");
  }
  product.number = *number;
  product.full_name = full_name == nullptr ? std::string() : *full_name;
  return {};
}

void appendAbsoluteMove(std::string& out, double pan_deg, double tilt_deg, double zoom_value, int speed)
{
  const std::size_t start = out.size();
  auto separate = [&] { return out.size() > start ? "&" : ""; };
  if (std::isfinite(pan_deg))
  {
    out += formatText("%span=%.4f", separate(), pan_deg);
  }
  if (std::isfinite(tilt_deg))
  {
    out += formatText("%stilt=%.4f", separate(), tilt_deg);
  }
  if (std::isfinite(zoom_value) && zoom_value >= ZOOM_VALUE_MIN)
  {
    out += formatText("%szoom=%.0f", separate(), std::round(zoom_value));
  }
  out += formatText("%sspeed=%d", separate(), std::clamp(speed, 1, 100));
}

void appendContinuousMove(std::string& out, int pan, int tilt, int zoom, bool with_zoom)
{
  out += formatText("continuouspantiltmove=%d,%d", std::clamp(pan, -100, 100), std::clamp(tilt, -100, 100));
  if (with_zoom)
  {
    out += formatText("&continuouszoommove=%d", std::clamp(zoom, -100, 100));
  }
}

void appendCenter(std::string& out, const ImagePoint& point)
{
  out +=
      formatText("center=%d,%d&imagewidth=%d&imageheight=%d", point.x, point.y, point.image_width, point.image_height);
}

void appendAreaZoom(std::string& out, const ImagePoint& point, int zoom_percent)
{
  out += formatText("areazoom=%d,%d,%d&imagewidth=%d&imageheight=%d", point.x, point.y, std::max(zoom_percent, 1),
                    point.image_width, point.image_height);
}

}  // namespace vapix
}  // namespace ptz_action_server
