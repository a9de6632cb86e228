// The words of the VISCA settings (~visca/framing, ~visca/zoom_drive), as the plugin reads them.
#include "ptz_action_server/core/visca/visca_protocol.h"

namespace ptz_action_server
{
bool parseViscaFraming(const std::string& text, ViscaFraming& framing)
{
  if (text == "raw" || text == "sony_ip")
  {
    framing = text == "raw" ? ViscaFraming::RAW : ViscaFraming::SONY_IP;
    return true;
  }
  return false;
}

const char* toString(ViscaFraming framing)
{
  return framing == ViscaFraming::RAW ? "raw" : "sony_ip";
}

bool parseViscaZoomDrive(const std::string& text, ViscaZoomDrive& drive)
{
  for (ViscaZoomDrive candidate : { ViscaZoomDrive::AUTO, ViscaZoomDrive::VARIABLE, ViscaZoomDrive::STANDARD })
  {
    if (text == toString(candidate))
    {
      drive = candidate;
      return true;
    }
  }
  return false;
}

const char* toString(ViscaZoomDrive drive)
{
  switch (drive)
  {
    case ViscaZoomDrive::VARIABLE:
      return "variable";
    case ViscaZoomDrive::STANDARD:
      return "standard";
    default:
      return "auto";
  }
}

}  // namespace ptz_action_server
