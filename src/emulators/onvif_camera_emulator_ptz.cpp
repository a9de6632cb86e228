#include <cmath>

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
constexpr double MOVING = 1e-6;  ///< rad/s (X/s) an axis moves faster than when MoveStatus says MOVING

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
    }
  }
  spaces += space("ContinuousPanTiltVelocitySpace", GENERIC_PAN_TILT_VELOCITY, -1, 1, -1, 1) +
            space("ContinuousZoomVelocitySpace", GENERIC_ZOOM_VELOCITY, -1, 1);
  if (config_.absolute)
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

void OnvifCameraEmulator::goToAll(const AxisValues& position, TimePoint now)
{
  velocity_axes_ = {};
  approach_.fill(std::numeric_limits<double>::quiet_NaN());
  for (Axis axis : ALL_AXES)
  {
    driving_[axis] = true;
    model_.goToAxis(axis, position[axis], now);
  }
}

void OnvifCameraEmulator::goToPanTilt(Axis axis, double target, TimePoint now)
{
  velocity_axes_[axis] = false;
  driving_[axis] = true;
  if (config_.backlash <= 0.0)
  {
    approach_[axis] = std::numeric_limits<double>::quiet_NaN();
    model_.goToAxis(axis, target, now);
    return;
  }
  // It takes up its gears' backlash: to the point below the target first, then up to it (advance()), even when it
  // stands there already.
  const AxisRange& travel = config_.device.axes[axis].range;
  approach_[axis] = std::clamp(target, travel.min, travel.max);
  model_.goToAxis(axis, std::max(travel.min, approach_[axis] - config_.backlash), now);
}

void OnvifCameraEmulator::moveAxis(Axis axis, double x, TimePoint now)
{
  const double max_speed = config_.device.axes[axis].motion.max_speed;
  // A camera that ignores the magnitude moves at its one speed for any velocity but 0.
  const double speed = config_.fixed_speed_share > 0.0 && x != 0.0 ? std::copysign(config_.fixed_speed_share, x) : x;
  approach_[axis] = std::numeric_limits<double>::quiet_NaN();
  velocity_axes_[axis] = true;
  driving_[axis] = speed != 0.0;
  model_.moveAxisAtVelocity(axis, speed * max_speed, now);
}

void OnvifCameraEmulator::advance(TimePoint now) const
{
  if (now >= velocity_until_ && !config_.stop_keeps_moving)  // those cameras go on past their Timeout too
  {
    for (Axis axis : ALL_AXES)
    {
      if (velocity_axes_[axis])
      {
        velocity_axes_[axis] = false;
        driving_[axis] = false;
        model_.moveAxisAtVelocity(axis, 0.0, velocity_until_);  // the ContinuousMove's Timeout ran out
      }
    }
  }
  const PtzSample state = model_.sample(now);
  for (Axis axis : { PAN, TILT })
  {
    const double below = std::max(config_.device.axes[axis].range.min, approach_[axis] - config_.backlash);
    if (!std::isnan(approach_[axis]) && std::abs(state.position[axis] - below) < 1e-9 &&
        std::abs(state.velocity[axis]) <= MOVING)
    {
      model_.goToAxis(axis, approach_[axis], now);  // below the target: now up to it
      approach_[axis] = std::numeric_limits<double>::quiet_NaN();
    }
  }
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

HttpAnswer OnvifCameraEmulator::move(const std::string& operation, const Element* request, TimePoint now)
{
  if (operation == "GetStatus")
  {
    const PtzSample state = model_.sample(now);
    std::array<bool, AXIS_COUNT> moves{};
    for (Axis axis : ALL_AXES)
    {
      // A blocked axis (a stall fault) does not move, but the camera still drives it: MOVING, as a real one says.
      moves[axis] = std::abs(state.velocity[axis]) > MOVING || (driving_[axis] && model_.faults().stalled[axis]);
    }
    const bool pan_tilt_moves = moves[PAN] || moves[TILT];
    const bool zoom_moves = moves[ZOOM];
    return respond(ns::PTZ, "GetStatusResponse><PTZStatus>" +
                                (config_.status_position ? positionVector("Position", state.position) : std::string()) +
                                "<sch:MoveStatus><sch:PanTilt>" + (pan_tilt_moves ? "MOVING" : "IDLE") +
                                "</sch:PanTilt><sch:Zoom>" + (zoom_moves ? "MOVING" : "IDLE") +
                                "</sch:Zoom></sch:MoveStatus><sch:UtcTime>" + isoTime(cameraUtc()) +
                                "</sch:UtcTime></PTZStatus></GetStatusResponse>");
  }
  if (operation == "Stop")
  {
    const std::string pan_tilt = text(child(request, ns::PTZ, "PanTilt"));
    const std::string zoom = text(child(request, ns::PTZ, "Zoom"));
    const bool stop_pan_tilt = pan_tilt != "false" && pan_tilt != "0";  // both default to true
    const bool stop_zoom = zoom != "false" && zoom != "0";
    for (Axis axis : ALL_AXES)
    {
      // A camera that keeps moving after Stop goes on at its ContinuousMove's speed (a position move does stop).
      if ((axis == ZOOM ? stop_zoom : stop_pan_tilt) && !(config_.stop_keeps_moving && velocity_axes_[axis]))
      {
        velocity_axes_[axis] = false;
        driving_[axis] = false;
        approach_[axis] = std::numeric_limits<double>::quiet_NaN();
        model_.moveAxisAtVelocity(axis, 0.0, now);
      }
    }
    return respond(ns::PTZ, "StopResponse></StopResponse>");
  }
  if (operation == "ContinuousMove")
  {
    const Element* velocity = child(request, ns::PTZ, "Velocity");
    const PanTiltArgument pan_tilt = panTiltOf(velocity);
    const ZoomArgument zoom = zoomOf(velocity);
    double timeout = 5.0;  // DefaultPTZTimeout
    const Element* timeout_element = child(request, ns::PTZ, "Timeout");
    if ((pan_tilt.given && !pan_tilt.space.empty() && pan_tilt.space != GENERIC_PAN_TILT_VELOCITY) ||
        (zoom.given && !zoom.space.empty() && zoom.space != GENERIC_ZOOM_VELOCITY))
    {
      return invalid("ter:SpaceNotSupported", "A space is referenced which is not supported by the PTZ node");
    }
    if (!pan_tilt.numbers || !zoom.number || std::abs(pan_tilt.x) > 1 || std::abs(pan_tilt.y) > 1 ||
        std::abs(zoom.x) > 1)
    {
      return invalid("ter:InvalidVelocity", "The requested speed is out of bounds");
    }
    if (timeout_element != nullptr && (!parseDuration(text(timeout_element), timeout) ||
                                       timeout < config_.min_timeout || timeout > config_.max_timeout))
    {
      return invalid("ter:TimeoutNotSupported", "The specified timeout argument is not within the supported timeout "
                                                "range");
    }
    // An axis left out goes on as it was; one at 0 stops.
    if (pan_tilt.given)
    {
      moveAxis(PAN, pan_tilt.x, now);
      moveAxis(TILT, pan_tilt.y, now);
    }
    if (zoom.given)
    {
      moveAxis(ZOOM, zoom.x, now);
    }
    velocity_until_ = addSeconds(now, timeout);
    return respond(ns::PTZ, "ContinuousMoveResponse></ContinuousMoveResponse>");
  }
  if (!config_.absolute)
  {
    return notSupported(operation);  // the continuous-only cameras: no positions, so no presets or home either
  }
  if (operation == "AbsoluteMove" || operation == "RelativeMove")
  {
    const bool absolute = operation == "AbsoluteMove";
    if ((absolute && config_.refuse_absolute_move) || (!absolute && !config_.relative))
    {
      return notSupported(operation);
    }
    const Element* argument = child(request, ns::PTZ, absolute ? "Position" : "Translation");
    PanTiltArgument pan_tilt = panTiltOf(argument);
    ZoomArgument zoom = zoomOf(argument);
    if (pan_tilt.space.empty())
    {
      pan_tilt.space = absolute ? defaultSpace() : GENERIC_PAN_TILT_TRANSLATION;
    }
    if (zoom.space.empty())
    {
      zoom.space = absolute ? GENERIC_ZOOM_SPACE : GENERIC_ZOOM_TRANSLATION;
    }
    const bool degrees = pan_tilt.space == (absolute ? DEGREE_SPACE : DEGREE_TRANSLATION);
    const bool generic = pan_tilt.space == (absolute ? GENERIC_PAN_TILT_SPACE : GENERIC_PAN_TILT_TRANSLATION);
    if ((pan_tilt.given && !(generic || (degrees && config_.degree_space))) ||
        (zoom.given && zoom.space != (absolute ? GENERIC_ZOOM_SPACE : GENERIC_ZOOM_TRANSLATION)))
    {
      return invalid("ter:SpaceNotSupported", "A space is referenced that is not supported by the PTZ node");
    }
    // The camera's own ranges, whatever GetNodes lists (generic: the whole travel; degrees: its mechanics).
    const double limit_x = degrees ? (absolute ? 180.0 : 360.0) : (absolute ? 1.0 : 2.0);
    const double limit_y = degrees ? (absolute ? 90.0 : 180.0) : (absolute ? 1.0 : 2.0);
    const bool zoom_in_range = absolute ? zoom.x >= 0.0 && zoom.x <= 1.0 : std::abs(zoom.x) <= 1.0;
    if (!pan_tilt.numbers || !zoom.number || std::abs(pan_tilt.x) > limit_x || std::abs(pan_tilt.y) > limit_y ||
        !zoom_in_range)
    {
      return absolute ? invalid("ter:InvalidPosition", "The requested position is out of bounds") :
                        invalid("ter:InvalidTranslation", "The requested translation is out of bounds");
    }
    if (absolute && config_.absolute_never_moves)
    {
      return respond(ns::PTZ, "AbsoluteMoveResponse></AbsoluteMoveResponse>");  // answered, and nothing moves
    }
    const AxisValues at = model_.sample(now).position;
    if (pan_tilt.given)
    {
      const double pan = degrees ? toRadians(pan_tilt.x) : pan_tilt.x * M_PI;
      const double tilt = degrees ? toRadians(pan_tilt.y) : pan_tilt.y * M_PI / 2.0;
      // A translation beyond the travel stops at its border.
      const AxisRange& pan_travel = config_.device.axes[PAN].range;
      const AxisRange& tilt_travel = config_.device.axes[TILT].range;
      goToPanTilt(PAN, std::clamp(absolute ? pan : at[PAN] + pan, pan_travel.min, pan_travel.max), now);
      goToPanTilt(TILT, std::clamp(absolute ? tilt : at[TILT] + tilt, tilt_travel.min, tilt_travel.max), now);
    }
    if (zoom.given)
    {
      // The lens stops where it really ends (honoured_zoom), whatever the move asked: the model clamps.
      const double z = absolute ? zoom.x : std::log(at[ZOOM]) / std::log(zoomMax()) + zoom.x;
      velocity_axes_[ZOOM] = false;
      driving_[ZOOM] = true;
      model_.goToAxis(ZOOM, std::pow(zoomMax(), std::clamp(z, 0.0, 1.0)), now);
    }
    return respond(ns::PTZ, operation + "Response></" + operation + "Response>");
  }
  if (operation == "GotoHomePosition" || operation == "SetHomePosition")
  {
    if (!config_.home)
    {
      return notSupported(operation);
    }
    if (operation == "SetHomePosition")
    {
      home_ = model_.sample(now).position;
    }
    else
    {
      goToAll(home_, now);
    }
    return respond(ns::PTZ, operation + "Response></" + operation + "Response>");
  }
  return notSupported(operation);
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
