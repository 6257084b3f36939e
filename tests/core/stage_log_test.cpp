// core/stage_log.hpp: the stages a command ran, each listed once in the order first recorded, echoed when verbose.
#include "core/stage_log.hpp"

#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

namespace rollspin {
namespace {

// The one log every test shares, emptied and quiet before and after each test.
struct StageLogTest : ::testing::Test {
  StageLog& log = StageLog::instance();
  void SetUp() override {
    log.clear();
    log.setEcho(false);
  }
  void TearDown() override {
    log.clear();
    log.setEcho(false);
  }
};

TEST_F(StageLogTest, EveryCallReachesTheSameLog) {
  StageLog::instance().record("scene");
  EXPECT_EQ(&StageLog::instance(), &log);
  EXPECT_EQ(log.stages(), std::vector<std::string>{"scene"});
}

TEST_F(StageLogTest, ListsEachStageOnceInTheOrderFirstRecorded) {
  for (const char* stage : {"scene", "solver", "gl-context", "solver", "shadow-map", "scene", "shadow-map"})
    log.record(stage);
  EXPECT_EQ(log.stages(), (std::vector<std::string>{"scene", "solver", "gl-context", "shadow-map"}));
}

TEST_F(StageLogTest, ClearEmptiesTheListSoAStageCountsAgain) {
  log.record("encoder");
  log.clear();
  EXPECT_TRUE(log.stages().empty());
  log.record("font");
  log.record("encoder");
  EXPECT_EQ(log.stages(), (std::vector<std::string>{"font", "encoder"}));
}

// A view into a longer text: the stage is the view's characters, listed and echoed.
TEST_F(StageLogTest, AStageIsTheViewsCharactersOnly) {
  const std::string text = "gltf-keys,gltf-write";
  log.setEcho(true);
  ::testing::internal::CaptureStderr();
  log.record(std::string_view(text).substr(0, 9));
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "rollspin: stage: gltf-keys\n");
  EXPECT_EQ(log.stages(), std::vector<std::string>{"gltf-keys"});
}

TEST_F(StageLogTest, EchoesEachNewStageOnStderrOnlyWhenVerbose) {
  ::testing::internal::CaptureStderr();
  log.record("scene");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");

  log.setEcho(true);
  EXPECT_TRUE(log.echo());
  ::testing::internal::CaptureStderr();
  log.record("scene");  // already listed: not said again
  log.record("gl-context");
  log.record("gl-context");
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "rollspin: stage: gl-context\n");
  EXPECT_EQ(log.stages(), (std::vector<std::string>{"scene", "gl-context"}));
}

}  // namespace
}  // namespace rollspin
