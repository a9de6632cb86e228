/**
 * \file
 * \brief The ONVIF requests: the SOAP envelope (with its WS-Security header) and the operations' bodies, in the
 * tds/trt/tptz/tt prefixes it declares. The replies are onvif_codec.cpp's.
 */
#include <string>

#include "ptz_action_server/core/http/crypto.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/onvif/onvif_xml.h"
#include "ptz_action_server/core/text.h"

namespace ptz_action_server
{
namespace onvif
{
namespace
{
/// The tt:PanTilt / tt:Zoom elements of \p vector (a space attribute only when it names one).
std::string vectorElements(const Vector& vector)
{
  std::string body;
  if (vector.pan_tilt)
  {
    body += formatText("<tt:PanTilt x=\"%.6f\" y=\"%.6f\"", vector.x, vector.y);
    body += vector.pan_tilt_space.empty() ? "/>" : " space=\"" + escaped(vector.pan_tilt_space) + "\"/>";
  }
  if (vector.zoom)
  {
    body += formatText("<tt:Zoom x=\"%.6f\"", vector.z);
    body += vector.zoom_space.empty() ? "/>" : " space=\"" + escaped(vector.zoom_space) + "\"/>";
  }
  return body;
}

std::string profileOnly(const char* operation, const std::string& profile)
{
  return std::string("<tptz:") + operation + "><tptz:ProfileToken>" + escaped(profile) +
         "</tptz:ProfileToken></tptz:" + operation + ">";
}
}  // namespace

std::string envelope(const std::string& body, const UsernameToken* token, const std::string& password)
{
  std::string xml = std::string("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<s:Envelope xmlns:s=\"") + ns::SOAP +
                    "\" xmlns:tds=\"" + ns::DEVICE + "\" xmlns:trt=\"" + ns::MEDIA + "\" xmlns:tptz=\"" + ns::PTZ +
                    "\" xmlns:tt=\"" + ns::SCHEMA + "\">";
  if (token != nullptr)
  {
    xml += std::string("<s:Header><wsse:Security s:mustUnderstand=\"1\" xmlns:wsse=\"") + ns::WSSE + "\" xmlns:wsu=\"" +
           ns::WSU + "\"><wsse:UsernameToken><wsse:Username>" + escaped(token->username) +
           "</wsse:Username><wsse:Password Type=\"http://docs.oasis-open.org/wss/2004/01/"
           "oasis-200401-wss-username-token-profile-1.0#PasswordDigest\">" +
           passwordDigest(token->nonce, token->created, password) +
           "</wsse:Password><wsse:Nonce EncodingType=\"http://docs.oasis-open.org/wss/2004/01/"
           "oasis-200401-wss-soap-message-security-1.0#Base64Binary\">" +
           base64Encode(token->nonce) + "</wsse:Nonce><wsu:Created>" + token->created +
           "</wsu:Created></wsse:UsernameToken></wsse:Security></s:Header>";
  }
  return xml + "<s:Body>" + body + "</s:Body></s:Envelope>";
}

std::string getSystemDateAndTime()
{
  return "<tds:GetSystemDateAndTime/>";
}

std::string getCapabilities()
{
  return "<tds:GetCapabilities><tds:Category>All</tds:Category></tds:GetCapabilities>";
}

std::string getServices(bool include_capability)
{
  return std::string("<tds:GetServices><tds:IncludeCapability>") + (include_capability ? "true" : "false") +
         "</tds:IncludeCapability></tds:GetServices>";
}

std::string getProfiles()
{
  return "<trt:GetProfiles/>";
}

std::string getVideoSources()
{
  return "<trt:GetVideoSources/>";
}

std::string getNodes()
{
  return "<tptz:GetNodes/>";
}

std::string getConfigurations()
{
  return "<tptz:GetConfigurations/>";
}

std::string getConfiguration(const std::string& configuration_token)
{
  return "<tptz:GetConfiguration><tptz:PTZConfigurationToken>" + escaped(configuration_token) +
         "</tptz:PTZConfigurationToken></tptz:GetConfiguration>";
}

std::string getConfigurationOptions(const std::string& configuration_token)
{
  return "<tptz:GetConfigurationOptions><tptz:ConfigurationToken>" + escaped(configuration_token) +
         "</tptz:ConfigurationToken></tptz:GetConfigurationOptions>";
}

std::string getStatus(const std::string& profile)
{
  return profileOnly("GetStatus", profile);
}

std::string absoluteMove(const std::string& profile, const Vector& position)
{
  return absoluteMove(profile, position, Vector());
}

std::string absoluteMove(const std::string& profile, const Vector& position, const Vector& speed)
{
  const std::string speed_elements = vectorElements(speed);
  return "<tptz:AbsoluteMove><tptz:ProfileToken>" + escaped(profile) + "</tptz:ProfileToken><tptz:Position>" +
         vectorElements(position) + "</tptz:Position>" +
         (speed_elements.empty() ? "" : "<tptz:Speed>" + speed_elements + "</tptz:Speed>") + "</tptz:AbsoluteMove>";
}

std::string absoluteMove(const std::string& profile, double x, double y, const char* space, bool with_zoom, double zoom)
{
  return absoluteMove(profile, Vector::of(true, x, y, space, with_zoom, zoom, GENERIC_ZOOM_SPACE));
}

std::string relativeMove(const std::string& profile, const Vector& translation)
{
  return "<tptz:RelativeMove><tptz:ProfileToken>" + escaped(profile) + "</tptz:ProfileToken><tptz:Translation>" +
         vectorElements(translation) + "</tptz:Translation></tptz:RelativeMove>";
}

std::string continuousMove(const std::string& profile, double x, double y, bool with_zoom, double zoom,
                           double timeout_seconds, bool with_pan_tilt)
{
  const Vector velocity =
      Vector::of(with_pan_tilt, x, y, GENERIC_PAN_TILT_VELOCITY, with_zoom, zoom, GENERIC_ZOOM_VELOCITY);
  return "<tptz:ContinuousMove><tptz:ProfileToken>" + escaped(profile) + "</tptz:ProfileToken><tptz:Velocity>" +
         vectorElements(velocity) +
         formatText("</tptz:Velocity><tptz:Timeout>PT%gS</tptz:Timeout></tptz:ContinuousMove>", timeout_seconds);
}

std::string stop(const std::string& profile)
{
  return "<tptz:Stop><tptz:ProfileToken>" + escaped(profile) +
         "</tptz:ProfileToken><tptz:PanTilt>true</tptz:PanTilt><tptz:Zoom>true</tptz:Zoom></tptz:Stop>";
}

std::string getPresets(const std::string& profile)
{
  return profileOnly("GetPresets", profile);
}

std::string setPreset(const std::string& profile, const std::string& name, const std::string& preset_token)
{
  return "<tptz:SetPreset><tptz:ProfileToken>" + escaped(profile) + "</tptz:ProfileToken>" +
         (name.empty() ? "" : "<tptz:PresetName>" + escaped(name) + "</tptz:PresetName>") +
         (preset_token.empty() ? "" : "<tptz:PresetToken>" + escaped(preset_token) + "</tptz:PresetToken>") +
         "</tptz:SetPreset>";
}

std::string gotoPreset(const std::string& profile, const std::string& preset_token)
{
  return "<tptz:GotoPreset><tptz:ProfileToken>" + escaped(profile) + "</tptz:ProfileToken><tptz:PresetToken>" +
         escaped(preset_token) + "</tptz:PresetToken></tptz:GotoPreset>";
}

std::string removePreset(const std::string& profile, const std::string& preset_token)
{
  return "<tptz:RemovePreset><tptz:ProfileToken>" + escaped(profile) + "</tptz:ProfileToken><tptz:PresetToken>" +
         escaped(preset_token) + "</tptz:PresetToken></tptz:RemovePreset>";
}

std::string gotoHomePosition(const std::string& profile)
{
  return profileOnly("GotoHomePosition", profile);
}

std::string setHomePosition(const std::string& profile)
{
  return profileOnly("SetHomePosition", profile);
}

}  // namespace onvif
}  // namespace ptz_action_server
