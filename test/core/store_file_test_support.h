/**
 * \file
 * \brief A store's file (the presets, the tours) in a fresh temporary directory, for the stores' tests.
 */
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <system_error>
#include <vector>

namespace ptz_action_server
{
/// A fresh directory under the system's temporary directory, removed with its content at the end of the test, and
/// the store's file at \p relative_path in it (its directories not made).
class StoreFileTest : public ::testing::Test
{
protected:
  explicit StoreFileTest(std::string relative_path) : relative_path_(std::move(relative_path))
  {
  }
  void SetUp() override
  {
    std::string pattern = (std::filesystem::temp_directory_path() / "ptz_store_XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    directory_ = pattern;
    path_ = (directory_ / relative_path_).string();
  }
  void TearDown() override
  {
    std::error_code ignored;
    std::filesystem::remove_all(directory_, ignored);
  }
  std::string readFile() const
  {
    std::ifstream file(path_);
    std::stringstream text;
    text << file.rdbuf();
    return text.str();
  }
  /// Writes \p text as the store's file, making its directories.
  void writeFile(const std::string& text) const
  {
    std::filesystem::create_directories(std::filesystem::path(path_).parent_path());
    std::ofstream(path_) << text;
  }

  const std::string relative_path_;
  std::filesystem::path directory_;
  std::string path_;
};

}  // namespace ptz_action_server
