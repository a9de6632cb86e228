#include "ptz_action_server/core/presets/preset_store.h"

#include "ptz_action_server/core/presets/atomic_file.h"

#include <charconv>
#include <cmath>

#include <yaml-cpp/yaml.h>

namespace ptz_action_server
{
namespace
{
constexpr const char* PRESETS_KEY = "presets";
constexpr const char* HEADER = "# ptz_action_server presets: pan and tilt in rad, zoom as X-factor.\n"
                               "# Rewritten on every save and delete: edit it only while the node is stopped.\n";

/// The shortest text that reads back as exactly \p value.
std::string exactText(double value)
{
  char buffer[64];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

/// Reads one preset's pose from \p node; "" or the reason.
/// "" when \p fraction is a preset's speed (0: the default speed, or a fraction of the top speed in (0, 1]).
std::string checkPresetSpeed(double fraction)
{
  return fraction >= 0.0 && fraction <= 1.0 ?
             std::string() :
             "speed " + exactText(fraction) + " is not in [0, 1] (0: the default speed)";
}

/// The optional `speed` of a preset's map into \p speed (0 without one).
std::string readSpeed(const YAML::Node& node, double& speed)
{
  const YAML::Node value = node["speed"];
  speed = 0.0;
  if (!value)
  {
    return {};
  }
  try
  {
    speed = value.as<double>();
  }
  catch (const YAML::Exception&)
  {
    return "speed '" + (value.IsScalar() ? value.Scalar() : std::string("?")) + "' is not a number";
  }
  return checkPresetSpeed(speed);
}

std::string readPose(const YAML::Node& node, AxisValues& pose)
{
  if (!node.IsMap())
  {
    return "must be a map with pan, tilt and zoom";
  }
  for (const auto& entry : node)
  {
    const std::string key = entry.first.as<std::string>();
    if (key != "pan" && key != "tilt" && key != "zoom" && key != "speed")
    {
      return "has an unknown key '" + key + "' (only pan, tilt, zoom and speed)";
    }
  }
  for (Axis axis : ALL_AXES)
  {
    const YAML::Node value = node[axisName(axis)];
    if (!value || !value.IsScalar())
    {
      return std::string("lacks ") + axisName(axis);
    }
    try
    {
      pose[axis] = value.as<double>();
    }
    catch (const YAML::Exception&)
    {
      return std::string(axisName(axis)) + " '" + value.Scalar() + "' is not a number";
    }
    if (!std::isfinite(pose[axis]))
    {
      return std::string(axisName(axis)) + " is not finite";
    }
  }
  return {};
}

/// Reads the presets of a parsed file; "" or the reason.
std::string readPresets(const YAML::Node& root, std::map<std::string, AxisValues>& presets,
                        std::map<std::string, double>& speeds)
{
  if (root.IsNull())
  {
    return {};  // an empty file: nothing to lose
  }
  if (!root.IsMap())
  {
    return "the file must be a map with the key 'presets'";
  }
  for (const auto& entry : root)
  {
    if (entry.first.as<std::string>() != PRESETS_KEY)
    {
      return "unknown top-level key '" + entry.first.as<std::string>() + "' (only 'presets')";
    }
  }
  const YAML::Node list = root[PRESETS_KEY];
  if (list.IsNull())
  {
    return {};
  }
  if (!list.IsMap())
  {
    return "'presets' must be a map from names to poses";
  }
  for (const auto& entry : list)
  {
    const std::string name = entry.first.as<std::string>();
    std::string reason = PresetStore::checkName(name);
    if (reason.empty())
    {
      reason = readPose(entry.second, presets[name]);
    }
    double speed = 0.0;
    if (reason.empty())
    {
      reason = readSpeed(entry.second, speed);
    }
    if (speed > 0.0)
    {
      speeds[name] = speed;
    }
    if (!reason.empty())
    {
      return "preset '" + name + "' " + reason;
    }
  }
  if (presets.size() > PresetStore::MAX_COUNT)
  {
    return "it holds " + std::to_string(presets.size()) + " presets, more than " +
           std::to_string(PresetStore::MAX_COUNT);
  }
  return {};
}

/// The file's text for \p presets.
std::string formatPresets(const std::map<std::string, AxisValues>& presets, const std::map<std::string, double>& speeds)
{
  YAML::Emitter out;
  out << YAML::BeginMap << YAML::Key << PRESETS_KEY << YAML::Value;
  if (presets.empty())
  {
    out << YAML::Flow << YAML::BeginMap << YAML::EndMap;
  }
  else
  {
    out << YAML::BeginMap;
    for (const auto& preset : presets)
    {
      out << YAML::Key << preset.first << YAML::Value << YAML::Flow << YAML::BeginMap;
      for (Axis axis : ALL_AXES)
      {
        out << YAML::Key << axisName(axis) << YAML::Value << exactText(preset.second[axis]);
      }
      const auto speed = speeds.find(preset.first);
      if (speed != speeds.end())
      {
        out << YAML::Key << "speed" << YAML::Value << exactText(speed->second);
      }
      out << YAML::EndMap;
    }
    out << YAML::EndMap;
  }
  out << YAML::EndMap;
  return std::string(HEADER) + out.c_str() + "\n";
}

}  // namespace

PresetStore::PresetStore(std::string path, const AxisValues& home) : path_(std::move(path)), home_(home)
{
}

std::string PresetStore::checkName(const std::string& name)
{
  if (name.empty())
  {
    return "the name is empty";
  }
  if (name.size() > MAX_NAME)
  {
    return "the name is longer than " + std::to_string(MAX_NAME) + " characters";
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
  if (name == HOME)
  {
    return "'home' is predefined (the parameters ~home/pan, ~home/tilt, ~home/zoom), not a preset to save or delete";
  }
  return {};
}

std::string PresetStore::load()
{
  std::map<std::string, AxisValues> presets;
  std::map<std::string, double> speeds;
  std::optional<std::string> text;
  std::string reason = readStoredFile(path_, text);
  if (text)
  {
    try
    {
      reason = readPresets(YAML::Load(*text), presets, speeds);
    }
    catch (const YAML::Exception& exception)
    {
      reason = exception.what();
    }
    if (!reason.empty())
    {
      reason = "cannot read the presets in " + path_ + ": " + reason;
      presets.clear();
      speeds.clear();
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  presets_ = std::move(presets);
  speeds_ = std::move(speeds);
  load_error_ = reason;
  return reason;
}

std::optional<AxisValues> PresetStore::find(const std::string& name) const
{
  if (name == HOME)
  {
    return home_;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  const auto preset = presets_.find(name);
  if (preset == presets_.end())
  {
    return std::nullopt;
  }
  return preset->second;
}

std::string PresetStore::save(const std::string& name, const AxisValues& pose)
{
  std::string reason = checkName(name);
  for (Axis axis : ALL_AXES)
  {
    if (reason.empty() && !std::isfinite(pose[axis]))
    {
      reason = std::string("the ") + axisName(axis) + " is not finite";
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (reason.empty())
  {
    reason = checkWritable();
  }
  std::map<std::string, AxisValues> presets = presets_;
  presets[name] = pose;
  if (reason.empty() && presets.size() > MAX_COUNT)
  {
    reason = "there are already " + std::to_string(MAX_COUNT) + " presets: delete some first";
  }
  if (reason.empty())
  {
    reason = write(presets, speeds_);
  }
  if (reason.empty())
  {
    presets_ = std::move(presets);
  }
  return reason;
}

std::string PresetStore::remove(const std::string& name)
{
  if (name == HOME)
  {
    return checkName(name);
  }
  std::lock_guard<std::mutex> lock(mutex_);
  std::string reason = checkWritable();
  std::map<std::string, AxisValues> presets = presets_;
  if (reason.empty() && presets.erase(name) == 0)
  {
    reason = "no preset named '" + name + "'";
  }
  std::map<std::string, double> speeds = speeds_;
  speeds.erase(name);
  if (reason.empty())
  {
    reason = write(presets, speeds);
  }
  if (reason.empty())
  {
    presets_ = std::move(presets);
    speeds_ = std::move(speeds);
  }
  return reason;
}

double PresetStore::speed(const std::string& name) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  const auto speed = speeds_.find(name);
  return speed == speeds_.end() ? 0.0 : speed->second;
}

std::string PresetStore::setSpeed(const std::string& name, double fraction)
{
  std::string reason = name == HOME ? "'home' runs at the default speed (~default_speed)" : checkPresetSpeed(fraction);
  std::lock_guard<std::mutex> lock(mutex_);
  if (reason.empty())
  {
    reason = checkWritable();
  }
  if (reason.empty() && presets_.count(name) == 0)
  {
    reason = "no preset named '" + name + "'";
  }
  std::map<std::string, double> speeds = speeds_;
  if (fraction > 0.0)
  {
    speeds[name] = fraction;
  }
  else
  {
    speeds.erase(name);
  }
  if (reason.empty())
  {
    reason = write(presets_, speeds);
  }
  if (reason.empty())
  {
    speeds_ = std::move(speeds);
  }
  return reason;
}

std::vector<NamedPose> PresetStore::list() const
{
  std::vector<NamedPose> result{ { HOME, home_ } };
  std::lock_guard<std::mutex> lock(mutex_);
  result.insert(result.end(), presets_.begin(), presets_.end());
  return result;
}

std::string PresetStore::loadError() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return load_error_;
}

std::string PresetStore::checkWritable() const
{
  if (load_error_.empty())
  {
    return {};
  }
  return "presets are read-only until the presets file is fixed (it is kept as it is, not overwritten) and the node "
         "restarted: " +
         load_error_;
}

std::string PresetStore::write(const std::map<std::string, AxisValues>& presets,
                               const std::map<std::string, double>& speeds) const
{
  return writeFileAtomically(path_, formatPresets(presets, speeds));
}

}  // namespace ptz_action_server
