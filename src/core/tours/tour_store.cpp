#include "ptz_action_server/core/tours/tour_store.h"

#include <charconv>
#include <cmath>
#include <utility>

#include <yaml-cpp/yaml.h>

#include "ptz_action_server/core/presets/atomic_file.h"

namespace ptz_action_server
{
namespace tour_store
{
constexpr const char* TOURS_KEY = "tours";
constexpr const char* TOURS_HEADER = "# ptz_action_server tours: each stop a preset, its dwell in s and its speed as "
                                     "a\n"
                                     "# fraction of top speed (0 or absent: the default). Rewritten on every save and\n"
                                     "# delete: edit it only while the node is stopped.\n";

/// The shortest text that reads back as exactly \p value.
std::string shortestText(double value)
{
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

/// Reads the number at \p key of \p node into \p value (left as it is if absent); "" or the reason.
std::string readNumber(const YAML::Node& node, const char* key, double& value)
{
  const YAML::Node field = node[key];
  if (!field)
  {
    return {};
  }
  try
  {
    value = field.as<double>();
  }
  catch (const YAML::Exception&)
  {
    return std::string(key) + " '" + (field.IsScalar() ? field.Scalar() : std::string("?")) + "' is not a number";
  }
  return {};
}

/// Reads one stop from \p node; "" or the reason.
std::string readStop(const YAML::Node& node, TourStop& stop)
{
  if (!node.IsMap())
  {
    return "must be a map with preset, dwell and speed";
  }
  for (const auto& entry : node)
  {
    const std::string key = entry.first.as<std::string>();
    if (key != "preset" && key != "dwell" && key != "speed")
    {
      return "has an unknown key '" + key + "' (only preset, dwell and speed)";
    }
  }
  const YAML::Node preset = node["preset"];
  if (!preset || !preset.IsScalar())
  {
    return "lacks preset";
  }
  stop.preset = preset.Scalar();
  std::string reason = readNumber(node, "dwell", stop.dwell);
  return reason.empty() ? readNumber(node, "speed", stop.speed) : reason;
}
}  // namespace tour_store

std::string parseTours(const std::string& text, std::map<std::string, Tour>& tours)
{
  using namespace tour_store;
  YAML::Node root;
  try
  {
    root = YAML::Load(text);
  }
  catch (const YAML::Exception& exception)
  {
    return exception.what();
  }
  if (root.IsNull())
  {
    return {};  // an empty file: nothing to lose
  }
  if (!root.IsMap() || root.size() != 1 || !root[TOURS_KEY])
  {
    return "the file must be a map with the one key 'tours'";
  }
  const YAML::Node list = root[TOURS_KEY];
  if (list.IsNull())
  {
    return {};
  }
  if (!list.IsMap())
  {
    return "'tours' must be a map from names to lists of stops";
  }
  for (const auto& entry : list)
  {
    Tour tour;
    tour.name = entry.first.as<std::string>();
    if (!entry.second.IsSequence())
    {
      return "tour '" + tour.name + "' must be a list of stops";
    }
    for (std::size_t index = 0; index < entry.second.size(); ++index)
    {
      tour.stops.emplace_back();
      const std::string reason = readStop(entry.second[index], tour.stops.back());
      if (!reason.empty())
      {
        return "tour '" + tour.name + "' stop " + std::to_string(index) + " " + reason;
      }
    }
    const std::string reason = checkTour(tour);
    if (!reason.empty())
    {
      return "tour '" + tour.name + "': " + reason;
    }
    tours[tour.name] = std::move(tour);
  }
  if (tours.size() > TourLimits::MAX_TOURS)
  {
    return "it holds " + std::to_string(tours.size()) + " tours, more than " + std::to_string(TourLimits::MAX_TOURS);
  }
  return {};
}

std::string formatTours(const std::map<std::string, Tour>& tours)
{
  using namespace tour_store;
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << TOURS_KEY << YAML::Value;
  if (tours.empty())
  {
    out << YAML::Flow << YAML::BeginMap << YAML::EndMap;
  }
  else
  {
    out << YAML::BeginMap;
    for (const auto& [name, tour] : tours)
    {
      out << YAML::Key << name << YAML::Value << YAML::BeginSeq;
      for (const TourStop& stop : tour.stops)
      {
        out << YAML::Flow << YAML::BeginMap << YAML::Key << "preset" << YAML::Value << stop.preset;
        out << YAML::Key << "dwell" << YAML::Value << shortestText(stop.dwell);
        if (stop.speed > 0.0)
        {
          out << YAML::Key << "speed" << YAML::Value << shortestText(stop.speed);
        }
        out << YAML::EndMap;
      }
      out << YAML::EndSeq;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  return std::string(TOURS_HEADER) + out.c_str() + "\n";
}

TourStore::TourStore(std::string path) : path_(std::move(path))
{
}

std::string TourStore::load()
{
  std::map<std::string, Tour> tours;
  std::optional<std::string> text;
  std::string reason = readStoredFile(path_, text);
  if (text)
  {
    reason = parseTours(*text, tours);
    if (!reason.empty())
    {
      reason = "cannot read the tours in " + path_ + ": " + reason;
      tours.clear();
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  tours_ = std::move(tours);
  load_error_ = reason;
  return reason;
}

std::optional<Tour> TourStore::find(const std::string& name) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const auto tour = tours_.find(name);
  if (tour == tours_.end())
  {
    return std::nullopt;
  }
  return tour->second;
}

std::string TourStore::save(const Tour& tour)
{
  const std::string reason = checkTour(tour);
  if (!reason.empty())
  {
    return reason;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  std::map<std::string, Tour> tours = tours_;
  tours[tour.name] = tour;
  if (tours.size() > TourLimits::MAX_TOURS)
  {
    return "there are already " + std::to_string(TourLimits::MAX_TOURS) + " tours: delete some first";
  }
  return commit(std::move(tours));
}

std::string TourStore::remove(const std::string& name)
{
  std::lock_guard<std::mutex> lock(mutex_);
  std::map<std::string, Tour> tours = tours_;
  if (tours.erase(name) == 0)
  {
    return "no tour named '" + name + "'";
  }
  return commit(std::move(tours));
}

std::vector<Tour> TourStore::list() const
{
  std::vector<Tour> result;
  std::lock_guard<std::mutex> lock(mutex_);
  for (const auto& entry : tours_)
  {
    result.push_back(entry.second);
  }
  return result;
}

std::string TourStore::loadError() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return load_error_;
}

std::string TourStore::commit(std::map<std::string, Tour> tours)
{
  if (!load_error_.empty())
  {
    return "tours are read-only until the tours file is fixed (it is kept as it is, not overwritten) and the node "
           "restarted: " +
           load_error_;
  }
  std::string reason = writeFileAtomically(path_, formatTours(tours));
  if (reason.empty())
  {
    tours_ = std::move(tours);
  }
  return reason;
}

std::string checkTourName(const std::string& name)
{
  if (name.empty())
  {
    return "the name is empty";
  }
  if (name.size() > TourLimits::MAX_NAME)
  {
    return "the name is longer than " + std::to_string(TourLimits::MAX_NAME) + " characters";
  }
  for (const char character : name)
  {
    if (character < 0x20 || character > 0x7e)
    {
      return "the name may hold only printable ASCII characters";
    }
  }
  if (name.front() == ' ' || name.back() == ' ')
  {
    return "the name may not begin or end with a space";
  }
  return {};
}

std::string checkTour(const Tour& tour)
{
  std::string reason = checkTourName(tour.name);
  if (!reason.empty())
  {
    return reason;
  }
  if (tour.stops.empty())
  {
    return "a tour needs at least one stop";
  }
  if (tour.stops.size() > TourLimits::MAX_STOPS)
  {
    return "a tour has at most " + std::to_string(TourLimits::MAX_STOPS) + " stops";
  }
  for (std::size_t index = 0; index < tour.stops.size(); ++index)
  {
    const TourStop& stop = tour.stops[index];
    const std::string which = "stop " + std::to_string(index) + ": ";
    if (stop.preset.empty())
    {
      return which + "no preset";
    }
    if (!std::isfinite(stop.dwell) || stop.dwell < 0.0 || stop.dwell > TourLimits::MAX_DWELL)
    {
      return which + "dwell " + tour_store::shortestText(stop.dwell) + " s is not within [0, 86400]";
    }
    if (!std::isfinite(stop.speed) || stop.speed < 0.0 || stop.speed > 1.0)
    {
      return which + "speed " + tour_store::shortestText(stop.speed) +
             " is not a fraction of top speed within (0, 1] (or 0: the default)";
    }
  }
  return {};
}

}  // namespace ptz_action_server
