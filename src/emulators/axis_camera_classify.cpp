#include <optional>
#include <string>

#include "ptz_action_server/core/units.h"
#include "ptz_action_server/emulators/axis_camera_emulator.h"

namespace ptz_action_server
{
std::vector<ClassifiedCommand> AxisCameraEmulator::classify() const
{
  using Kind = ClassifiedCommand::Kind;
  const double pan_max_speed = config_.device.axes[PAN].motion.max_speed;  // at speed=100
  return server_->received().classified(
      [pan_max_speed](const HttpExchange& exchange) -> std::optional<ClassifiedCommand> {
        if (exchange.status == 401)
        {
          return std::nullopt;  // challenged, not carried out: the same request follows with its credentials
        }
        const std::string& target = exchange.target;
        ClassifiedCommand command{ exchange.at, Kind::OTHER, exchange.method + " " + target };
        if (target.find("query=") != std::string::npos)
        {
          command.kind = Kind::QUERY;
        }
        else if (target.find("move=stop") != std::string::npos)
        {
          command.kind = Kind::STOP;
        }
        else if (target.find("&pan=") != std::string::npos)
        {
          command.kind = Kind::MOVE;
          command.aims = true;
          command.pan = toRadians(std::stod(target.substr(target.find("&pan=") + 5)));
          const std::size_t speed = target.find("&speed=");
          if (speed != std::string::npos)
          {
            command.pan_speed = pan_max_speed * std::stod(target.substr(speed + 7)) / 100.0;
          }
        }
        else if (target.find("continuouspantiltmove=") != std::string::npos ||
                 target.find("continuouszoommove=") != std::string::npos)
        {
          command.kind = Kind::MOVE;  // a velocity goal's
        }
        else if (target.find("center=") != std::string::npos || target.find("areazoom=") != std::string::npos)
        {
          command.kind = Kind::MOVE;  // a point of its picture: where it goes is the camera's to know
        }
        return command;
      });
}

}  // namespace ptz_action_server
