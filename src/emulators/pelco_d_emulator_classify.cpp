#include "ptz_action_server/emulators/pelco_d_emulator.h"

namespace ptz_action_server
{
std::vector<ClassifiedCommand> PelcoDEmulator::classify() const
{
  using Kind = ClassifiedCommand::Kind;
  const double wire = pelco::FRAME_SIZE * port_->byteTime();
  return received_.classified([wire](const ReceivedFrame& item) {
    const std::uint8_t command = item.frame.command2;
    Kind kind = Kind::OTHER;  // a drive, a preset, the start-up's probe
    if (command == pelco::QUERY_PAN || command == pelco::QUERY_TILT || command == pelco::QUERY_ZOOM)
    {
      kind = Kind::QUERY;
    }
    else if (item.frame == pelco::stop(item.frame.address))
    {
      kind = Kind::STOP;
    }
    else if (command == pelco::SET_PAN || command == pelco::SET_TILT || command == pelco::SET_ZOOM)
    {
      kind = Kind::MOVE;
    }
    const pelco::Bytes bytes = pelco::encode(item.frame);
    return ClassifiedCommand{ item.at, kind, hexText(bytes.data(), bytes.size()), false, 0.0, wire };
  });
}

}  // namespace ptz_action_server
