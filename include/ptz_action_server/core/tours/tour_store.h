/**
 * \file
 * \brief Named tours kept in a YAML file that is only ever replaced whole, atomically, as the presets are.
 */
#pragma once

#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "ptz_action_server/core/tours/tour.h"

namespace ptz_action_server
{
/**
 * \brief The tours of one node, in a YAML file beside its presets file:
 *
 * \code{.yaml}
 * tours:
 *   gate_round:
 *     - {preset: gate, dwell: 10, speed: 0.5}
 *     - {preset: yard, dwell: 4}         # speed absent or 0: the default speed
 * \endcode
 *
 * Every change writes the whole file anew with writeFileAtomically(). A file that exists but cannot be read or parsed
 * is reported by load() and kept: the store then holds no tours and refuses every change, so the file is never
 * overwritten with less than it holds. Thread-safe: the tour action looks tours up while the services change them.
 */
class TourStore
{
public:
  /// A store for \p path (not read yet).
  explicit TourStore(std::string path);

  /// Reads the file: "" when it was read or does not exist (no tours yet), else the reason it could not be read.
  std::string load();

  /// The tour named \p name, if there is one.
  std::optional<Tour> find(const std::string& name) const;

  /// Saves \p tour (replacing one of its name) and writes the file; "" or the reason it did not (checkTour(), the
  /// file). Nothing changes when the file cannot be written.
  std::string save(const Tour& tour);

  /// Deletes tour \p name and writes the file; "" or the reason it did not.
  std::string remove(const std::string& name);

  /// Every tour, by name.
  std::vector<Tour> list() const;

  /// "" or why the file could not be read at load() (changes are refused while it is not "").
  std::string loadError() const;

  const std::string& path() const
  {
    return path_;
  }

private:
  /// Writes \p tours atomically and takes them on success; "" or the reason. With mutex_ held.
  std::string commit(std::map<std::string, Tour> tours);

  const std::string path_;
  mutable std::mutex mutex_;
  std::map<std::string, Tour> tours_;  ///< by name
  std::string load_error_;
};

/// Reads the tours of a tours file's text into \p tours; "" or the reason (the first bad tour or stop, named).
std::string parseTours(const std::string& text, std::map<std::string, Tour>& tours);

/// The tours file's text for \p tours.
std::string formatTours(const std::map<std::string, Tour>& tours);

}  // namespace ptz_action_server
