#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

// The core must build and run without ROS: codecs, motion, validation and backends are plain C++.
TEST(CoreSources, IncludeNothingFromRos)
{
  const std::regex ros_include(
      R"(#\s*include\s*[<"](ros/|actionlib|tf2|tf2_ros/|pluginlib|diagnostic_updater|sensor_msgs|std_msgs|ptz_action_server/(Ptz|SetSimFaults)))");
  const std::filesystem::path root(PTZ_SOURCE_DIR);
  int files = 0;
  // The simulated camera's renderer too: plain C++ and OpenCV.
  for (const char* folder :
       { "include/ptz_action_server/core", "src/core", "include/ptz_action_server/render", "src/render" })
  {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / folder))
    {
      std::ifstream file(entry.path());
      std::string line;
      int number = 0;
      while (std::getline(file, line))
      {
        ++number;
        EXPECT_FALSE(std::regex_search(line, ros_include)) << entry.path() << ":" << number << ": " << line;
      }
      ++files;
    }
  }
  EXPECT_GT(files, 10);
}
