/**
 * \file
 * \brief OnvifCameraEmulator's PTZ service: its spaces, node and configuration as it lists them, the operations on a
 * profile sorted out (refused under setRefuse()), and the presets. How it moves is onvif_camera_emulator_moves.cpp's.
 */
#include <cmath>
#include <cstdlib>
#include <string>

#include "onvif_camera_emulator_internal.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/text.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace ptz_action_server
{
using namespace onvif;
using namespace onvif_emulator;

namespace
{
std::string range(const char* name, double min, double max)
{
  return formatText("<sch:%s><sch:Min>%g</sch:Min><sch:Max>%g</sch:Max></sch:%s>", name, min, max, name);
}

std::string space(const char* kind, const char* uri, double min, double max)
{
  return std::string("<sch:") + kind + "><sch:URI>" + uri + "</sch:URI>" + range("XRange", min, max) + "</sch:" + kind +
         ">";
}

std::string space(const char* kind, const char* uri, double x_min, double x_max, double y_min, double y_max)
{
  return std::string("<sch:") + kind + "><sch:URI>" + uri + "</sch:URI>" + range("XRange", x_min, x_max) +
         range("YRange", y_min, y_max) + "</sch:" + kind + ">";
}
}  // namespace

const char* OnvifCameraEmulator::defaultSpace() const
{
  // A continuous-only camera lists no position space, and reports its status in the generic one (as those do).
  return config_.absolute && config_.degree_space && config_.degrees_default ? DEGREE_SPACE : GENERIC_PAN_TILT_SPACE;
}

std::string OnvifCameraEmulator::supportedSpaces() const
{
  std::string spaces;
  if (config_.absolute)
  {
    spaces += (config_.degree_space ? space("AbsolutePanTiltPositionSpace", DEGREE_SPACE, -180, 180, -90, 90) : "") +
              space("AbsolutePanTiltPositionSpace", GENERIC_PAN_TILT_SPACE, config_.listed_generic_pan_min,
                    config_.listed_generic_pan_max, -1, 1) +
              space("AbsoluteZoomPositionSpace", GENERIC_ZOOM_SPACE, 0, 1);
    if (config_.relative)
    {
      spaces +=
          (config_.degree_space ? space("RelativePanTiltTranslationSpace", DEGREE_TRANSLATION, -360, 360, -180, 180) :
                                  "") +
          space("RelativePanTiltTranslationSpace", GENERIC_PAN_TILT_TRANSLATION, -1, 1, -1, 1) +
          space("RelativeZoomTranslationSpace", GENERIC_ZOOM_TRANSLATION, -1, 1);
      if (config_.fov_space)  // after the generic ones, as cameras list it
      {
        spaces += space("RelativePanTiltTranslationSpace", FOV_PAN_TILT_TRANSLATION, -1, 1, -1, 1) +
                  space("RelativeZoomTranslationSpace", FOV_ZOOM_TRANSLATION, 0, zoomMax());
      }
    }
  }
  spaces += space("ContinuousPanTiltVelocitySpace", GENERIC_PAN_TILT_VELOCITY, -1, 1, -1, 1) +
            space("ContinuousZoomVelocitySpace", GENERIC_ZOOM_VELOCITY, -1, 1);
  if (config_.absolute && config_.speed_space)
  {
    spaces +=
        space("PanTiltSpeedSpace", GENERIC_PAN_TILT_SPEED, 0, 1) + space("ZoomSpeedSpace", GENERIC_ZOOM_SPEED, 0, 1);
  }
  return spaces;
}

std::string OnvifCameraEmulator::ptzConfiguration(const char* element) const
{
  std::string defaults;
  if (config_.absolute)
  {
    defaults += std::string("<sch:DefaultAbsolutePantTiltPositionSpace>") + defaultSpace() +
                "</sch:DefaultAbsolutePantTiltPositionSpace><sch:DefaultAbsoluteZoomPositionSpace>" +
                GENERIC_ZOOM_SPACE + "</sch:DefaultAbsoluteZoomPositionSpace>";
    if (config_.relative)
    {
      defaults += std::string("<sch:DefaultRelativePanTiltTranslationSpace>") + GENERIC_PAN_TILT_TRANSLATION +
                  "</sch:DefaultRelativePanTiltTranslationSpace><sch:DefaultRelativeZoomTranslationSpace>" +
                  GENERIC_ZOOM_TRANSLATION + "</sch:DefaultRelativeZoomTranslationSpace>";
    }
  }
  defaults += std::string("<sch:DefaultContinuousPanTiltVelocitySpace>") + GENERIC_PAN_TILT_VELOCITY +
              "</sch:DefaultContinuousPanTiltVelocitySpace><sch:DefaultContinuousZoomVelocitySpace>" +
              GENERIC_ZOOM_VELOCITY + "</sch:DefaultContinuousZoomVelocitySpace>";
  if (config_.absolute)
  {
    defaults += std::string("<sch:DefaultPTZSpeed><sch:PanTilt x=\"1\" y=\"1\" space=\"") + GENERIC_PAN_TILT_SPEED +
                "\"/><sch:Zoom x=\"1\" space=\"" + GENERIC_ZOOM_SPEED + "\"/></sch:DefaultPTZSpeed>";
  }
  return std::string("<") + element + " token=\"" + CONFIGURATION + "\"><sch:Name>ptz</sch:Name><sch:UseCount>1" +
         "</sch:UseCount><sch:NodeToken>" + NODE + "</sch:NodeToken>" + defaults +
         "<sch:DefaultPTZTimeout>PT5S</sch:DefaultPTZTimeout></" + element + ">";
}

std::string OnvifCameraEmulator::positionVector(const char* element, const AxisValues& position) const
{
  const bool degrees = std::string(defaultSpace()) == DEGREE_SPACE;
  const double x = degrees ? toDegrees(position[PAN]) : position[PAN] / M_PI;
  const double y = degrees ? toDegrees(position[TILT]) : position[TILT] / (M_PI / 2.0);
  const double z = std::log(position[ZOOM]) / std::log(zoomMax());
  return formatText("<sch:%s><sch:PanTilt x=\"%.6f\" y=\"%.6f\" space=\"%s\"/><sch:Zoom x=\"%.6f\" "
                    "space=\"%s\"/></sch:%s>",
                    element, x, y, defaultSpace(), z, GENERIC_ZOOM_SPACE, element);
}

HttpAnswer OnvifCameraEmulator::ptz(const std::string& operation, const SoapMessage& message, TimePoint now)
{
  const Element* request = message.content;
  if (operation == "GetServiceCapabilities")
  {
    return respond(ns::PTZ, std::string("GetServiceCapabilitiesResponse><Capabilities EFlip=\"false\" "
                                        "Reverse=\"false\" GetCompatibleConfigurations=\"false\" MoveStatus=\"true\" "
                                        "StatusPosition=\"") +
                                (config_.status_position ? "true" : "false") + "\"/></GetServiceCapabilitiesResponse>");
  }
  const std::string node =
      std::string("<PTZNode token=\"") + NODE +
      "\" FixedHomePosition=\"false\"><sch:Name>node</sch:Name><sch:SupportedPTZSpaces>" + supportedSpaces() +
      "</sch:SupportedPTZSpaces>" +
      formatText("<sch:MaximumNumberOfPresets>%d</sch:MaximumNumberOfPresets>", config_.max_presets) +
      "<sch:HomeSupported>" + (config_.home ? "true" : "false") + "</sch:HomeSupported></PTZNode>";
  if (operation == "GetNodes")
  {
    return respond(ns::PTZ, "GetNodesResponse>" + node + "</GetNodesResponse>");
  }
  if (operation == "GetNode")
  {
    if (text(child(request, ns::PTZ, "NodeToken")) != NODE)
    {
      return invalid("ter:NoEntity", "No such PTZ node on the device");
    }
    return respond(ns::PTZ, "GetNodeResponse>" + node + "</GetNodeResponse>");
  }
  if (operation == "GetConfigurations")
  {
    return respond(ns::PTZ, "GetConfigurationsResponse>" + ptzConfiguration("PTZConfiguration") +
                                "</GetConfigurationsResponse>");
  }
  if (operation == "GetConfiguration" || operation == "GetConfigurationOptions")
  {
    const bool options = operation == "GetConfigurationOptions";
    if (text(child(request, ns::PTZ, options ? "ConfigurationToken" : "PTZConfigurationToken")) != CONFIGURATION)
    {
      return invalid("ter:NoConfig", "The requested configuration does not exist");
    }
    if (!options)
    {
      return respond(ns::PTZ, "GetConfigurationResponse>" + ptzConfiguration("PTZConfiguration") +
                                  "</GetConfigurationResponse>");
    }
    return respond(ns::PTZ, "GetConfigurationOptionsResponse><PTZConfigurationOptions><sch:Spaces>" +
                                supportedSpaces() +
                                formatText("</sch:Spaces><sch:PTZTimeout><sch:Min>PT%gS</sch:Min><sch:Max>PT%gS"
                                           "</sch:Max></sch:PTZTimeout>",
                                           config_.min_timeout, config_.max_timeout) +
                                "</PTZConfigurationOptions></GetConfigurationOptionsResponse>");
  }
  // Everything below acts on a profile: it must exist and have PTZ.
  const std::string profile = text(child(request, ns::PTZ, "ProfileToken"));
  if (profile == PROFILE_WITHOUT_PTZ)
  {
    return invalid("ter:NoPTZProfile", "The requested profile token does not reference a PTZ configuration");
  }
  if (profile != PROFILE)
  {
    return invalid("ter:NoProfile", "The requested profile token ProfileToken does not exist");
  }
  const bool moves = operation == "AbsoluteMove" || operation == "ContinuousMove" || operation == "RelativeMove" ||
                     operation == "GotoPreset" || operation == "GotoHomePosition";
  if (moves && refusing())
  {
    return fault(true, { "ter:InvalidArgVal" }, OnvifCameraEmulator::REFUSAL);
  }
  const bool preset_operation =
      operation == "GetPresets" || operation == "SetPreset" || operation == "GotoPreset" || operation == "RemovePreset";
  return preset_operation ? presets(operation, request, now) : move(operation, request, now);
}

HttpAnswer OnvifCameraEmulator::presets(const std::string& operation, const Element* request, TimePoint now)
{
  if (!config_.absolute || !config_.presets || config_.max_presets <= 0)
  {
    return notSupported(operation);  // the continuous-only cameras: no positions, so no presets either
  }
  if (operation == "GetPresets")
  {
    std::string listed;
    for (const auto& preset : presets_)
    {
      listed += formatText("<Preset token=\"%d\"><sch:Name>", preset.first) + escaped(preset.second.name) +
                "</sch:Name>" + positionVector("PTZPosition", preset.second.position) + "</Preset>";
    }
    return respond(ns::PTZ, "GetPresetsResponse>" + listed + "</GetPresetsResponse>");
  }
  const std::string token_text = text(child(request, ns::PTZ, "PresetToken"));
  char* end = nullptr;
  const long token = std::strtol(token_text.c_str(), &end, 10);
  const auto found = !token_text.empty() && *end == '\0' ? presets_.find(static_cast<int>(token)) : presets_.end();
  if (operation == "SetPreset")
  {
    if (!token_text.empty() && found == presets_.end())
    {
      return invalid("ter:NoToken", "The requested preset token does not exist");
    }
    const Element* name_element = child(request, ns::PTZ, "PresetName");
    std::string name = text(name_element);
    for (const auto& preset : presets_)
    {
      if (name_element != nullptr && preset.second.name == name &&
          (found == presets_.end() || found->first != preset.first))
      {
        return invalid("ter:PresetExist", "The requested name already exist for another preset");
      }
    }
    const PtzSample state = model_.sample(now);
    if (state.moving)
    {
      return fault(false, { "ter:Action", "ter:MovingPTZ" }, "Preset cannot be set while PTZ unit is moving");
    }
    if (found == presets_.end() && static_cast<int>(presets_.size()) >= config_.max_presets)
    {
      return fault(false, { "ter:Action", "ter:TooManyPresets" }, "Maximum number of Presets reached");
    }
    const int stored = found != presets_.end() ? found->first : next_preset_++;
    Preset& preset = presets_[stored];
    if (name_element != nullptr || preset.name.empty())
    {
      preset.name = name_element != nullptr ? name : formatText("Preset %d", stored);
    }
    preset.position = state.position;
    return respond(ns::PTZ, formatText("SetPresetResponse><PresetToken>%d</PresetToken></SetPresetResponse>", stored));
  }
  if (found == presets_.end())
  {
    return invalid("ter:NoToken", "The requested preset token does not exist");
  }
  if (operation == "GotoPreset")
  {
    goToAll(found->second.position, now);
  }
  else
  {
    presets_.erase(found);
  }
  return respond(ns::PTZ, operation + "Response></" + operation + "Response>");
}

}  // namespace ptz_action_server
