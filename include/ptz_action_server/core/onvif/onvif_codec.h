/**
 * \file
 * \brief ONVIF PTZ (protocols.md section 7): the SOAP requests a client sends, WS-Security UsernameToken
 * PasswordDigest, and readers for the replies (clock, services, profiles, nodes and their spaces, presets, status),
 * by the element names of the ONVIF device, media and PTZ WSDLs (ver10/device, ver10/media, ver20/ptz).
 */
#pragma once

#include <string>
#include <vector>

#include "ptz_action_server/core/onvif/onvif_xml.h"

namespace ptz_action_server
{
namespace onvif
{
/// The spaces of the PTZ service specification ("Predefined PTZ spaces").
constexpr const char* DEGREE_SPACE = "http://www.onvif.org/ver10/tptz/PanTiltSpaces/SphericalPositionSpaceDegrees";
constexpr const char* GENERIC_PAN_TILT_SPACE = "http://www.onvif.org/ver10/tptz/PanTiltSpaces/PositionGenericSpace";
constexpr const char* GENERIC_ZOOM_SPACE = "http://www.onvif.org/ver10/tptz/ZoomSpaces/PositionGenericSpace";
constexpr const char* GENERIC_PAN_TILT_VELOCITY = "http://www.onvif.org/ver10/tptz/PanTiltSpaces/VelocityGenericSpace";
constexpr const char* GENERIC_ZOOM_VELOCITY = "http://www.onvif.org/ver10/tptz/ZoomSpaces/VelocityGenericSpace";
constexpr const char* GENERIC_PAN_TILT_TRANSLATION = "http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                                                     "TranslationGenericSpace";
constexpr const char* DEGREE_TRANSLATION = "http://www.onvif.org/ver10/tptz/PanTiltSpaces/"
                                           "SphericalTranslationSpaceDegrees";
constexpr const char* GENERIC_ZOOM_TRANSLATION = "http://www.onvif.org/ver10/tptz/ZoomSpaces/TranslationGenericSpace";
/// The PTZ specification's annex "Additional PTZ spaces": a translation in the current field of view, origin at the
/// picture's centre, (1, 1) its upper right corner; what clients such as Frigate centre a point of the picture with.
constexpr const char* FOV_PAN_TILT_TRANSLATION = "http://www.onvif.org/ver10/tptz/PanTiltSpaces/TranslationSpaceFov";
/// Its zoom counterpart (PTZ specification 25.12): the magnification relative to the current view (2: half the field
/// of view; range 0..INF, below 1 zooms out).
constexpr const char* FOV_ZOOM_TRANSLATION = "http://www.onvif.org/ver10/tptz/ZoomSpaces/TranslationSpaceFov";
constexpr const char* GENERIC_PAN_TILT_SPEED = "http://www.onvif.org/ver10/tptz/PanTiltSpaces/GenericSpeedSpace";
constexpr const char* GENERIC_ZOOM_SPEED = "http://www.onvif.org/ver10/tptz/ZoomSpaces/ZoomGenericSpeedSpace";
constexpr const char* SOAP_CONTENT_TYPE = "application/soap+xml; charset=utf-8";

/// The last part of a space URI, for messages ("PositionGenericSpace"); the whole text if it has no '/'.
std::string spaceName(const std::string& uri);

/// A WS-Security UsernameToken, made for one request.
struct UsernameToken
{
  std::string username;
  std::string nonce;    ///< raw bytes (Base64 in the message)
  std::string created;  ///< UTC in the camera's clock: "2026-11-21T10:20:30.123Z"
};

/// A token for one request of \p username: a fresh 16-byte nonce from randomBytes() (never repeated, never
/// guessable), and \p created.
UsernameToken newUsernameToken(const std::string& username, const std::string& created);
/// Base64(SHA-1(nonce + created + password)).
std::string passwordDigest(const std::string& nonce, const std::string& created, const std::string& password);
/// "YYYY-MM-DDTHH:MM:SS.mmmZ" of \p utc_seconds since the epoch.
std::string isoTime(double utc_seconds);
/// Reads any xsd:dateTime ("2010-09-16T07:50:45.25Z", "...+00:00" as python-onvif-zeep stamps it, "...-05:30", a
/// time without a zone as UTC, 24:00:00) into seconds since the epoch (UTC); false for anything else.
bool parseIsoTime(const std::string& text, double& utc_seconds);

/// The whole envelope of \p body (an element with the tds/trt/tptz/tt prefixes this codec declares); with a
/// wsse:Security header when \p token is given.
std::string envelope(const std::string& body, const UsernameToken* token = nullptr, const std::string& password = "");

/// One axis (or both) of a PTZVector in a request: pan-tilt x, y and zoom x, each with its space ("" leaves the
/// space out: the camera takes the PTZ configuration's default space).
struct Vector
{
  bool pan_tilt = false;
  double x = 0.0, y = 0.0;
  std::string pan_tilt_space;
  bool zoom = false;
  double z = 0.0;
  std::string zoom_space;

  /// Pan-tilt \p x, \p y in \p space (left out unless \p with_pan_tilt), zoom \p z in \p z_space (unless
  /// \p with_zoom).
  static Vector of(bool with_pan_tilt, double x, double y, const char* space, bool with_zoom, double z,
                   const char* z_space)
  {
    return Vector{ with_pan_tilt, x, y, space, with_zoom, z, z_space };
  }
};

/// Request bodies (device service).
std::string getSystemDateAndTime();
std::string getCapabilities();
std::string getServices(bool include_capability);
/// Request bodies (media service).
std::string getProfiles();
std::string getVideoSources();
/// Request bodies (PTZ service).
std::string getNodes();
std::string getConfigurations();
std::string getConfiguration(const std::string& configuration_token);
std::string getConfigurationOptions(const std::string& configuration_token);
std::string getStatus(const std::string& profile);
/// AbsoluteMove{ProfileToken, Position}: only the parts \p position has.
std::string absoluteMove(const std::string& profile, const Vector& position);
/// AbsoluteMove{ProfileToken, Position, Speed}: the Speed's parts \p speed has (none: no Speed element, the camera's
/// default speed), e.g. PanTilt x, y and Zoom x in GenericSpeedSpace / ZoomGenericSpeedSpace, shares 0..1 of the top
/// speed.
std::string absoluteMove(const std::string& profile, const Vector& position, const Vector& speed);
/// The usual AbsoluteMove: pan-tilt in \p space, and the generic zoom when \p with_zoom.
std::string absoluteMove(const std::string& profile, double x, double y, const char* space, bool with_zoom,
                         double zoom);
/// RelativeMove{ProfileToken, Translation}.
std::string relativeMove(const std::string& profile, const Vector& translation);
/// Generic velocities in [-1, 1]; \p timeout_seconds as given ("PT2S", "PT0.5S": whole seconds where the camera's
/// range allows, as some cameras take no fractions). \p with_pan_tilt false leaves the pan-tilt out (it goes on as it
/// was), \p with_zoom false the zoom.
std::string continuousMove(const std::string& profile, double x, double y, bool with_zoom, double zoom,
                           double timeout_seconds, bool with_pan_tilt = true);
std::string stop(const std::string& profile);
std::string getPresets(const std::string& profile);
/// SetPreset: a new preset when \p preset_token is "", else that one overwritten; \p name "" leaves it out.
std::string setPreset(const std::string& profile, const std::string& name, const std::string& preset_token = "");
std::string gotoPreset(const std::string& profile, const std::string& preset_token);
std::string removePreset(const std::string& profile, const std::string& preset_token);
std::string gotoHomePosition(const std::string& profile);
std::string setHomePosition(const std::string& profile);

/// What the bring-up learns.
struct ServicePaths
{
  std::string media;    ///< path of the media service ("/onvif/media_service")
  std::string ptz;      ///< path of the PTZ service
  std::string imaging;  ///< path of the Imaging service (focus, iris), "" when the camera lists none
};
/// The profile the backend drives, and the default spaces of its PTZConfiguration.
struct Profile
{
  std::string token;
  std::string ptz_configuration;  ///< token of its PTZConfiguration
  std::string node;               ///< token of its PTZ node
  /// DefaultAbsolutePantTiltPositionSpace (the schema's spelling): the space of GetStatus and of moves that name
  /// none; "" when the configuration declares none.
  std::string default_pan_tilt_space;
  std::string default_zoom_space;  ///< DefaultAbsoluteZoomPositionSpace, or ""
  /// VideoSourceConfiguration/SourceToken: the video source the Imaging service's requests name ("" if none)
  std::string video_source;
};
/// A range of one axis of a space. The specification writes an unbounded one as -INF / INF.
struct Range
{
  double min = -1.0;
  double max = 1.0;

  bool contains(double value, double tolerance = 0.0) const
  {
    return value >= min - tolerance && value <= max + tolerance;
  }
};
/// A space a PTZ node lists, with its ranges (y only for pan-tilt spaces).
struct Space
{
  std::string uri;
  Range x, y;
};
/// The space \p uri in \p spaces, or nullptr.
const Space* findSpace(const std::vector<Space>& spaces, const std::string& uri);
/// What a PTZ node supports (SupportedPTZSpaces, MaximumNumberOfPresets, HomeSupported).
struct Node
{
  std::string token;
  std::vector<Space> absolute_pan_tilt;    ///< AbsolutePanTiltPositionSpace
  std::vector<Space> absolute_zoom;        ///< AbsoluteZoomPositionSpace
  std::vector<Space> relative_pan_tilt;    ///< RelativePanTiltTranslationSpace
  std::vector<Space> relative_zoom;        ///< RelativeZoomTranslationSpace
  std::vector<Space> continuous_pan_tilt;  ///< ContinuousPanTiltVelocitySpace
  std::vector<Space> continuous_zoom;      ///< ContinuousZoomVelocitySpace
  std::vector<Space> pan_tilt_speed;       ///< PanTiltSpeedSpace (one-dimensional: x only)
  std::vector<Space> zoom_speed;           ///< ZoomSpeedSpace
  int max_presets = 0;                     ///< MaximumNumberOfPresets (0 when absent)
  bool home_supported = false;             ///< HomeSupported
};
/// A GetStatus reply. The specification makes Position and MoveStatus optional (capabilities StatusPosition and
/// MoveStatus): what is absent is false / "".
struct Status
{
  bool has_pan_tilt = false;
  double x = 0.0, y = 0.0;  ///< pan-tilt position in \p space
  std::string space;        ///< "" when the camera leaves it out (then it is the configuration's default)
  bool has_zoom = false;
  double zoom = 0.0;
  std::string zoom_space;        ///< "" when left out
  std::string move_status;       ///< MoveStatus/PanTilt: IDLE, MOVING, UNKNOWN ("" if not given)
  std::string zoom_move_status;  ///< MoveStatus/Zoom
  std::string error;             ///< Error, if any
};
/// A preset as GetPresets lists it.
struct Preset
{
  std::string token;
  std::string name;
  Status position;  ///< PTZPosition, read as a status position (has_pan_tilt / has_zoom)
};

/// Readers of a response element (SoapMessage::content); each returns "" or what is missing.
std::string readSystemTime(const Element* response, double& utc_seconds);
/// Keeps only the path of each XAddr (some firmware advertises a wrong host: the configured one is used); the Imaging
/// XAddr is optional.
std::string readCapabilities(const Element* response, ServicePaths& paths);
/// The media and PTZ paths of a GetServicesResponse (by each Service's Namespace).
std::string readServices(const Element* response, ServicePaths& paths);
/// \p wanted "" takes the first profile with a PTZConfiguration.
std::string readProfiles(const Element* response, const std::string& wanted, Profile& profile);
/// \p token "" takes the first node.
std::string readNode(const Element* response, const std::string& token, Node& node);
/// The PTZTimeout range of GetConfigurationOptions (s); leaves \p min_s, \p max_s if absent.
std::string readTimeoutRange(const Element* response, double& min_s, double& max_s);
/// The translation spaces GetConfigurationOptions' Spaces list (where the TranslationSpaceFov is advertised), into
/// \p spaces' relative_pan_tilt and relative_zoom; the rest of \p spaces is left as it is.
std::string readOptionSpaces(const Element* response, Node& spaces);
std::string readStatus(const Element* response, Status& status);
std::string readPresets(const Element* response, std::vector<Preset>& presets);
/// The PresetToken of a SetPresetResponse.
std::string readPresetToken(const Element* response, std::string& token);

/// "PT5S" -> 5; "PT0.5S", "PT1M" also. False for anything else.
bool parseDuration(const std::string& text, double& seconds);

}  // namespace onvif
}  // namespace ptz_action_server
