#include "ptz_action_server/core/visca/visca_protocol.h"

#include "visca_protocol_internal.h"

namespace ptz_action_server
{
void ViscaProtocol::lens(const LensCommand& command)
{
  if (!session_.connected() || !set_up_)
  {
    session_.lens().fault("the VISCA camera is not connected: " + describe(command) + " not sent");
    return;
  }
  const std::vector<visca::Packet> packets =
      visca::lensPackets(settings_.address, settings_.lens, command, session_.lens().state());
  for (const visca::Packet& packet : packets)
  {
    // Not tagged with the current command: a refused focus command is no fault of the goal running.
    channel_.queue(TransactionChannel::Request{ bytesOf(packet), LENS, true, 0, false });
  }
  if (command.kind == LensCommand::Kind::MODE)
  {
    session_.lens().setMode(command.function, command.automatic() ? LensMode::AUTO : LensMode::MANUAL);
  }
  else
  {
    session_.lens().setMode(command.function, LensMode::MANUAL);  // lensPackets() switched it to manual first
  }
}

}  // namespace ptz_action_server
