#include "ptz_action_server/ros/param_reader.h"

#include <algorithm>
#include <sstream>

#include <ros/console.h>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
namespace
{
const char* typeName(const XmlRpc::XmlRpcValue& value)
{
  switch (value.getType())
  {
    case XmlRpc::XmlRpcValue::TypeBoolean:
      return "a bool";
    case XmlRpc::XmlRpcValue::TypeInt:
      return "an int";
    case XmlRpc::XmlRpcValue::TypeDouble:
      return "a double";
    case XmlRpc::XmlRpcValue::TypeString:
      return "a string";
    case XmlRpc::XmlRpcValue::TypeArray:
      return "a list";
    case XmlRpc::XmlRpcValue::TypeStruct:
      return "a dictionary";
    default:
      return "an unsupported type";
  }
}

std::string show(double value)
{
  std::ostringstream text;
  text << value;
  return text.str();
}
}  // namespace

ParamReader::ParamReader(const ros::NodeHandle& node_handle) : node_handle_(node_handle)
{
}

ParamReader ParamReader::child(const std::string& name) const
{
  ParamReader child(ros::NodeHandle(node_handle_, name));
  child.renames_ = renames_;
  child.prefix_ = prefix_ + name + "/";
  return child;
}

ParamReader ParamReader::renamed(ParamRenames renames) const
{
  ParamReader reader(node_handle_);
  reader.renames_ = std::make_shared<Renames>();
  reader.renames_->table = std::move(renames);
  return reader;
}

const ParamRename* ParamReader::renameOf(const std::string& name) const
{
  if (!renames_)
  {
    return nullptr;
  }
  const auto found = renames_->table.find(prefix_ + name);
  return found == renames_->table.end() ? nullptr : &found->second;
}

bool ParamReader::has(const std::string& name) const
{
  const ParamRename* rename = renameOf(name);
  return rename == nullptr ? node_handle_.hasParam(name) :
                             !rename->parameter.empty() && node_handle_.hasParam(rename->parameter);
}

bool ParamReader::get(const std::string& name, XmlRpc::XmlRpcValue& value) const
{
  const ParamRename* rename = renameOf(name);
  if (rename == nullptr)
  {
    return node_handle_.getParam(name, value);
  }
  if (rename->parameter.empty() || !node_handle_.getParam(rename->parameter, value))
  {
    return false;
  }
  if (!rename->warning.empty() && renames_->warned.insert(rename->parameter).second)
  {
    ROS_WARN("%s", rename->warning.c_str());
  }
  return true;
}

std::string ParamReader::resolve(const std::string& name) const
{
  const ParamRename* rename = renameOf(name);
  return rename == nullptr || rename->parameter.empty() ? node_handle_.resolveName(name) : rename->parameter;
}

double ParamReader::number(const std::string& name, double default_value, double min, double max) const
{
  XmlRpc::XmlRpcValue value;
  double result = default_value;
  if (get(name, value))
  {
    if (value.getType() == XmlRpc::XmlRpcValue::TypeDouble)
    {
      result = static_cast<double>(value);
    }
    else if (value.getType() == XmlRpc::XmlRpcValue::TypeInt)
    {
      result = static_cast<int>(value);
    }
    else
    {
      throw ConfigError("parameter " + resolve(name) + " must be a number, not " + typeName(value));
    }
  }
  if (!(result >= min && result <= max))
  {
    throw ConfigError("parameter " + resolve(name) + " = " + show(result) + " is outside [" + show(min) + ", " +
                      show(max) + "]");
  }
  return result;
}

int ParamReader::integer(const std::string& name, int default_value, int min, int max) const
{
  XmlRpc::XmlRpcValue value;
  int result = default_value;
  if (get(name, value))
  {
    if (value.getType() != XmlRpc::XmlRpcValue::TypeInt)
    {
      throw ConfigError("parameter " + resolve(name) + " must be an int, not " + typeName(value));
    }
    result = static_cast<int>(value);
  }
  if (result < min || result > max)
  {
    throw ConfigError("parameter " + resolve(name) + " = " + std::to_string(result) + " is outside [" +
                      std::to_string(min) + ", " + std::to_string(max) + "]");
  }
  return result;
}

bool ParamReader::flag(const std::string& name, bool default_value) const
{
  XmlRpc::XmlRpcValue value;
  if (!get(name, value))
  {
    return default_value;
  }
  if (value.getType() != XmlRpc::XmlRpcValue::TypeBoolean)
  {
    throw ConfigError("parameter " + resolve(name) + " must be a bool (true/false), not " + typeName(value));
  }
  return static_cast<bool>(value);
}

std::string ParamReader::text(const std::string& name, const std::string& default_value) const
{
  XmlRpc::XmlRpcValue value;
  if (!get(name, value))
  {
    return default_value;
  }
  if (value.getType() != XmlRpc::XmlRpcValue::TypeString)
  {
    throw ConfigError("parameter " + resolve(name) + " must be a string, not " + typeName(value));
  }
  return static_cast<std::string>(value);
}

std::string ParamReader::choice(const std::string& name, const std::string& default_value,
                                const std::vector<std::string>& allowed) const
{
  const std::string result = text(name, default_value);
  if (std::find(allowed.begin(), allowed.end(), result) == allowed.end())
  {
    std::string list;
    for (const std::string& option : allowed)
    {
      list += (list.empty() ? "" : ", ") + option;
    }
    throw ConfigError("parameter " + resolve(name) + " = '" + result + "' is not one of: " + list);
  }
  return result;
}

}  // namespace ptz_action_server
