/**
 * \file
 * \brief The ONVIF Imaging service (ver20/imaging/wsdl, prefix timg) for focus and iris: the requests
 * (GetImagingSettings, SetImagingSettings with Focus/AutoFocusMode and Exposure/Mode + Iris, GetOptions,
 * GetMoveOptions, Move with a continuous or absolute focus, Stop, GetStatus), the readers of their replies, and the
 * lens they declare.
 */
#pragma once

#include <string>

#include "ptz_action_server/core/lens.h"
#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/onvif/onvif_xml.h"

namespace ptz_action_server
{
namespace onvif
{
/// Request bodies (Imaging service). Each declares the timg prefix itself, so the envelope stays as it is; the
/// video source is the profile's VideoSourceConfiguration/SourceToken.
std::string getImagingSettings(const std::string& video_source);
std::string getImagingOptions(const std::string& video_source);
std::string getMoveOptions(const std::string& video_source);
std::string getImagingStatus(const std::string& video_source);
/// SetImagingSettings{Focus{AutoFocusMode AUTO|MANUAL}}.
std::string setFocusMode(const std::string& video_source, bool automatic);
/// SetImagingSettings{Exposure{Mode AUTO|MANUAL}}; with \p iris (dB, as GetOptions' Iris range) in MANUAL, the Iris
/// too (pass NaN for none).
std::string setExposure(const std::string& video_source, bool automatic, double iris);
/// Move{Focus{Continuous{Speed}}}, \p speed within GetMoveOptions' Continuous Speed range.
std::string moveFocusContinuous(const std::string& video_source, double speed);
/// Move{Focus{Absolute{Position}}}, within GetMoveOptions' Absolute Position range (no Speed: the camera's).
std::string moveFocusAbsolute(const std::string& video_source, double position);
std::string stopFocus(const std::string& video_source);

/// A FloatRange of the options; known when the camera lists it with Min <= Max.
struct FloatRange
{
  bool known = false;
  double min = 0.0;
  double max = 0.0;
};

/// What GetOptions and GetMoveOptions list for focus and iris.
struct ImagingOptions
{
  bool focus_auto = false;       ///< Focus/AutoFocusModes lists AUTO
  bool focus_manual = false;     ///< ... and MANUAL
  bool exposure_auto = false;    ///< Exposure/Mode lists AUTO
  bool exposure_manual = false;  ///< ... and MANUAL
  FloatRange iris;               ///< Exposure/Iris (dB: 0 fully open; the end farther from 0 the most closed)
  FloatRange focus_position;     ///< GetMoveOptions' Absolute/Position
  FloatRange focus_speed;        ///< GetMoveOptions' Continuous/Speed
};

/// The current settings (GetImagingSettings) and status (GetStatus) of the lens; what is absent stays unset.
struct ImagingReading
{
  LensMode focus_mode = LensMode::UNKNOWN;     ///< Focus/AutoFocusMode
  LensMode exposure_mode = LensMode::UNKNOWN;  ///< Exposure/Mode
  bool has_iris = false;
  double iris = 0.0;  ///< Exposure/Iris, dB
  bool has_focus = false;
  double focus = 0.0;       ///< FocusStatus20/Position
  std::string move_status;  ///< FocusStatus20/MoveStatus: IDLE, MOVING, UNKNOWN
};

/// Readers of a response element; each returns "" or what is wrong (a reply without the element it must carry).
std::string readImagingOptions(const Element* response, ImagingOptions& options);
/// Adds GetMoveOptions' focus ranges to \p options.
std::string readMoveOptions(const Element* response, ImagingOptions& options);
/// Modes and iris of a GetImagingSettingsResponse into \p reading (its focus position left as it is).
std::string readImagingSettings(const Element* response, ImagingReading& reading);
/// The focus position and move status of an Imaging GetStatusResponse into \p reading.
std::string readImagingStatus(const Element* response, ImagingReading& reading);

/// The share 0..1 of \p value in \p range (clamped); for the iris 1 is the end nearer 0 dB (fully open).
double focusShare(const FloatRange& range, double value);
double irisShare(const FloatRange& range, double value);
/// Their inverses: the camera's value of share \p share.
double focusValue(const FloatRange& range, double share);
double irisValue(const FloatRange& range, double share);

/// The lens that \p options and the first \p reading show: focus auto/manual where both modes are listed, velocity
/// with a Continuous speed range, position with an Absolute one, feedback where GetStatus reports a position within a
/// known range; iris auto/manual where Exposure/Mode lists both, position with an Iris range (in manual exposure),
/// feedback where the settings carry it; no iris velocity and no one-push: the Imaging service has no words for them.
LensCapabilities imagingLens(const ImagingOptions& options, const ImagingReading& reading);

}  // namespace onvif
}  // namespace ptz_action_server
