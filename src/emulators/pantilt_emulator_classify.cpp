#include "ptz_action_server/emulators/pantilt_emulator.h"

namespace ptz_action_server
{
std::vector<ClassifiedCommand> PanTiltEmulator::classify() const
{
  using namespace cr::pantilt;
  using Kind = ClassifiedCommand::Kind;
  const WireFormat format = config_.format;
  return received_.classified([format](const ReceivedDatagram& datagram) {
    Kind kind = Kind::OTHER;  // a restart, or what does not decode
    if (!datagram.bytes.empty() && datagram.bytes[0] == PARAMS_HEADER)
    {
      kind = Kind::QUERY;  // a state request
    }
    else
    {
      PanTiltParam param{};
      PanTiltCommand command{};
      float value = 0.0f;
      const int decoded = PanTilt::decodeCommand(datagram.bytes.data(), static_cast<int>(datagram.bytes.size()), param,
                                                 command, value, format);
      if (decoded == 0 && command == PanTiltCommand::STOP)
      {
        kind = Kind::STOP;
      }
      // Every parameter a client sets moves an axis or says how fast (angles, positions, speeds).
      else if (decoded == 1 || (decoded == 0 && command != PanTiltCommand::RESTART))
      {
        kind = Kind::MOVE;
      }
    }
    return ClassifiedCommand{ datagram.at, kind, hexText(datagram.bytes.data(), datagram.bytes.size()) };
  });
}

}  // namespace ptz_action_server
