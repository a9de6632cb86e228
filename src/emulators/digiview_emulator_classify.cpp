#include "ptz_action_server/emulators/digiview_emulator.h"

namespace ptz_action_server
{
std::vector<ClassifiedCommand> DigiViewEmulator::classify() const
{
  using digiview::MessageType;
  using digiview::ParamType;
  using Kind = ClassifiedCommand::Kind;
  return received_.classified([](const ReceivedMessage& item) {
    if (item.error != digiview::UnpackError::NONE)
    {
      return ClassifiedCommand{ item.at, Kind::OTHER, std::string("unread: ") + digiview::toString(item.error) };
    }
    const digiview::Message& message = item.message;
    ClassifiedCommand command{ item.at, Kind::OTHER,
                               std::string(toString(message.message_type)) + " " + toString(message.param_type) };
    if (message.message_type == MessageType::GET_PARAMETERS || message.message_type == MessageType::GET_INTERVAL)
    {
      command.kind = Kind::QUERY;  // a state request, a subscription
    }
    // Where the view aims (a goal, a velocity goal's next aim, and the hold: DigiView has no stop). The optics (the
    // field of view) are other.
    else if (message.message_type == MessageType::SET_PARAMETERS && message.param_type == ParamType::CAM_TARGETING)
    {
      command.kind = Kind::MOVE;
      digiview::CamTargeting targeting;
      if (unpackTargeting(message, targeting) == digiview::UnpackError::NONE)
      {
        command.text += " yaw " + std::to_string(targeting.yaw) + " pitch " + std::to_string(targeting.pitch);
        command.aims = true;
        command.pan = targeting.yaw;
      }
    }
    return command;
  });
}

}  // namespace ptz_action_server
