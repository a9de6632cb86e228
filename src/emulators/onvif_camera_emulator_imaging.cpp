/**
 * \file
 * \brief OnvifCameraEmulator's Imaging service (ver20/imaging): GetOptions, GetMoveOptions, GetImagingSettings,
 * SetImagingSettings (Focus/AutoFocusMode, Exposure/Mode and Iris), Move (a continuous or absolute focus), Stop and
 * GetStatus on video_source_0, moving the simulated lens (SimLensModel).
 *
 * The specification leaves open whether a focus Move is taken while AutoFocusMode is AUTO; this camera plays the strict
 * kind: it refuses it (env:Receiver / ter:ActionNotSupported), as it refuses an Iris while Exposure/Mode is AUTO
 * (env:Sender / ter:InvalidArgVal / ter:SettingsInvalid).
 */
#include <cmath>
#include <string>

#include "onvif_camera_emulator_internal.h"
#include "ptz_action_server/core/parse_number.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace ptz_action_server
{
using namespace onvif;
using namespace onvif_emulator;

namespace
{
constexpr LensFunction FOCUS = LensFunction::FOCUS;
constexpr LensFunction IRIS = LensFunction::IRIS;
/// The lens in the camera's own units: focus Position 0 (near) .. 1000 (far), Continuous Speed -5..5, iris -22 dB
/// (most closed) .. 0 dB (fully open).
constexpr double FOCUS_MAX = 1000.0;
constexpr double FOCUS_SPEED_MAX = 5.0;
constexpr double IRIS_MIN = -22.0;

std::string range(const char* name, double min, double max)
{
  return formatText("<sch:%s><sch:Min>%g</sch:Min><sch:Max>%g</sch:Max></sch:%s>", name, min, max, name);
}

const char* modeWord(bool automatic)
{
  return automatic ? "AUTO" : "MANUAL";
}

HttpAnswer settingsInvalid(const std::string& reason)
{
  return fault(true, { "ter:InvalidArgVal", "ter:SettingsInvalid" }, reason);
}
}  // namespace

LensState OnvifCameraEmulator::lensState() const
{
  std::lock_guard<std::mutex> lock(mutex_);
  return lensStateOf(focus_iris_, clock_->now());
}

HttpAnswer OnvifCameraEmulator::imaging(const std::string& operation, const Element* request, TimePoint now)
{
  const bool focus = focus_iris_.present(FOCUS);
  const bool iris = focus_iris_.present(IRIS);
  if (text(child(request, ns::IMAGING, "VideoSourceToken")) != VIDEO_SOURCE)
  {
    return fault(true, { "ter:InvalidArgVal", "ter:NoSource" }, "The requested VideoSource does not exist");
  }
  if (operation == "GetOptions")
  {
    const std::string focus_options = focus ?
                                          std::string("<sch:Focus><sch:AutoFocusModes>AUTO</"
                                                      "sch:AutoFocusModes><sch:AutoFocusModes>MANUAL"
                                                      "</sch:AutoFocusModes>") +
                                              range("DefaultSpeed", 0, FOCUS_SPEED_MAX) + range("NearLimit", 0.1, 10) +
                                              range("FarLimit", 0, 1000) + "</sch:Focus>" :
                                          "";
    const std::string exposure_options = iris ? "<sch:Exposure><sch:Mode>AUTO</sch:Mode><sch:Mode>MANUAL</"
                                                "sch:Mode><sch:Priority>LowNoise</sch:Priority>" +
                                                    range("MinIris", IRIS_MIN, 0) + range("MaxIris", IRIS_MIN, 0) +
                                                    range("Iris", IRIS_MIN, 0) + "</sch:Exposure>" :
                                                "";
    return respond(ns::IMAGING, "GetOptionsResponse><ImagingOptions>" + exposure_options + focus_options +
                                    "</ImagingOptions></GetOptionsResponse>");
  }
  if (operation == "GetMoveOptions")
  {
    const std::string options = focus ? "<sch:Absolute>" + range("Position", 0, FOCUS_MAX) +
                                            range("Speed", 0, FOCUS_SPEED_MAX) + "</sch:Absolute><sch:Continuous>" +
                                            range("Speed", -FOCUS_SPEED_MAX, FOCUS_SPEED_MAX) + "</sch:Continuous>" :
                                        "";
    return respond(ns::IMAGING, "GetMoveOptionsResponse><MoveOptions>" + options +
                                    "</MoveOptions>"
                                    "</GetMoveOptionsResponse>");
  }
  if (operation == "GetImagingSettings")
  {
    const std::string exposure =
        iris ? formatText("<sch:Exposure><sch:Mode>%s</sch:Mode><sch:Iris>%g</sch:Iris></sch:Exposure>",
                          modeWord(focus_iris_.isAuto(IRIS)), IRIS_MIN * (1.0 - focus_iris_.position(IRIS, now))) :
               "";
    const std::string focus_settings = focus ? std::string("<sch:Focus><sch:AutoFocusMode>") +
                                                   modeWord(focus_iris_.isAuto(FOCUS)) +
                                                   "</sch:AutoFocusMode></sch:Focus>" :
                                               "";
    return respond(ns::IMAGING, "GetImagingSettingsResponse><ImagingSettings>" + exposure + focus_settings +
                                    "</ImagingSettings></GetImagingSettingsResponse>");
  }
  if (operation == "GetStatus")
  {
    const std::string status = focus ? formatText("<sch:FocusStatus20><sch:Position>%g</"
                                                  "sch:Position><sch:MoveStatus>%s</sch:MoveStatus>"
                                                  "</sch:FocusStatus20>",
                                                  FOCUS_MAX * focus_iris_.position(FOCUS, now),
                                                  focus_iris_.moving(FOCUS, now) ? "MOVING" : "IDLE") :
                                       "";
    return respond(ns::IMAGING, "GetStatusResponse><Status>" + status + "</Status></GetStatusResponse>");
  }
  if (refusing() && (operation == "SetImagingSettings" || operation == "Move" || operation == "Stop"))
  {
    return fault(true, { "ter:InvalidArgVal" }, OnvifCameraEmulator::REFUSAL);
  }
  if (operation == "SetImagingSettings")
  {
    return setImagingSettings(child(request, ns::IMAGING, "ImagingSettings"), now);
  }
  if (operation == "Move")
  {
    return moveFocus(child(request, ns::IMAGING, "Focus"), now);
  }
  if (operation == "Stop" && focus)
  {
    focus_iris_.drive(FOCUS, 0.0, now);
    return respond(ns::IMAGING, "StopResponse></StopResponse>");
  }
  return notSupported(operation);
}

HttpAnswer OnvifCameraEmulator::setImagingSettings(const Element* settings, TimePoint now)
{
  if (settings == nullptr)
  {
    return settingsInvalid("no ImagingSettings");
  }
  const Element* focus = child(settings, ns::SCHEMA, "Focus");
  const Element* exposure = child(settings, ns::SCHEMA, "Exposure");
  if ((focus != nullptr && !focus_iris_.present(FOCUS)) || (exposure != nullptr && !focus_iris_.present(IRIS)))
  {
    return settingsInvalid("The requested settings are not supported by this video source");
  }
  const std::string focus_mode = text(child(focus, ns::SCHEMA, "AutoFocusMode"));
  const std::string exposure_mode = text(child(exposure, ns::SCHEMA, "Mode"));
  const Element* iris_element = child(exposure, ns::SCHEMA, "Iris");
  double iris = 0.0;
  for (const std::string* mode : { &focus_mode, &exposure_mode })
  {
    if (!mode->empty() && *mode != "AUTO" && *mode != "MANUAL")
    {
      return settingsInvalid("The mode " + *mode + " is none of AUTO, MANUAL");
    }
  }
  const bool exposure_auto = exposure_mode.empty() ? focus_iris_.isAuto(IRIS) : exposure_mode == "AUTO";
  if (iris_element != nullptr &&
      (exposure_auto || !parseNumber(text(iris_element), iris) || iris < IRIS_MIN || iris > 0.0))
  {
    return settingsInvalid(exposure_auto ? "An Iris is set only with Exposure Mode MANUAL" :
                                           "The Iris " + text(iris_element) + " is outside -22..0 dB");
  }
  // Nothing is changed before everything was checked.
  if (!focus_mode.empty())
  {
    focus_iris_.setAuto(FOCUS, focus_mode == "AUTO", now);
  }
  if (!exposure_mode.empty())
  {
    focus_iris_.setAuto(IRIS, exposure_auto, now);
  }
  if (iris_element != nullptr)
  {
    focus_iris_.goTo(IRIS, 1.0 - iris / IRIS_MIN, now);
  }
  return respond(ns::IMAGING, "SetImagingSettingsResponse></SetImagingSettingsResponse>");
}

HttpAnswer OnvifCameraEmulator::moveFocus(const Element* focus, TimePoint now)
{
  if (!focus_iris_.present(FOCUS))
  {
    return notSupported("Move");
  }
  const Element* continuous = child(focus, ns::SCHEMA, "Continuous");
  const Element* absolute = child(focus, ns::SCHEMA, "Absolute");
  if (continuous == nullptr && absolute == nullptr)
  {
    return notSupported("Move");  // a relative focus move is not among its move options
  }
  if (focus_iris_.isAuto(FOCUS))
  {
    return fault(false, { "ter:ActionNotSupported" }, "A focus Move is not possible while AutoFocusMode is AUTO");
  }
  double value = 0.0;
  if (continuous != nullptr)
  {
    if (!parseNumber(text(child(continuous, ns::SCHEMA, "Speed")), value) || std::abs(value) > FOCUS_SPEED_MAX)
    {
      return settingsInvalid("The focus Speed is outside -5..5");
    }
    focus_iris_.drive(FOCUS, value / FOCUS_SPEED_MAX, now);
  }
  else
  {
    if (!parseNumber(text(child(absolute, ns::SCHEMA, "Position")), value) || value < 0.0 || value > FOCUS_MAX)
    {
      return settingsInvalid("The focus Position is outside 0..1000");
    }
    focus_iris_.goTo(FOCUS, value / FOCUS_MAX, now);
  }
  return respond(ns::IMAGING, "MoveResponse></MoveResponse>");
}

}  // namespace ptz_action_server
