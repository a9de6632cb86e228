/**
 * \file
 * \brief Typed, range-checked reads from the parameter server, for filling the core's config structs once.
 */
#pragma once

#include <string>
#include <vector>

#include <ros/node_handle.h>

namespace ptz_action_server
{
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

  /// A reader for the sub-namespace \p name (e.g. the backend's parameters).
  ParamReader child(const std::string& name) const;

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

  /// The fully resolved name of \p name, as errors print it.
  std::string resolve(const std::string& name) const;

  const ros::NodeHandle& nodeHandle() const
  {
    return node_handle_;
  }

private:
  ros::NodeHandle node_handle_;
};

}  // namespace ptz_action_server
