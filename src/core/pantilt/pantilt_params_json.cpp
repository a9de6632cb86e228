#include "ptz_action_server/core/pantilt/pantilt_codec.h"

#include <fstream>

#include <nlohmann/json.hpp>

#include "pantilt_fields.h"

namespace cr
{
namespace pantilt
{
using namespace detail;

// --- PanTiltParams as JSON

nlohmann::json PanTiltParams::toJson() const
{
  nlohmann::json json = nlohmann::json::object();
  for (const Field* field : ALL_FIELDS)
  {
    switch (field->type)
    {
      case FieldType::INT32:
        json[field->name] = this->*field->int_member;
        break;
      case FieldType::FLOAT32:
        json[field->name] = this->*field->float_member;
        break;
      case FieldType::FLAG:
        json[field->name] = this->*field->flag_member;
        break;
    }
  }
  return json;
}

bool PanTiltParams::fromJson(const nlohmann::json& json, std::string* error)
{
  if (!json.is_object())
  {
    if (error)
    {
      *error = "params must be a JSON object";
    }
    return false;
  }
  PanTiltParams read = *this;
  for (const Field* field : ALL_FIELDS)
  {
    const auto member = json.find(field->name);
    if (member == json.end())
    {
      continue;
    }
    const bool ok = field->type == FieldType::INT32   ? member->is_number_integer() :
                    field->type == FieldType::FLOAT32 ? member->is_number() :
                                                        member->is_boolean();
    if (!ok)
    {
      if (error)
      {
        *error = std::string("field '") + field->name + "' has the wrong type";
      }
      return false;
    }
    switch (field->type)
    {
      case FieldType::INT32:
        read.*field->int_member = member->get<int>();
        break;
      case FieldType::FLOAT32:
        read.*field->float_member = member->get<float>();
        break;
      case FieldType::FLAG:
        read.*field->flag_member = member->get<bool>();
        break;
    }
  }
  *this = read;
  return true;
}

bool PanTiltParams::writeToFile(const std::string& path, const std::string& key) const
{
  std::ofstream file(path);
  if (!file)
  {
    return false;
  }
  nlohmann::json document;
  document[key] = toJson();
  file << document.dump(2) << '\n';
  return static_cast<bool>(file);
}

bool PanTiltParams::readFromFile(const std::string& path, const std::string& key, std::string* error)
{
  std::ifstream file(path);
  if (!file)
  {
    if (error)
    {
      *error = "cannot open " + path;
    }
    return false;
  }
  const nlohmann::json document = nlohmann::json::parse(file, nullptr, false);
  if (document.is_discarded() || !document.is_object() || !document.contains(key))
  {
    if (error)
    {
      *error = path + " is not JSON with a '" + key + "' object";
    }
    return false;
  }
  return fromJson(document.at(key), error);
}

}  // namespace pantilt
}  // namespace cr
