/**
 * \file
 * \brief Named poses (presets) kept in a YAML file that is only ever replaced whole, atomically.
 */
#pragma once

#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
/// A preset's name and pose: pan, tilt (rad), zoom (X).
using NamedPose = std::pair<std::string, AxisValues>;

/**
 * \brief The presets of one node: "home" from the configuration, the others saved by name in a YAML file.
 *
 * Every change writes the whole file anew: a temporary file in the same directory, flushed and fsynced, renamed
 * over the old one, then the directory fsynced. A crash or a power loss leaves either the old file or the new one,
 * never half of one. A file that exists but cannot be read or parsed is reported by load() and kept: the store then
 * holds only home and refuses every change, so the file is never overwritten with less than it holds.
 *
 * Thread-safe: the node looks presets up on its goal queue while the services change them on their own.
 */
class PresetStore
{
public:
  static constexpr const char* HOME = "home";     ///< the predefined preset
  static constexpr std::size_t MAX_NAME = 64;     ///< longest name, in characters
  static constexpr std::size_t MAX_COUNT = 1000;  ///< most saved presets (home not counted)

  /// A store for \p path (not read yet) with \p home as the home pose.
  PresetStore(std::string path, const AxisValues& home);

  /// Reads the file: "" when it was read or does not exist (no presets yet), else the reason it could not be read;
  /// the store then keeps only home and refuses changes until the file is fixed and the store loaded again.
  std::string load();

  /// The pose of preset \p name (home included), if there is one.
  std::optional<AxisValues> find(const std::string& name) const;

  /// Saves \p pose as \p name (replacing one of that name) and writes the file; "" or the reason it did not.
  /// Nothing changes when the file cannot be written.
  std::string save(const std::string& name, const AxisValues& pose);

  /// Deletes preset \p name and writes the file; "" or the reason it did not.
  std::string remove(const std::string& name);

  /// Every preset: home first, then the saved ones by name.
  std::vector<NamedPose> list() const;

  /// The speed a goal to preset \p name runs at, a fraction (0, 1] of the top speed; 0: the default speed (home, a
  /// preset without one, or none of that name).
  double speed(const std::string& name) const;
  /// Sets the speed of the saved preset \p name (0: the default speed) and writes the file; "" or the reason it did
  /// not. Saving the preset's pose again keeps it; deleting the preset deletes it.
  std::string setSpeed(const std::string& name, double fraction);

  /// "" or why the file could not be read at load() (changes are refused while it is not "").
  std::string loadError() const;

  const std::string& path() const
  {
    return path_;
  }

  /// "" when \p name may be saved, else why not (empty, too long, not printable ASCII, spaces around it, home).
  static std::string checkName(const std::string& name);

private:
  /// Writes \p presets to the file atomically; "" or the reason.
  std::string write(const std::map<std::string, AxisValues>& presets,
                    const std::map<std::string, double>& speeds) const;
  /// "" when the store may change, else why not.
  std::string checkWritable() const;

  const std::string path_;
  const AxisValues home_;
  mutable std::mutex mutex_;
  std::map<std::string, AxisValues> presets_;  ///< saved presets by name (never home)
  std::map<std::string, double> speeds_;       ///< the saved presets' speeds, where they have one (> 0)
  std::string load_error_;
};

}  // namespace ptz_action_server
