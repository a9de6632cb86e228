#include "ptz_action_server/emulators/flir_ptu_emulator.h"

#include <cmath>
#include <cstdlib>

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
  const double resolution = resolution_rad_;
  return received_.classified([byte_time, resolution](const ReceivedCommand& command) {
    // Each command crossed the line with its delimiter.
    ClassifiedCommand classified{ command.at, flirCommandKind(command.text),        command.text, false,
                                  0.0,        (command.text.size() + 1) * byte_time };
    // `PS<n>`: the pan's speed in positions a second (of the move in CI mode, the velocity in CV mode).
    if (command.text.size() > 2 && command.text.compare(0, 2, "PS") == 0)
    {
      classified.pan_speed = std::abs(std::atof(command.text.c_str() + 2)) * resolution;
    }
    return classified;
  });
}

}  // namespace ptz_action_server
