/**
 * \file
 * \brief The ONVIF Imaging service's requests and replies for focus and iris (onvif_imaging.h), read by namespace URI
 * and local name as the rest of the ONVIF codec.
 */
#include "ptz_action_server/core/onvif/onvif_imaging.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace onvif
{
namespace
{
/// <timg:OPERATION xmlns:timg="..."><timg:VideoSourceToken>TOKEN</timg:VideoSourceToken>INNER</timg:OPERATION>
std::string request(const char* operation, const std::string& video_source, const std::string& inner = "")
{
  return std::string("<timg:") + operation + " xmlns:timg=\"" + ns::IMAGING + "\"><timg:VideoSourceToken>" +
         escaped(video_source) + "</timg:VideoSourceToken>" + inner + "</timg:" + operation + ">";
}

std::string settings(const std::string& video_source, const std::string& inner)
{
  return request("SetImagingSettings", video_source, "<timg:ImagingSettings>" + inner + "</timg:ImagingSettings>");
}

bool number(const Element* element, double& value)
{
  return element != nullptr && parseNumber(text(element), value);
}

FloatRange rangeOf(const Element* range)
{
  FloatRange read;
  read.known = number(child(range, ns::SCHEMA, "Min"), read.min) && number(child(range, ns::SCHEMA, "Max"), read.max) &&
               read.min <= read.max;
  return read.known ? read : FloatRange();
}

LensMode modeOf(const std::string& word)
{
  return word == "AUTO" ? LensMode::AUTO : word == "MANUAL" ? LensMode::MANUAL : LensMode::UNKNOWN;
}

/// The iris end that is fully open: 0 dB, the end nearer to it (cameras list 0..22 or -22..0).
bool openAtMax(const FloatRange& range)
{
  return std::abs(range.max) < std::abs(range.min);
}
}  // namespace

std::string getImagingSettings(const std::string& video_source)
{
  return request("GetImagingSettings", video_source);
}

std::string getImagingOptions(const std::string& video_source)
{
  return request("GetOptions", video_source);
}

std::string getMoveOptions(const std::string& video_source)
{
  return request("GetMoveOptions", video_source);
}

std::string getImagingStatus(const std::string& video_source)
{
  return request("GetStatus", video_source);
}

std::string setFocusMode(const std::string& video_source, bool automatic)
{
  return settings(video_source, std::string("<tt:Focus><tt:AutoFocusMode>") + (automatic ? "AUTO" : "MANUAL") +
                                    "</tt:AutoFocusMode></tt:Focus>");
}

std::string setExposure(const std::string& video_source, bool automatic, double iris)
{
  const std::string iris_element =
      !automatic && std::isfinite(iris) ? formatText("<tt:Iris>%g</tt:Iris>", iris) : std::string();
  return settings(video_source, std::string("<tt:Exposure><tt:Mode>") + (automatic ? "AUTO" : "MANUAL") + "</tt:Mode>" +
                                    iris_element + "</tt:Exposure>");
}

std::string moveFocusContinuous(const std::string& video_source, double speed)
{
  return request("Move", video_source,
                 formatText("<timg:Focus><tt:Continuous><tt:Speed>%g</tt:Speed></tt:Continuous></timg:Focus>", speed));
}

std::string moveFocusAbsolute(const std::string& video_source, double position)
{
  return request(
      "Move", video_source,
      formatText("<timg:Focus><tt:Absolute><tt:Position>%g</tt:Position></tt:Absolute></timg:Focus>", position));
}

std::string stopFocus(const std::string& video_source)
{
  return request("Stop", video_source);
}

std::string readImagingOptions(const Element* response, ImagingOptions& options)
{
  const Element* listed = child(response, ns::IMAGING, "ImagingOptions");
  if (listed == nullptr)
  {
    return "no ImagingOptions";
  }
  ImagingOptions read = options;
  const Element* focus = child(listed, ns::SCHEMA, "Focus");
  for (const Element* mode : children(focus, ns::SCHEMA, "AutoFocusModes"))
  {
    read.focus_auto = read.focus_auto || modeOf(text(mode)) == LensMode::AUTO;
    read.focus_manual = read.focus_manual || modeOf(text(mode)) == LensMode::MANUAL;
  }
  const Element* exposure = child(listed, ns::SCHEMA, "Exposure");
  for (const Element* mode : children(exposure, ns::SCHEMA, "Mode"))
  {
    read.exposure_auto = read.exposure_auto || modeOf(text(mode)) == LensMode::AUTO;
    read.exposure_manual = read.exposure_manual || modeOf(text(mode)) == LensMode::MANUAL;
  }
  read.iris = rangeOf(child(exposure, ns::SCHEMA, "Iris"));
  options = read;
  return {};
}

std::string readMoveOptions(const Element* response, ImagingOptions& options)
{
  const Element* listed = child(response, ns::IMAGING, "MoveOptions");
  if (listed == nullptr)
  {
    return "no MoveOptions";
  }
  options.focus_position = rangeOf(path(listed, ns::SCHEMA, { "Absolute", "Position" }));
  options.focus_speed = rangeOf(path(listed, ns::SCHEMA, { "Continuous", "Speed" }));
  return {};
}

std::string readImagingSettings(const Element* response, ImagingReading& reading)
{
  const Element* current = child(response, ns::IMAGING, "ImagingSettings");
  if (current == nullptr)
  {
    return "no ImagingSettings";
  }
  reading.focus_mode = modeOf(text(path(current, ns::SCHEMA, { "Focus", "AutoFocusMode" })));
  reading.exposure_mode = modeOf(text(path(current, ns::SCHEMA, { "Exposure", "Mode" })));
  reading.has_iris = number(path(current, ns::SCHEMA, { "Exposure", "Iris" }), reading.iris);
  return {};
}

std::string readImagingStatus(const Element* response, ImagingReading& reading)
{
  const Element* status = child(response, ns::IMAGING, "Status");
  if (status == nullptr)
  {
    return "no Status";
  }
  const Element* focus = child(status, ns::SCHEMA, "FocusStatus20");
  reading.has_focus = number(child(focus, ns::SCHEMA, "Position"), reading.focus);
  reading.move_status = text(child(focus, ns::SCHEMA, "MoveStatus"));
  return {};
}

double focusShare(const FloatRange& range, double value)
{
  return range.max > range.min ? std::clamp((value - range.min) / (range.max - range.min), 0.0, 1.0) : 0.0;
}

double irisShare(const FloatRange& range, double value)
{
  const double share = focusShare(range, value);
  return openAtMax(range) ? share : 1.0 - share;
}

double focusValue(const FloatRange& range, double share)
{
  return range.min + std::clamp(share, 0.0, 1.0) * (range.max - range.min);
}

double irisValue(const FloatRange& range, double share)
{
  return focusValue(range, openAtMax(range) ? share : 1.0 - share);
}

LensCapabilities imagingLens(const ImagingOptions& options, const ImagingReading& reading)
{
  LensCapabilities lens;
  LensControl& focus = lens.focus;
  focus.auto_mode = options.focus_auto && options.focus_manual;
  focus.velocity = options.focus_speed.known && options.focus_speed.max > 0.0;
  focus.absolute = options.focus_position.known && options.focus_position.max > options.focus_position.min;
  focus.feedback = focus.absolute && reading.has_focus;
  focus.present = focus.auto_mode || focus.velocity || focus.absolute;
  focus.limitation = !focus.present ? "this ONVIF camera's Imaging GetOptions and GetMoveOptions list no focus "
                                      "control" :
                                      "the ONVIF Imaging service has no one-push focus";
  LensControl& iris = lens.iris;
  iris.auto_mode = options.exposure_auto && options.exposure_manual;
  iris.absolute = options.exposure_manual && options.iris.known && options.iris.max > options.iris.min;
  iris.feedback = iris.absolute && reading.has_iris;
  iris.present = iris.auto_mode || iris.absolute;
  iris.limitation = !iris.present ? "this ONVIF camera's Imaging GetOptions lists no Exposure Iris range" :
                                    "the ONVIF Imaging service has no iris drive (only Exposure Iris values)";
  return lens;
}

}  // namespace onvif
}  // namespace ptz_action_server
