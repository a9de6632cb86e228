#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "ptz_action_server/core/presets/preset_store.h"
#include "store_file_test_support.h"

using namespace ptz_action_server;

namespace
{
namespace fs = std::filesystem;

const AxisValues HOME_POSE{ { 0.25, -0.125, 2.0 } };

class PresetStoreTest : public StoreFileTest
{
protected:
  PresetStoreTest() : StoreFileTest("presets.yaml")
  {
  }
  /// Names of the files in the directory, to find stray temporary files.
  std::vector<std::string> files() const
  {
    std::vector<std::string> names;
    for (const auto& entry : fs::directory_iterator(directory_))
    {
      names.push_back(entry.path().filename().string());
    }
    return names;
  }
};

TEST_F(PresetStoreTest, MissingFileMeansNoPresetsButHome)
{
  PresetStore store(path_, HOME_POSE);
  EXPECT_EQ(store.load(), "");
  ASSERT_EQ(store.list().size(), 1u);
  EXPECT_EQ(store.list()[0].first, "home");
  EXPECT_EQ(store.find("home"), HOME_POSE);
  EXPECT_FALSE(store.find("door"));
  EXPECT_FALSE(fs::exists(path_));
}

TEST_F(PresetStoreTest, SavedPresetsReadBackExactlyByAnotherStore)
{
  PresetStore store(path_, HOME_POSE);
  ASSERT_EQ(store.load(), "");
  const AxisValues door{ { 0.1, -0.7853981633974483, 3.5 } };
  const AxisValues odd{ { -3.0000000000000004, 1e-17, 1.0 } };
  EXPECT_EQ(store.save("door", door), "");
  EXPECT_EQ(store.save("a: b #c 'd' \"e\"", odd), "");
  EXPECT_EQ(store.save("Gate 2", door), "");
  EXPECT_EQ(store.save("Gate 2", odd), "");  // replaces

  PresetStore restarted(path_, { { 0.0, 0.0, 1.0 } });
  ASSERT_EQ(restarted.load(), "") << readFile();
  EXPECT_EQ(restarted.find("door"), door);
  EXPECT_EQ(restarted.find("a: b #c 'd' \"e\""), odd);
  EXPECT_EQ(restarted.find("Gate 2"), odd);
  const std::vector<NamedPose> list = restarted.list();
  ASSERT_EQ(list.size(), 4u);
  EXPECT_EQ(list[0].first, "home");
  EXPECT_EQ(list[1].first, "Gate 2");
  EXPECT_EQ(list[2].first, "a: b #c 'd' \"e\"");
  EXPECT_EQ(list[3].first, "door");
}

TEST_F(PresetStoreTest, DeleteRemovesFromFile)
{
  PresetStore store(path_, HOME_POSE);
  ASSERT_EQ(store.load(), "");
  ASSERT_EQ(store.save("door", HOME_POSE), "");
  ASSERT_EQ(store.save("gate", HOME_POSE), "");
  EXPECT_EQ(store.remove("door"), "");
  EXPECT_EQ(store.remove("door"), "no preset named 'door'");
  EXPECT_FALSE(store.find("door"));

  PresetStore restarted(path_, HOME_POSE);
  ASSERT_EQ(restarted.load(), "");
  EXPECT_FALSE(restarted.find("door"));
  EXPECT_TRUE(restarted.find("gate"));
}

TEST_F(PresetStoreTest, WritesLeaveNoTemporaryFile)
{
  PresetStore store(path_, HOME_POSE);
  ASSERT_EQ(store.load(), "");
  for (int i = 0; i < 5; ++i)
  {
    ASSERT_EQ(store.save("p" + std::to_string(i), HOME_POSE), "");
  }
  ASSERT_EQ(store.remove("p0"), "");
  EXPECT_EQ(files(), std::vector<std::string>{ "presets.yaml" });
}

TEST_F(PresetStoreTest, CreatesTheDirectory)
{
  path_ = (directory_ / "a" / "b" / "presets.yaml").string();
  PresetStore store(path_, HOME_POSE);
  ASSERT_EQ(store.load(), "");
  EXPECT_EQ(store.save("door", HOME_POSE), "");
  EXPECT_TRUE(fs::is_regular_file(path_));
}

TEST_F(PresetStoreTest, FailedWriteChangesNothing)
{
  PresetStore store(path_, HOME_POSE);
  ASSERT_EQ(store.load(), "");
  // The target becomes a directory that is not empty: the rename fails after the temporary file was written.
  fs::create_directories(fs::path(path_) / "inside");
  EXPECT_NE(store.save("door", HOME_POSE).find("cannot rename"), std::string::npos);
  EXPECT_FALSE(store.find("door"));
  EXPECT_EQ(files(), std::vector<std::string>{ "presets.yaml" });
}

TEST_F(PresetStoreTest, MalformedFileIsReportedKeptAndNeverOverwritten)
{
  const std::vector<std::string> malformed = {
    "presets: {door: {pan: 0.1, tilt: 0.2}",                      // broken YAML
    "presets: {door: {pan: 0.1, tilt: 0.2}}\n",                   // no zoom
    "presets: {door: {pan: x, tilt: 0.2, zoom: 1}}\n",            // not a number
    "presets: {door: {pan: .nan, tilt: 0.2, zoom: 1}}\n",         // not finite
    "presets: {home: {pan: 0, tilt: 0, zoom: 1}}\n",              // home is not a file preset
    "presets: {door: {pan: 0, tilt: 0, zoom: 1, focus: 3}}\n",    // an unknown field would be lost
    "presets: {door: {pan: 0, tilt: 0, zoom: 1}}\nversion: 2\n",  // an unknown key would be lost
    "- door\n",                                                   // not a map
    "presets: [door]\n",                                          // not a map of poses
  };
  for (const std::string& text : malformed)
  {
    SCOPED_TRACE(text);
    writeFile(text);
    PresetStore store(path_, HOME_POSE);
    const std::string reason = store.load();
    EXPECT_NE(reason.find(path_), std::string::npos) << reason;
    EXPECT_EQ(store.loadError(), reason);
    EXPECT_EQ(store.list().size(), 1u);
    EXPECT_EQ(store.find("home"), HOME_POSE);
    EXPECT_NE(store.save("gate", HOME_POSE).find("read-only"), std::string::npos);
    EXPECT_NE(store.remove("door").find("read-only"), std::string::npos);
    EXPECT_FALSE(store.find("gate"));
    EXPECT_EQ(readFile(), text);
    EXPECT_EQ(files(), std::vector<std::string>{ "presets.yaml" });
  }
}

TEST_F(PresetStoreTest, HandWrittenFileIsRead)
{
  writeFile("# mine\npresets:\n  door:\n    pan: 1\n    tilt: -0.5\n    zoom: 4.5\n");
  PresetStore store(path_, HOME_POSE);
  ASSERT_EQ(store.load(), "");
  EXPECT_EQ(store.find("door"), (AxisValues{ { 1.0, -0.5, 4.5 } }));
}

TEST_F(PresetStoreTest, EmptyFileHoldsNoPresets)
{
  writeFile("");
  PresetStore store(path_, HOME_POSE);
  EXPECT_EQ(store.load(), "");
  EXPECT_EQ(store.save("door", HOME_POSE), "");
}

TEST_F(PresetStoreTest, HomeIsNeitherSavedNorDeleted)
{
  PresetStore store(path_, HOME_POSE);
  ASSERT_EQ(store.load(), "");
  EXPECT_NE(store.save("home", { { 1.0, 1.0, 1.0 } }).find("predefined"), std::string::npos);
  EXPECT_NE(store.remove("home").find("predefined"), std::string::npos);
  EXPECT_EQ(store.find("home"), HOME_POSE);
  EXPECT_FALSE(fs::exists(path_));
}

TEST_F(PresetStoreTest, NamesAreChecked)
{
  EXPECT_EQ(PresetStore::checkName("door"), "");
  EXPECT_EQ(PresetStore::checkName("Gate 2: left"), "");
  EXPECT_EQ(PresetStore::checkName(std::string(64, 'x')), "");
  EXPECT_NE(PresetStore::checkName(""), "");
  EXPECT_NE(PresetStore::checkName(std::string(65, 'x')), "");
  EXPECT_NE(PresetStore::checkName("tab\there"), "");
  EXPECT_NE(PresetStore::checkName("new\nline"), "");
  EXPECT_NE(PresetStore::checkName("caf\xc3\xa9"), "");
  EXPECT_NE(PresetStore::checkName(" door"), "");
  EXPECT_NE(PresetStore::checkName("door "), "");
  EXPECT_NE(PresetStore::checkName("home"), "");

  PresetStore store(path_, HOME_POSE);
  ASSERT_EQ(store.load(), "");
  EXPECT_EQ(store.save("", HOME_POSE), "the name is empty");
  EXPECT_NE(store.save("door", { { 0.0, NAN, 1.0 } }), "");
  EXPECT_EQ(store.list().size(), 1u);
}

}  // namespace
