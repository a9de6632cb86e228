/**
 * \file
 * \brief ONVIF PTZ (protocols.md section 7): the SOAP requests the backend sends, WS-Security UsernameToken
 * PasswordDigest, and readers for the replies it needs (clock, services, profiles, nodes and spaces, status).
 */
#pragma once

#include <string>

#include "ptz_action_server/core/onvif/onvif_xml.h"

namespace ptz_action_server
{
namespace onvif
{
constexpr const char* DEGREE_SPACE = "http://www.onvif.org/ver10/tptz/PanTiltSpaces/SphericalPositionSpaceDegrees";
constexpr const char* GENERIC_PAN_TILT_SPACE = "http://www.onvif.org/ver10/tptz/PanTiltSpaces/PositionGenericSpace";
constexpr const char* GENERIC_ZOOM_SPACE = "http://www.onvif.org/ver10/tptz/ZoomSpaces/PositionGenericSpace";
constexpr const char* GENERIC_PAN_TILT_VELOCITY = "http://www.onvif.org/ver10/tptz/PanTiltSpaces/VelocityGenericSpace";
constexpr const char* GENERIC_ZOOM_VELOCITY = "http://www.onvif.org/ver10/tptz/ZoomSpaces/VelocityGenericSpace";
constexpr const char* SOAP_CONTENT_TYPE = "application/soap+xml; charset=utf-8";

/// A WS-Security UsernameToken, made for one request.
struct UsernameToken
{
  std::string username;
  std::string nonce;    ///< raw bytes (Base64 in the message)
  std::string created;  ///< UTC in the camera's clock: "2026-11-21T10:20:30.123Z"
};

/// Base64(SHA-1(nonce + created + password)).
std::string passwordDigest(const std::string& nonce, const std::string& created, const std::string& password);
/// "YYYY-MM-DDTHH:MM:SS.mmmZ" of \p utc_seconds since the epoch.
std::string isoTime(double utc_seconds);
/// Reads "YYYY-MM-DDTHH:MM:SS[.fff]Z" into seconds since the epoch; false for anything else.
bool parseIsoTime(const std::string& text, double& utc_seconds);

/// The whole envelope of \p body (an element with the tds/trt/tptz/tt prefixes this codec declares); with a
/// wsse:Security header when \p token is given.
std::string envelope(const std::string& body, const UsernameToken* token = nullptr, const std::string& password = "");

/// Request bodies.
std::string getSystemDateAndTime();
std::string getCapabilities();
std::string getProfiles();
std::string getNodes();
std::string getConfigurationOptions(const std::string& configuration_token);
std::string getStatus(const std::string& profile);
/// A move in \p space (pan-tilt) and the generic zoom space; \p with_zoom false leaves the zoom out.
std::string absoluteMove(const std::string& profile, double x, double y, const char* space, bool with_zoom,
                         double zoom);
/// Generic velocities in [-1, 1]; \p timeout_seconds whole seconds (some cameras take no fractions).
std::string continuousMove(const std::string& profile, double x, double y, bool with_zoom, double zoom,
                           int timeout_seconds);
std::string stop(const std::string& profile);

/// What the bring-up learns.
struct ServicePaths
{
  std::string media;  ///< path of the media service ("/onvif/media_service")
  std::string ptz;    ///< path of the PTZ service
};
/// The profile the backend drives.
struct Profile
{
  std::string token;
  std::string ptz_configuration;  ///< token of its PTZConfiguration
  std::string node;               ///< token of its PTZ node
};
/// A range of one axis of a space.
struct Range
{
  double min = -1.0;
  double max = 1.0;
};
/// What a PTZ node supports.
struct Node
{
  bool degree_space = false;  ///< lists SphericalPositionSpaceDegrees
  Range degree_pan, degree_tilt;
  bool generic_space = false;
  bool zoom = false;  ///< lists the generic zoom position space
};
/// A GetStatus reply.
struct Status
{
  double x = 0.0, y = 0.0;  ///< pan-tilt position in \p space
  std::string space;        ///< "" when the camera leaves it out (the generic space)
  double zoom = 0.0;        ///< generic [0, 1]
  bool has_zoom = false;
  std::string move_status;  ///< of the pan-tilt: IDLE, MOVING, UNKNOWN ("" if not given)
};

/// Readers of a response element (SoapMessage::content); each returns "" or what is missing.
std::string readSystemTime(const Element* response, double& utc_seconds);
/// Keeps only the path of each XAddr (some firmware advertises a wrong host: the configured one is used).
std::string readCapabilities(const Element* response, ServicePaths& paths);
/// \p wanted "" takes the first profile with a PTZConfiguration.
std::string readProfiles(const Element* response, const std::string& wanted, Profile& profile);
std::string readNode(const Element* response, const std::string& token, Node& node);
/// The PTZTimeout range of GetConfigurationOptions (s); leaves \p min_s, \p max_s if absent.
std::string readTimeoutRange(const Element* response, double& min_s, double& max_s);
std::string readStatus(const Element* response, Status& status);

/// "PT5S" -> 5; "PT0.5S", "PT1M" also. False for anything else.
bool parseDuration(const std::string& text, double& seconds);

}  // namespace onvif
}  // namespace ptz_action_server
