#include "ptz_action_server/core/pelco_d/pelco_d_protocol.h"

namespace ptz_action_server
{
LensCapabilities pelcoLens(const PelcoSettings& settings)
{
  LensCapabilities lens;
  const char* const speed_only = "Pelco-D drives it at the camera's own speed (only the sign of a velocity is sent); "
                                 "it has no position, no auto/manual switch and no feedback";
  lens.focus.present = lens.focus.velocity = settings.focus;
  lens.focus.limitation = settings.focus ? speed_only : "pelco_d/focus is false: this camera has no focus to drive";
  lens.iris.present = lens.iris.velocity = settings.iris;
  lens.iris.limitation = settings.iris ? speed_only : "pelco_d/iris is false: this camera has no iris to drive";
  return lens;
}

void PelcoProtocol::lens(const LensCommand& command)
{
  if (!session_.connected())
  {
    session_.lens().fault("the Pelco-D camera is not connected: " + describe(command) + " not sent");
    return;
  }
  if (command.kind != LensCommand::Kind::VELOCITY)
  {
    session_.lens().fault("Pelco-D takes no " + describe(command));  // the node checked: not reached
    return;
  }
  const int drive = command.value > 0.0 ? 1 : (command.value < 0.0 ? -1 : 0);
  (command.function == LensFunction::FOCUS ? focus_drive_ : iris_drive_) = drive;
  const pelco::Bytes bytes = pelco::encode(pelco::withLens(motion_, focus_drive_, iris_drive_));
  // Not tagged with the current command: Pelco-D has no refusals, and a lens frame is no goal's.
  channel_.queue(TransactionChannel::Request{ std::string(bytes.begin(), bytes.end()), COMMAND, settings_.general_reply,
                                              0, false });
}

}  // namespace ptz_action_server
