#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "ptz_action_server/core/tours/tour_store.h"
#include "store_file_test_support.h"

using namespace ptz_action_server;

namespace
{
namespace fs = std::filesystem;

class TourStoreTest : public StoreFileTest
{
protected:
  TourStoreTest() : StoreFileTest("sub/tours.yaml")
  {
  }
};

const Tour GATE_ROUND{ "gate round", { { "gate", 10.0, 0.5 }, { "yard", 0.1, 0.0 }, { "home", 2.5, 1.0 } } };

TEST_F(TourStoreTest, SavedToursReadBackExactlyByAnotherStoreInOrder)
{
  TourStore store(path_);
  EXPECT_EQ(store.load(), "");
  EXPECT_TRUE(store.list().empty());
  ASSERT_EQ(store.save(GATE_ROUND), "");
  ASSERT_EQ(store.save({ "short", { { "door", 1.0 / 3.0, 0.0 } } }), "");

  TourStore again(path_);
  ASSERT_EQ(again.load(), "");
  const std::optional<Tour> read = again.find("gate round");
  ASSERT_TRUE(read);
  ASSERT_EQ(read->stops.size(), 3U);
  for (std::size_t index = 0; index < 3; ++index)
  {
    EXPECT_EQ(read->stops[index].preset, GATE_ROUND.stops[index].preset);
    EXPECT_EQ(read->stops[index].dwell, GATE_ROUND.stops[index].dwell);
    EXPECT_EQ(read->stops[index].speed, GATE_ROUND.stops[index].speed);
  }
  EXPECT_EQ(again.find("short")->stops[0].dwell, 1.0 / 3.0);
  ASSERT_EQ(again.list().size(), 2U);
  EXPECT_EQ(again.list()[0].name, "gate round");

  ASSERT_EQ(again.remove("gate round"), "");
  EXPECT_NE(again.remove("gate round"), "");
  TourStore third(path_);
  ASSERT_EQ(third.load(), "");
  EXPECT_FALSE(third.find("gate round"));
  EXPECT_TRUE(third.find("short"));
  // Only the file: no temporary file left beside it.
  EXPECT_EQ(std::distance(fs::directory_iterator(fs::path(path_).parent_path()), fs::directory_iterator()), 1);
}

TEST_F(TourStoreTest, HandWrittenFileIsRead)
{
  writeFile("tours:\n  patrol:\n    - {preset: a, dwell: 5}\n    - preset: b\n      speed: 0.25\n");
  TourStore store(path_);
  ASSERT_EQ(store.load(), "");
  const std::optional<Tour> patrol = store.find("patrol");
  ASSERT_TRUE(patrol);
  ASSERT_EQ(patrol->stops.size(), 2U);
  EXPECT_EQ(patrol->stops[0].dwell, 5.0);
  EXPECT_EQ(patrol->stops[0].speed, 0.0);
  EXPECT_EQ(patrol->stops[1].dwell, 0.0);
  EXPECT_EQ(patrol->stops[1].speed, 0.25);
}

TEST_F(TourStoreTest, MalformedFileIsReportedKeptAndNeverOverwritten)
{
  const std::string bad = "tours:\n  patrol:\n    - {preset: a, dwell: -1}\n";
  writeFile(bad);
  TourStore store(path_);
  const std::string reason = store.load();
  EXPECT_NE(reason.find("tour 'patrol'"), std::string::npos) << reason;
  EXPECT_NE(reason.find("dwell"), std::string::npos) << reason;
  EXPECT_NE(store.save(GATE_ROUND).find("read-only"), std::string::npos);
  EXPECT_EQ(readFile(), bad);

  for (const std::string& text :
       { std::string("presets: {}\n"), std::string("tours: [a]\n"), std::string("tours:\n  p: {preset: a}\n"),
         std::string("tours:\n  p:\n    - {preset: a, wait: 3}\n"), std::string("tours:\n  p:\n    - {dwell: 3}\n"),
         std::string("tours:\n  p:\n    - {preset: a, speed: fast}\n"), std::string("tours:\n  p: [\n") })
  {
    std::map<std::string, Tour> tours;
    EXPECT_NE(parseTours(text, tours), "") << text;
  }
}

TEST_F(TourStoreTest, ToursAreChecked)
{
  TourStore store(path_);
  ASSERT_EQ(store.load(), "");
  EXPECT_NE(store.save({ "", { { "a", 1.0, 0.0 } } }), "");
  EXPECT_NE(store.save({ " a", { { "a", 1.0, 0.0 } } }), "");
  EXPECT_NE(store.save({ std::string(65, 'x'), { { "a", 1.0, 0.0 } } }), "");
  EXPECT_NE(store.save({ "empty", {} }), "");
  EXPECT_NE(store.save({ "t", { { "", 1.0, 0.0 } } }), "");
  EXPECT_NE(store.save({ "t", { { "a", std::nan(""), 0.0 } } }), "");
  EXPECT_NE(store.save({ "t", { { "a", 1.0, 1.5 } } }), "");
  EXPECT_NE(store.save({ "t", { { "a", 1.0, -0.1 } } }), "");
  EXPECT_NE(store.save({ "t", std::vector<TourStop>(TourLimits::MAX_STOPS + 1, { "a", 1.0, 0.0 }) }), "");
  EXPECT_TRUE(store.list().empty());
  EXPECT_FALSE(fs::exists(path_));  // nothing refused was written
}

}  // namespace
