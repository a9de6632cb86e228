#include "ptz_action_server/core/axis/axis_protocol.h"

namespace ptz_action_server
{
void AxisProtocol::lens(const LensCommand& command)
{
  const std::string arguments = vapix::lensArguments(command, lens_limits_);
  if (arguments.empty())
  {
    session_.lens().fault("VAPIX has no words for " + describe(command));  // the node checked: not reached
    return;
  }
  if (!haveControl())
  {
    session_.lens().fault(withoutControl());
    return;
  }
  std::string problem;
  vapix::Reply reply;
  if (!request(arguments, reply, problem))
  {
    session_.lens().fault(problem.empty() ? "'" + arguments + "' not sent: the link was lost" : problem);
    return;
  }
  if (command.kind == LensCommand::Kind::MODE)
  {
    session_.lens().setMode(command.function, command.automatic() ? LensMode::AUTO : LensMode::MANUAL);
  }
}

void AxisProtocol::reportLens(const vapix::LensReading& reading)
{
  LensReport& report = session_.lens();
  if (reading.autofocus)
  {
    report.setMode(LensFunction::FOCUS, *reading.autofocus ? LensMode::AUTO : LensMode::MANUAL);
  }
  if (reading.autoiris)
  {
    report.setMode(LensFunction::IRIS, *reading.autoiris ? LensMode::AUTO : LensMode::MANUAL);
  }
  if (reading.focus && lens_limits_.focus.known)
  {
    report.setPosition(LensFunction::FOCUS, lens_limits_.focus.toShare(*reading.focus));
  }
  if (reading.iris && lens_limits_.iris.known)
  {
    report.setPosition(LensFunction::IRIS, lens_limits_.iris.toShare(*reading.iris));
  }
}

}  // namespace ptz_action_server
