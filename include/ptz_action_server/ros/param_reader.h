/**
 * \file
 * \brief Typed, range-checked reads from the parameter server, for filling the core's config structs once.
 */
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

namespace ptz_action_server
{
/// What a reader reads in the place of a name it is asked for (an old spelling of it: see ParamReader::renamed()).
struct ParamRename
{
  std::string parameter;  ///< resolved ("/ptz/ptz_action_server/pantilt_udp/device_host"); empty: none, the default
  std::string warning;    ///< printed once (ROS_WARN) when the parameter is read; empty: none
};

/// Names as a reader is asked for them ("host", "pan/min") and what it reads in their place.
using ParamRenames = std::map<std::string, ParamRename>;

/**
 * \brief Reads parameters under one namespace; every error (a ConfigError) names the resolved parameter.
 *
 * Defaults are typed values, never strings: a missing parameter takes the default, a parameter of the wrong type or
 * out of range is an error rather than silently replaced.
 */
class ParamReader
{
public:
  explicit ParamReader(const ros::NodeHandle& node_handle);

  /// A reader for the sub-namespace \p name (e.g. the backend's parameters), with the renames under it.
  ParamReader child(const std::string& name) const;
  /// This reader, reading each name of \p renames from the parameter given there (the old names of
  /// src/plugins/deprecated_names.h): code that reads through it knows only the names of today.
  ParamReader renamed(ParamRenames renames) const;

  /// A double (an int is accepted too) in [\p min, \p max].
  double number(const std::string& name, double default_value, double min, double max) const;
  /// An int in [\p min, \p max].
  int integer(const std::string& name, int default_value, int min, int max) const;
  bool flag(const std::string& name, bool default_value) const;
  std::string text(const std::string& name, const std::string& default_value) const;
  /// A string that must be one of \p allowed.
  std::string choice(const std::string& name, const std::string& default_value,
                     const std::vector<std::string>& allowed) const;
  bool has(const std::string& name) const;
  /// The value of \p name whatever its type, for a parameter that may take several; false if it is not set.
  bool get(const std::string& name, XmlRpc::XmlRpcValue& value) const;

  /// The fully resolved name of the parameter read for \p name, as errors print it.
  std::string resolve(const std::string& name) const;

  const ros::NodeHandle& nodeHandle() const
  {
    return node_handle_;
  }

private:
  /// The renames of a reader and its children, and the warnings already printed (one thread: the one reading).
  struct Renames
  {
    ParamRenames table;
    std::set<std::string> warned;
  };

  /// The rename of \p name, or none.
  const ParamRename* renameOf(const std::string& name) const;

  ros::NodeHandle node_handle_;
  std::shared_ptr<Renames> renames_;
  std::string prefix_;  ///< this reader's names under the renamed reader it is a child of ("pan/")
};

}  // namespace ptz_action_server
