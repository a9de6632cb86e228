#include "ptz_action_server/emulators/pantilt_emulator.h"

namespace ptz_action_server
{
std::vector<ClassifiedCommand> PanTiltEmulator::classify() const
{
  using namespace cr::pantilt;
  using Kind = ClassifiedCommand::Kind;
  const WireFormat format = config_.format;
  const double pan_max_speed = config_.device.axes[PAN].motion.max_speed;  // at 100 %
  return received_.classified([format, pan_max_speed](const ReceivedDatagram& datagram) {
    Kind kind = Kind::OTHER;  // a restart, or what does not decode
    double pan_speed = 0.0;
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
      // The pan's motor speed, in % of its max speed: the speed of the next move.
      if (decoded == 1 && (param == PanTiltParam::PAN_MOTOR_SPEED || param == PanTiltParam::PAN_TILT_MOTOR_SPEED))
      {
        pan_speed = value / 100.0 * pan_max_speed;
      }
    }
    ClassifiedCommand classified{ datagram.at, kind, hexText(datagram.bytes.data(), datagram.bytes.size()) };
    classified.pan_speed = pan_speed;
    return classified;
  });
}

}  // namespace ptz_action_server
