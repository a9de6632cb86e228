/**
 * \file
 * \brief Private to OnvifCameraEmulator, what its parts share: the services' paths and tokens, and the SOAP answers
 * and faults in the camera's own prefixes. onvif_camera_emulator.cpp is the camera (WS-Security, the device and media
 * services), onvif_camera_emulator_modes.cpp its modes, onvif_camera_emulator_ptz.cpp its PTZ service and
 * onvif_camera_emulator_moves.cpp how it moves, onvif_camera_emulator_imaging.cpp its Imaging service (focus, iris).
 */
#pragma once

#include <initializer_list>
#include <string>

#include "ptz_action_server/core/onvif/onvif_xml.h"
#include "ptz_action_server/emulators/http_camera_server.h"

namespace ptz_action_server
{
namespace onvif_emulator
{
constexpr const char* DEVICE_PATH = "/onvif/device_service";
constexpr const char* MEDIA_PATH = "/onvif/media_service";
constexpr const char* PTZ_PATH = "/onvif/ptz_service";
constexpr const char* IMAGING_PATH = "/onvif/imaging_service";
constexpr const char* CONTENT_TYPE = "application/soap+xml; charset=utf-8";
constexpr const char* PROFILE = "profile_1";  ///< the profile with PTZ
constexpr const char* PROFILE_WITHOUT_PTZ = "profile_0";
constexpr const char* CONFIGURATION = "ptz0";
constexpr const char* NODE = "node0";
constexpr const char* VIDEO_SOURCE = "video_source_0";

/// An answer in the camera's own prefixes: env for SOAP, a default namespace for the response's service.
HttpAnswer respond(const char* service, const std::string& content);
/// A SOAP fault: env:Sender (HTTP 400) or env:Receiver (HTTP 500), then the subcodes, outermost first.
HttpAnswer fault(bool sender, std::initializer_list<const char*> subcodes, const std::string& reason);
/// env:Sender / ter:InvalidArgVal / ter:\p what, as the PTZ service's argument faults are.
HttpAnswer invalid(const char* what, const std::string& reason);
/// env:Receiver / ter:ActionNotSupported.
HttpAnswer notSupported(const std::string& operation);

/// The pan-tilt part of a position or velocity vector read: x, y in \p space ("" for none given).
struct PanTiltArgument
{
  bool given = false;
  double x = 0.0, y = 0.0;
  std::string space;
  bool numbers = true;
};
PanTiltArgument panTiltOf(const onvif::Element* vector);

struct ZoomArgument
{
  bool given = false;
  double x = 0.0;
  std::string space;
  bool number = true;
};
ZoomArgument zoomOf(const onvif::Element* vector);

}  // namespace onvif_emulator
}  // namespace ptz_action_server
