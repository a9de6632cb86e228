/**
 * \file
 * \brief AxisProtocol: what the camera's zoom is (its X-factor table and where it came from) and what it can do
 * (capabilities from the limits and info=1). The link, the requests and the commands are in axis_protocol.cpp.
 */
#include <algorithm>
#include <cmath>

#include "ptz_action_server/core/axis/axis_protocol.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"

namespace ptz_action_server
{
const char* zoomSourceName(AxisZoomSource source)
{
  switch (source)
  {
    case AxisZoomSource::NO_ZOOM:
      return "no zoom";
    case AxisZoomSource::CONFIGURED_TABLE:
      return "configured zoom_table";
    case AxisZoomSource::CONFIGURED_MAXIMUM:
      return "configured zoom_max_factor";
    case AxisZoomSource::CAMERA_TABLE:
      return "camera zoomSteps";
    case AxisZoomSource::CAMERA_MAXIMUM:
      return "camera maxOpticalZoomMag";
    case AxisZoomSource::MODEL_GUESS:
      return "model family guess";
    case AxisZoomSource::UNKNOWN:
      return "unknown";
  }
  return "?";
}

Capabilities AxisProtocol::cameraCapabilities(const vapix::Limits& limits, const vapix::CommandList& commands) const
{
  // A camera that gave no usable info=1 is taken to offer what VAPIX documents for a PTZ camera; the informative
  // flags (relative moves, presets, home) are only declared when it lists them.
  const bool listed = !commands.empty();
  const auto offered = [&](const char* name) { return !listed || commands.has(name); };
  Capabilities capabilities;
  AxisCapability& pan = capabilities.axes[PAN];
  pan = fullAxis({ toRadians(limits.min_pan), toRadians(limits.max_pan) }, settings_.pan_max_speed,
                 settings_.acceleration);
  pan.absolute = offered("pan");
  pan.velocity = offered("continuouspantiltmove");
  AxisCapability& tilt = capabilities.axes[TILT];
  tilt = fullAxis({ toRadians(limits.min_tilt), toRadians(limits.max_tilt) }, settings_.tilt_max_speed,
                  settings_.acceleration);
  tilt.absolute = offered("tilt");
  tilt.velocity = offered("continuouspantiltmove");
  for (AxisCapability* axis : { &pan, &tilt })
  {
    if (!axis->absolute)
    {
      axis->limitation = "this Axis camera does not list absolute pan/tilt in info=1";
    }
  }

  capabilities.relative_moves = listed && commands.has("rpan") && commands.has("rtilt");
  capabilities.device_presets =
      listed && (commands.offers("query", "presetposall") || commands.offers("query", "presetposcam") ||
                 commands.has("gotoserverpresetno"));
  capabilities.device_home = listed && commands.offers("move", "home");
  // center and areazoom work on the camera's own picture: only a camera that lists them is asked to.
  capabilities.view_centre = listed && commands.has("center");
  capabilities.view_box_zoom =
      capabilities.view_centre && commands.has("areazoom") && zoom_source_ != AxisZoomSource::NO_ZOOM;
  capabilities.view_command = capabilities.view_box_zoom ? "VAPIX center, areazoom" : "VAPIX center";
  capabilities.speed = moveSpeed();

  AxisCapability& zoom = capabilities.axes[ZOOM];
  if (zoom_source_ == AxisZoomSource::NO_ZOOM)
  {
    zoom = absentAxis("this Axis camera's limits give no zoom");
    return capabilities;
  }
  zoom = fullAxis({ 1.0, 1.0 }, settings_.zoom_max_rate, 0.0);
  zoom.velocity = zoom_velocity_;
  if (zoom_feedback_)
  {
    zoom.range = { zoom_table_.toFactor(std::max(limits.min_zoom, zoom_table_.minValue())),
                   zoom_table_.toFactor(std::min(limits.max_zoom, zoom_table_.maxValue())) };
    zoom.absolute = offered("zoom");
    if (zoom_source_ == AxisZoomSource::MODEL_GUESS)
    {
      zoom.limitation = "this Axis camera gives no zoom table: its X-factor is a guess (" + zoom_text_ + ")";
      zoom.remedy = "set axis/zoom_max_factor to its optical zoom, or axis/zoom_table";
    }
  }
  else
  {
    zoom.absolute = false;
    zoom.feedback = false;
    // Whatever its X-factors, `zoom=` at the limits' MinZoom is the widest view: a zoom 1 goal can go there.
    zoom.widest_view = widest_view_;
    if (zoom_table_.empty())
    {
      zoom.limitation = "this Axis camera gives no zoom table";
      zoom.remedy = "set axis/zoom_table (or axis/zoom_max_factor, its optical zoom)";
    }
    else
    {
      zoom.limitation = "this Axis camera reports no zoom position";
    }
  }
  return capabilities;
}

AxisZoomSource AxisProtocol::zoomSource() const
{
  std::lock_guard<std::mutex> lock(facts_mutex_);
  return shared_zoom_source_;
}

bool AxisProtocol::findZoomTable(const vapix::Limits& limits)
{
  zoom_table_ = vapix::ZoomTable();
  std::string text;
  std::string model;
  if (!limits.has_zoom)
  {
    zoom_source_ = AxisZoomSource::NO_ZOOM;
    text = "none: query=limits gives no MinZoom/MaxZoom";
  }
  else if (!configured_table_.empty())
  {
    zoom_table_ = configured_table_;
    zoom_source_ = settings_.zoom_table.empty() ? AxisZoomSource::CONFIGURED_MAXIMUM : AxisZoomSource::CONFIGURED_TABLE;
    text = settings_.zoom_table.empty() ? formatText("zoom_max_factor %gX, linear", settings_.zoom_max_factor) :
                                          "zoom_table " + settings_.zoom_table;
  }
  else
  {
    std::string problem;
    std::string body;
    const std::string arguments = "query=attributes&group=zoom";
    vapix::ZoomAttributes attributes;
    const std::string path = formatText("%s?camera=%d&%s", vapix::PTZ_PATH, settings_.camera, arguments.c_str());
    std::string refusal = "no answer";
    if (exchange(path, "'" + arguments + "'", body, problem))
    {
      problem = vapix::readZoomAttributes(body, settings_.camera, attributes);
      if (problem.empty() && attributes.refused)
      {
        refusal = attributes.refusal;
      }
      else if (problem.empty() && attributes.steps.empty() && attributes.max_optical == 0.0)
      {
        refusal = "no zoomSteps and no maxOpticalZoomMag in the answer";
      }
      else if (problem.empty())
      {
        problem = vapix::zoomTableOf(attributes, zoom_table_);
      }
      if (!problem.empty())
      {
        ++counters_.malformed;
        setupFailed(arguments + ": " + problem + " (set axis/zoom_table or axis/zoom_max_factor to override it)");
        return false;
      }
    }
    else if (!session_.connected())
    {
      return false;
    }
    else
    {
      refusal = problem;  // an HTTP error: no attributes either
    }
    if (!zoom_table_.empty())
    {
      zoom_source_ = attributes.steps.empty() ? AxisZoomSource::CAMERA_MAXIMUM : AxisZoomSource::CAMERA_TABLE;
      text = attributes.steps.empty() ?
                 formatText("the camera's maxOpticalZoomMag %gX, linear", attributes.max_optical) :
                 formatText("the camera's zoomSteps (%zu points, %g..%gX)", zoom_table_.size(), zoom_table_.minFactor(),
                            zoom_table_.maxFactor());
    }
    else
    {
      // No table from the camera: its model may tell (param.cgi), as a guess.
      vapix::Product product;
      if (exchange(vapix::BRAND_PATH, "the brand parameters", body, problem))
      {
        vapix::Reply brand;
        if (vapix::parseReply(body, brand).empty() && vapix::readProduct(brand, product).empty())
        {
          model = product.full_name.empty() ? "AXIS " + product.number : product.full_name;
        }
      }
      else if (!session_.connected())
      {
        return false;
      }
      vapix::FamilyZoom family;
      const std::string camera = model.empty() ? "this Axis camera" : model;
      const std::string why = "query=attributes&group=zoom: " + refusal;
      if (settings_.zoom_guess && !product.number.empty() && vapix::modelFamilyZoom(product.number, family))
      {
        zoom_table_ = vapix::ZoomTable::linear(family.max_optical);
        zoom_source_ = AxisZoomSource::MODEL_GUESS;
        text = formatText("GUESS: %gX optical at VAPIX zoom 9999, linear, the usual zoom of %s", family.max_optical,
                          family.models);
        session_.warn(camera + " gives no zoom table (" + why + "): its zoom X-factor is a guess, " +
                      formatText("%gX optical as is usual for %s, linear from VAPIX zoom 1 to 9999; ",
                                 family.max_optical, family.models) +
                      "set axis/zoom_max_factor to its optical zoom (data sheet) or axis/zoom_table");
      }
      else
      {
        zoom_source_ = AxisZoomSource::UNKNOWN;
        const char* reason = !settings_.zoom_guess  ? "zoom_guess is off" :
                             product.number.empty() ? "its model could not be read" :
                                                      "its model family has no default";
        text = std::string("UNKNOWN: no zoom table, ") + reason +
               "; zoom goals other than 1 (the widest view) are refused";
        session_.warn(camera + " gives no zoom table (" + why + ") and " + reason +
                      ": zoom goals other than 1 (the widest view) are refused (velocity goals work); set "
                      "axis/zoom_table or axis/zoom_max_factor (its optical zoom)");
      }
    }
  }
  std::lock_guard<std::mutex> lock(facts_mutex_);
  shared_zoom_source_ = zoom_source_;
  zoom_text_ = text;
  if (!model.empty())
  {
    model_text_ = model;
  }
  return true;
}

}  // namespace ptz_action_server
