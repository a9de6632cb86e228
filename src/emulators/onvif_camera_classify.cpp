#include <cmath>
#include <cstdlib>
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
  const double pan_max_speed = config_.device.axes[PAN].motion.max_speed;  // at a Speed's PanTilt x = 1
  const bool speed_space = config_.speed_space;
  return server_->received().classified([=](const HttpExchange& exchange) -> std::optional<ClassifiedCommand> {
    onvif::SoapMessage message;
    // A request HTTP Digest challenged is not carried out (the same follows with its credentials); nor is one that is
    // no SOAP message.
    if (exchange.status == 401 || !onvif::parseSoap(exchange.body, message).empty())
    {
      return std::nullopt;
    }
    const std::string operation = onvif::localName(*message.content);
    Kind kind = operation == "GetStatus" ? Kind::QUERY : operation == "Stop" ? Kind::STOP : Kind::OTHER;
    if (onvif::namespaceOf(*message.content) == onvif::ns::IMAGING)
    {
      // The lens: its readings are questions about the device; its commands move no axis (a focus Stop is no stop).
      kind = operation.compare(0, 3, "Get") == 0 ? Kind::QUERY : Kind::OTHER;
      return ClassifiedCommand{ exchange.at, kind, "Imaging " + operation, false, 0.0 };
    }
    bool aims = false;
    double pan = 0.0;
    double pan_speed = 0.0;
    if (operation == "AbsoluteMove")
    {
      kind = Kind::MOVE;
      const onvif::Element* pan_tilt =
          onvif::child(onvif::child(message.content, onvif::ns::PTZ, "Position"), onvif::ns::SCHEMA, "PanTilt");
      const char* space = onvif::attribute(pan_tilt, "space");
      aims = pan_tilt != nullptr;
      pan = aims ? std::stod(onvif::attribute(pan_tilt, "x")) : 0.0;
      pan = space != nullptr && std::string(space) == onvif::DEGREE_SPACE ? toRadians(pan) : pan * M_PI;
      // The Speed's PanTilt x: the pan's share of its top speed, as a camera that lists the speed space reads it.
      const char* speed = onvif::attribute(
          onvif::child(onvif::child(message.content, onvif::ns::PTZ, "Speed"), onvif::ns::SCHEMA, "PanTilt"), "x");
      pan_speed = speed != nullptr && speed_space ? pan_max_speed * std::atof(speed) : 0.0;
    }
    else if (operation == "ContinuousMove" || operation == "RelativeMove")
    {
      kind = Kind::MOVE;  // a velocity goal's, or one by an offset (also in the picture's TranslationSpaceFov)
    }
    ClassifiedCommand command{ exchange.at, kind, operation + " " + std::to_string(pan), aims, pan };
    command.pan_speed = pan_speed;
    return command;
  });
}

}  // namespace ptz_action_server
