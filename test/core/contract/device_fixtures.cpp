#include "device_fixtures.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "device_fixtures_internal.h"

namespace ptz_action_server
{
std::string hex(const std::vector<std::uint8_t>& bytes)
{
  std::ostringstream text;
  for (std::uint8_t byte : bytes)
  {
    char digits[4];
    std::snprintf(digits, sizeof(digits), "%02X ", byte);
    text << digits;
  }
  return text.str();
}

std::string uniqueLink(const char* name)
{
  static int counter = 0;
  return ::testing::TempDir() + "ptz_" + name + "_" + std::to_string(::getpid()) + "_" + std::to_string(counter++);
}

std::vector<DeviceCommand> withoutQueries(const std::vector<DeviceCommand>& commands)
{
  std::vector<DeviceCommand> kept;
  std::copy_if(commands.begin(), commands.end(), std::back_inserter(kept),
               [](const DeviceCommand& command) { return command.kind != DeviceCommand::Kind::QUERY; });
  return kept;
}

std::string describe(const std::vector<DeviceCommand>& commands)
{
  std::string text;
  for (const DeviceCommand& command : commands)
  {
    text += (text.empty() ? "" : " | ") + command.text;
  }
  return text.empty() ? "(none)" : text;
}

bool DeviceFixture::ignoreAxis(Axis axis, bool ignore)
{
  SimFaults faults;
  faults.stalled[axis] = ignore;
  return setFaults(faults);
}

std::size_t DeviceFixture::holds(const std::vector<DeviceCommand>& commands, const AxisValues&) const
{
  return static_cast<std::size_t>(std::count_if(commands.begin(), commands.end(), [](const DeviceCommand& command) {
    return command.kind == DeviceCommand::Kind::STOP;
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
