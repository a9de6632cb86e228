#include "device_fixtures.h"

#include <algorithm>

#include "device_fixtures_internal.h"

namespace ptz_action_server
{
std::vector<ClassifiedCommand> withoutQueries(const std::vector<ClassifiedCommand>& commands)
{
  std::vector<ClassifiedCommand> kept;
  std::copy_if(commands.begin(), commands.end(), std::back_inserter(kept),
               [](const ClassifiedCommand& command) { return command.kind != ClassifiedCommand::Kind::QUERY; });
  return kept;
}

std::vector<std::string> texts(const std::vector<ClassifiedCommand>& commands)
{
  std::vector<std::string> result;
  std::transform(commands.begin(), commands.end(), std::back_inserter(result),
                 [](const ClassifiedCommand& command) { return command.text; });
  return result;
}

std::string transportLossWords(const DeviceHarness& harness, const std::string& silence_words)
{
  if (!harness.link().empty())
  {
    return harness.link();
  }
  return harness.breaksAtOnce() ? "connection to 127.0.0.1" : silence_words;
}

std::string describe(const std::vector<ClassifiedCommand>& commands)
{
  std::string text;
  for (const ClassifiedCommand& command : commands)
  {
    text += (text.empty() ? "" : " | ") + command.text;
  }
  return text.empty() ? "(none)" : text;
}

void DeviceFixture::ignoreAxis(Axis axis, bool ignore)
{
  SimFaults faults;
  faults.stalled[axis] = ignore;
  harness().setFaults(faults);
}

std::size_t DeviceFixture::holds(const std::vector<ClassifiedCommand>& commands, const AxisValues&) const
{
  return static_cast<std::size_t>(std::count_if(commands.begin(), commands.end(), [](const ClassifiedCommand& command) {
    return command.kind == ClassifiedCommand::Kind::STOP;
  }));
}

namespace
{
std::vector<FixtureMaker>& registeredFixtures()
{
  static std::vector<FixtureMaker> fixtures;  // built at first use: registrations run during static initialisation
  return fixtures;
}
}  // namespace

DeviceFixtureRegistration::DeviceFixtureRegistration(std::vector<FixtureMaker> fixtures)
{
  std::vector<FixtureMaker>& all = registeredFixtures();
  all.insert(all.end(), std::make_move_iterator(fixtures.begin()), std::make_move_iterator(fixtures.end()));
}

std::vector<FixtureMaker> allDeviceFixtures()
{
  std::vector<FixtureMaker> fixtures = registeredFixtures();
  // By name: the order of static initialisation is the linker's.
  std::sort(fixtures.begin(), fixtures.end(),
            [](const FixtureMaker& a, const FixtureMaker& b) { return a.name < b.name; });
  return fixtures;
}

}  // namespace ptz_action_server
