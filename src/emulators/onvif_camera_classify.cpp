#include <cmath>
#include <optional>
#include <string>

#include "ptz_action_server/core/onvif/onvif_codec.h"
#include "ptz_action_server/core/onvif/onvif_xml.h"
#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/onvif_camera_emulator.h"

namespace ptz_action_server
{
std::vector<ClassifiedCommand> OnvifCameraEmulator::classify() const
{
  using Kind = ClassifiedCommand::Kind;
  return server_->received().classified([](const HttpExchange& exchange) -> std::optional<ClassifiedCommand> {
    onvif::SoapMessage message;
    // A request HTTP Digest challenged is not carried out (the same follows with its credentials); nor is one that is
    // no SOAP message.
    if (exchange.status == 401 || !onvif::parseSoap(exchange.body, message).empty())
    {
      return std::nullopt;
    }
    const std::string operation = onvif::localName(*message.content);
    Kind kind = operation == "GetStatus" ? Kind::QUERY : operation == "Stop" ? Kind::STOP : Kind::OTHER;
    bool aims = false;
    double pan = 0.0;
    if (operation == "AbsoluteMove")
    {
      kind = Kind::MOVE;
      const onvif::Element* pan_tilt =
          onvif::child(onvif::child(message.content, onvif::ns::PTZ, "Position"), onvif::ns::SCHEMA, "PanTilt");
      const char* space = onvif::attribute(pan_tilt, "space");
      aims = pan_tilt != nullptr;
      pan = aims ? std::stod(onvif::attribute(pan_tilt, "x")) : 0.0;
      pan = space != nullptr && std::string(space) == onvif::DEGREE_SPACE ? toRadians(pan) : pan * M_PI;
    }
    else if (operation == "ContinuousMove" || operation == "RelativeMove")
    {
      kind = Kind::MOVE;  // a velocity goal's, or one by an offset (also in the picture's TranslationSpaceFov)
    }
    return ClassifiedCommand{ exchange.at, kind, operation + " " + std::to_string(pan), aims, pan };
  });
}

}  // namespace ptz_action_server
