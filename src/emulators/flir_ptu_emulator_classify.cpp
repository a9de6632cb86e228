#include "ptz_action_server/emulators/flir_ptu_emulator.h"

namespace ptz_action_server
{
namespace
{
using Kind = ClassifiedCommand::Kind;

/// A halt; a question (an axis letter and a setting's letter without a value: PP, TP, PR, PN, PU, ...); a command
/// that moves an axis or says how it moves (a position, an offset or a speed with its value, the control mode CI or
/// CV); anything else is set-up (FT, ED, R, ...).
Kind flirCommandKind(const std::string& text)
{
  if (text == "H" || text == "HP" || text == "HT")
  {
    return Kind::STOP;
  }
  if (text == "CI" || text == "CV")
  {
    return Kind::MOVE;
  }
  const bool axis = text.size() >= 2 && (text[0] == 'P' || text[0] == 'T');
  if (axis && text.size() == 2)
  {
    return Kind::QUERY;
  }
  if (axis && (text[1] == 'P' || text[1] == 'O' || text[1] == 'S'))
  {
    return Kind::MOVE;
  }
  return Kind::OTHER;
}
}  // namespace

std::vector<ClassifiedCommand> FlirPtuEmulator::classify() const
{
  const double byte_time = port_->byteTime();
  return received_.classified([byte_time](const ReceivedCommand& command) {
    // Each command crossed the line with its delimiter.
    return ClassifiedCommand{ command.at, flirCommandKind(command.text),        command.text, false,
                              0.0,        (command.text.size() + 1) * byte_time };
  });
}

}  // namespace ptz_action_server
