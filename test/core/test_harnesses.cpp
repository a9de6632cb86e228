/**
 * \file
 * \brief The harnesses every protocol registers (cmake/protocols.cmake, HARNESS), as the benchmarks take them: each
 * starts its emulator, names the plugin whose protocol drives it, and gives the node that plugin's parameters.
 */
#include <gtest/gtest.h>

#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "harness/device_harness.h"

namespace ptz_action_server
{
namespace
{
TEST(Harnesses, EveryProtocolRegistersItsHarnessesUnderItsPluginsName)
{
  std::ifstream file(std::string(PTZ_SOURCE_DIR) + "/backend_plugins.xml");
  std::stringstream plugins;
  plugins << file.rdbuf();
  std::set<std::string> names;
  for (const HarnessEntry& entry : allHarnesses())
  {
    SCOPED_TRACE(entry.name);
    EXPECT_TRUE(names.insert(entry.name).second) << "named twice";
    EXPECT_NE(plugins.str().find("<class name=\"ptz_action_server/" + entry.plugin + "\""), std::string::npos)
        << "no plugin " << entry.plugin << " in backend_plugins.xml";
    for (const HarnessParam& param : entry.params)
    {
      EXPECT_EQ(param.name.rfind(entry.plugin + "/", 0), 0u) << param.name;
    }
    EXPECT_FALSE(entry.figures.summary.empty() || entry.figures.goal_items.empty() || entry.figures.stop_items.empty());
    ASSERT_TRUE(entry.start);
    const std::unique_ptr<DeviceHarness> harness = entry.start("");
    // The protocol's name() is its plugin's: the node's diagnostics and texts name the backend by it.
    EXPECT_EQ(harness->makeBackend()->name(), entry.plugin);
    EXPECT_TRUE(harness->port() != 0 || !harness->link().empty()) << "the backend cannot find the emulator";
    EXPECT_NE(harness->faults(), nullptr);
  }
  EXPECT_GE(names.size(), 8u);
}

}  // namespace
}  // namespace ptz_action_server
