#include "ptz_action_server/emulators/visca_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = ClassifiedCommand::Kind;

/// The pan-tilt drive's stop (`8x 01 06 01 VV WW 03 03 FF`).
bool isPanTiltHalt(const visca::Packet& packet)
{
  return packet.size() == 9 && packet[2] == 0x06 && packet[3] == 0x01 && packet[6] == 0x03 && packet[7] == 0x03;
}

/// An inquiry; the halt; a command that moves the pan-tilt (absolute, relative, a drive) or the zoom (direct, a
/// drive); anything else (the broadcasts, IF_Clear, a cancel, the zoom's stop, which goes with a halt) is other.
Kind viscaPacketKind(const visca::Packet& packet)
{
  if (packet.size() <= 3 || packet[0] == visca::BROADCAST)
  {
    return Kind::OTHER;
  }
  if (packet[1] == 0x09)
  {
    return Kind::QUERY;
  }
  if (packet[1] != 0x01)
  {
    return Kind::OTHER;
  }
  if (isPanTiltHalt(packet))
  {
    return Kind::STOP;
  }
  const bool pan_tilt = packet[2] == 0x06 && (packet[3] == 0x01 || packet[3] == 0x02 || packet[3] == 0x03);
  const bool zoom =
      packet[2] == 0x04 && (packet[3] == 0x47 || (packet[3] == 0x07 && packet.size() > 4 && packet[4] != 0));
  return pan_tilt || zoom ? Kind::MOVE : Kind::OTHER;
}
}  // namespace

std::vector<ClassifiedCommand> ViscaEmulator::classify() const
{
  const double byte_time = port_->byteTime();
  const visca::ViscaModel& model = config_.model;
  return received_.classified([byte_time, &model](const ReceivedPacket& item) {
    // A VISCA over IP control message (a sequence reset) is no camera command.
    const Kind kind = item.control ? Kind::OTHER : viscaPacketKind(item.packet);
    ClassifiedCommand command{ item.at, kind, hexText(item.packet.data(), item.packet.size()),
                               false,   0.0,  item.packet.size() * byte_time };
    // The pan-tilt absolute or relative move's pan speed byte VV (`8x 01 06 02 VV WW ...`).
    const visca::Packet& packet = item.packet;
    if (kind == Kind::MOVE && packet.size() > 5 && packet[2] == 0x06 && (packet[3] == 0x02 || packet[3] == 0x03))
    {
      command.pan_speed = model.speedOfByte(PAN, packet[4]);
    }
    return command;
  });
}

}  // namespace ptz_action_server
