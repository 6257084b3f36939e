// jobs/flag_overrides.hpp: a flag that stands for a scene key (--width, a
// --quality preset's keys) is laid over the scene and its --set overrides,
// is validated by the loader like the file, and names itself in messages;
// a preset's key gives way to an explicit --set.
#include "jobs/flag_overrides.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "scene/scene_tables.hpp"

namespace rollspin::jobs {
namespace {

const std::string kScene = "[ball]\nradius = 1\n[path]\nkind = \"circle\"\nradius = 3\n[render]\nwidth = 640\n";

TEST(FlagOverrides, AFlagOverridesTheFileAndASet) {
  const scene::SceneSpec spec = loadSceneWithFlags(
      "flags.toml", {"render.width=800"}, {flagOverride("--width 1000", "render", scene::key::kWidth, 1000LL)}, kScene);
  EXPECT_EQ(spec.render.width, 1000);
}

TEST(FlagOverrides, APresetGivesWayToAnExplicitSet) {
  const std::vector<FlagOverride> preset{flagOverride("--quality low", "render", scene::key::kWidth, 854LL, true),
                                         flagOverride("--quality low", "render", scene::key::kHeight, 480LL, true)};
  const scene::SceneSpec spec = loadSceneWithFlags("flags.toml", {"render.width=1024"}, preset, kScene);
  EXPECT_EQ(spec.render.width, 1024) << "the user's --set stands";
  EXPECT_EQ(spec.render.height, 480) << "the preset's other key applies";
}

TEST(FlagOverrides, AnOutOfRangeFlagIsNamedInTheMessage) {
  try {
    (void)loadSceneWithFlags("flags.toml", {}, {flagOverride("--width 0", "render", scene::key::kWidth, 0LL)}, kScene);
    FAIL() << "a width of 0 was accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_EQ(e.where().file, "--width 0") << e.what();
    EXPECT_NE(e.message().find("width"), std::string::npos) << e.message();
  }
}

TEST(FlagOverrides, TheFlagsSettingCarriesItsKeyAndValue) {
  const FlagOverride f = flagOverride("--fps 24", "animation", scene::key::kFps, 24LL);
  EXPECT_EQ(f.flag, "--fps 24");
  EXPECT_FALSE(f.preset);
  EXPECT_EQ(f.setting.dottedKey(), "animation.fps");
  EXPECT_EQ(f.setting.valueText(), "24");
}

}  // namespace
}  // namespace rollspin::jobs
