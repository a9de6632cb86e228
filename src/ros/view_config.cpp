#include "ptz_action_server/ros/view_config.h"

#include <cmath>
#include <vector>

#include <xmlrpcpp/XmlRpcValue.h>

#include "ptz_action_server/core/types.h"

namespace ptz_action_server
{
namespace
{
bool isNumber(const XmlRpc::XmlRpcValue& value)
{
  return value.getType() == XmlRpc::XmlRpcValue::TypeDouble || value.getType() == XmlRpc::XmlRpcValue::TypeInt;
}

double toNumber(XmlRpc::XmlRpcValue& value)
{
  return value.getType() == XmlRpc::XmlRpcValue::TypeInt ? static_cast<int>(value) : static_cast<double>(value);
}

/// ~field_of_view/table as rows; throws ConfigError naming the parameter and the row.
std::vector<FieldOfViewRow> readTable(const ParamReader& params)
{
  const std::string name = params.resolve("table");
  const std::string shape = "a list of [zoom, horizontal, vertical] rows (X, rad, rad)";
  XmlRpc::XmlRpcValue table;
  params.nodeHandle().getParam("table", table);
  if (table.getType() != XmlRpc::XmlRpcValue::TypeArray)
  {
    throw ConfigError("parameter " + name + " must be " + shape);
  }
  std::vector<FieldOfViewRow> rows;
  for (int index = 0; index < table.size(); ++index)
  {
    XmlRpc::XmlRpcValue& row = table[index];
    if (row.getType() != XmlRpc::XmlRpcValue::TypeArray || row.size() != 3 || !isNumber(row[0]) || !isNumber(row[1]) ||
        !isNumber(row[2]))
    {
      throw ConfigError("parameter " + name + ": row " + std::to_string(index) + " is not [zoom, horizontal, " +
                        "vertical]; it must be " + shape);
    }
    rows.push_back(FieldOfViewRow{ toNumber(row[0]), { toNumber(row[1]), toNumber(row[2]) } });
  }
  return rows;
}
}  // namespace

MountConfig loadMountConfig(const ParamReader& params)
{
  MountConfig mount;
  mount.inverted = params.choice("mount", "upright", { "upright", "inverted" }) == "inverted";
  mount.pan_offset = params.number("pan_offset", 0.0, -2.0 * M_PI, 2.0 * M_PI);
  return mount;
}

FieldOfViewSettings FieldOfViewSettings::load(const ParamReader& params)
{
  FieldOfViewSettings settings;
  const ParamReader view = params.child("field_of_view");
  const bool wide_end = view.has("horizontal") || view.has("vertical");
  if (wide_end && view.has("table"))
  {
    throw ConfigError("parameters " + view.resolve("horizontal") + "/vertical and " + view.resolve("table") +
                      " exclude each other: give the wide-end angles or a table");
  }
  if (view.has("zoom_law") && !wide_end)
  {
    throw ConfigError("parameter " + view.resolve("zoom_law") + " applies to the wide-end angles " +
                      view.resolve("horizontal") + " and " + view.resolve("vertical") + ", which are not set");
  }
  if (wide_end)
  {
    if (!view.has("horizontal") || !view.has("vertical"))
    {
      throw ConfigError("parameters " + view.resolve("horizontal") + " and " + view.resolve("vertical") +
                        " go together: give both wide-end angles (rad)");
    }
    const double horizontal = view.number("horizontal", 1.0, 1e-6, M_PI - 1e-6);
    const double vertical = view.number("vertical", 1.0, 1e-6, M_PI - 1e-6);
    const ZoomLaw law =
        view.choice("zoom_law", "lens", { "lens", "divided" }) == "divided" ? ZoomLaw::DIVIDED : ZoomLaw::LENS;
    settings.model = FieldOfViewModel::fromWideEnd({ horizontal, vertical }, law);
  }
  else if (view.has("table"))
  {
    try
    {
      settings.model = FieldOfViewModel::fromTable(readTable(view));
    }
    catch (const ConfigError& error)
    {
      const std::string text = error.what();
      throw ConfigError(text.rfind("parameter ", 0) == 0 ? text : "parameter " + view.resolve("table") + ": " + text);
    }
  }

  settings.camera_info_topic = params.text("camera_info_topic", "");
  settings.camera_info_zoom = params.number("camera_info_zoom", 1.0, 1.0, 1000.0);
  if (!settings.camera_info_topic.empty() && !settings.model)
  {
    throw ConfigError("parameter " + params.resolve("camera_info_topic") + " is set, but rescaling camera_info needs " +
                      "a field of view: set " + view.resolve("horizontal") + " and " + view.resolve("vertical") +
                      " or " + view.resolve("table"));
  }
  return settings;
}

}  // namespace ptz_action_server
