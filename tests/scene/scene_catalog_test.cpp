// scene/scene_catalog.hpp: bare scene names found in $ROLLSPIN_SCENE_PATH then the program's folders, the list
// of bundled scenes with their descriptions, and the message when there is none.
#include "scene/scene_catalog.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "support/test_files.hpp"

namespace rollspin::scene {
namespace {

namespace fs = std::filesystem;

// Scene folders of the test's own: $ROLLSPIN_SCENE_PATH unset and the program's folders empty (the executable's)
// again after each test, as the other tests of the program expect.
struct SceneCatalogTest : ::testing::Test {
  fs::path root = test::freshTempDir("scene_catalog");
  std::optional<std::string> savedScenePath;
  void SetUp() override {
    if (const char* env = std::getenv("ROLLSPIN_SCENE_PATH")) savedScenePath = env;
    ::unsetenv("ROLLSPIN_SCENE_PATH");
  }
  void TearDown() override {
    if (savedScenePath) ::setenv("ROLLSPIN_SCENE_PATH", savedScenePath->c_str(), 1);
    else ::unsetenv("ROLLSPIN_SCENE_PATH");
    setProgramSceneFolders({});
    fs::remove_all(root);
  }
  // A folder under the test's root, made unless `make` is false.
  fs::path folder(const std::string& name, bool make = true) const {
    const fs::path f = root / name;
    if (make) fs::create_directories(f);
    return f;
  }
};

void writeCatalogFile(const fs::path& file, const std::string& text) { std::ofstream(file, std::ios::binary) << text; }

TEST(SceneDescription, IsTheFirstSentenceOfTheLeadingComment) {
  EXPECT_EQ(sceneDescription("# Rolling on a torus. The ball goes round.\n[ball]\nradius = 1\n"),
            "Rolling on a torus.");
  EXPECT_EQ(sceneDescription("# Ends at the end of the block.\n[ball]\n"), "Ends at the end of the block.");
}

TEST(SceneDescription, JoinsTheBlocksLinesTrimmed) {
  EXPECT_EQ(sceneDescription("#   A ball rolls  \n#\tround a circle\t\n#on a plane. Then more.\n"),
            "A ball rolls round a circle on a plane.");
}

TEST(SceneDescription, AnAbbreviationOrADecimalPointEndsNoSentence) {
  EXPECT_EQ(sceneDescription("# As in sec. IV and Fig. 2 (cf. Berry), e.g. a radius of 1.5 turns. Not this.\n"),
            "As in sec. IV and Fig. 2 (cf. Berry), e.g. a radius of 1.5 turns.");
  EXPECT_EQ(sceneDescription("# Fig. 3 vs. Eq. 4 etc.\n"), "Fig. 3 vs. Eq. 4 etc.");
  // At a sentence's start too, capitalised: "Cf." and "Sec." and "E.g.".
  EXPECT_EQ(sceneDescription("# Cf. Berry and Sec. II, E.g. here. Not this.\n"), "Cf. Berry and Sec. II, E.g. here.");
  EXPECT_EQ(sceneDescription("# A word.like this one. Next.\n"), "A word.like this one.");
}

TEST(SceneDescription, TheBlockEndsAtAnEmptyCommentOrAnyOtherLine) {
  EXPECT_EQ(sceneDescription("# No full stop\n#\n# Later. Text.\n"), "No full stop");
  EXPECT_EQ(sceneDescription("# First\n\n# Second.\n"), "First");
  EXPECT_EQ(sceneDescription("# First\n[ball]\n# Second.\n"), "First");
  EXPECT_EQ(sceneDescription("[ball]\n# A comment after the first key.\n"), "");
  EXPECT_EQ(sceneDescription(""), "");
}

TEST_F(SceneCatalogTest, FoldersAreTheEnvironmentsThenTheProgramsExistingOnesOnce) {
  const fs::path a = folder("a"), b = folder("b"), c = folder("c"), missing = folder("missing", false);
  ::setenv("ROLLSPIN_SCENE_PATH", (a.string() + "::" + missing.string() + ":" + b.string()).c_str(), 1);
  setProgramSceneFolders({c, a});
  EXPECT_EQ(sceneFolders(), (std::vector<fs::path>{a, b, c}));
  // Searched, whether there or not: every folder, in order.
  ::setenv("ROLLSPIN_SCENE_PATH", (a.string() + ":" + missing.string()).c_str(), 1);
  setProgramSceneFolders({c});
  EXPECT_EQ(sceneSearchText(), a.string() + ", " + missing.string() + ", " + c.string());
  // A folder named both ways is searched once, so said once.
  ::setenv("ROLLSPIN_SCENE_PATH", (a.string() + ":" + c.string()).c_str(), 1);
  setProgramSceneFolders({c, a});
  EXPECT_EQ(sceneSearchText(), a.string() + ", " + c.string());
}

TEST_F(SceneCatalogTest, ABareNameIsTheFirstFoldersFileWithOrWithoutToml) {
  const fs::path a = folder("a"), b = folder("b");
  writeCatalogFile(a / "lollipop.toml", "# From a.\n");
  writeCatalogFile(b / "lollipop.toml", "# From b.\n");
  writeCatalogFile(b / "penny.toml", "# Penny.\n");
  fs::create_directories(a / "folder.toml");
  ::setenv("ROLLSPIN_SCENE_PATH", a.string().c_str(), 1);
  setProgramSceneFolders({b});
  EXPECT_EQ(findBundledScene("lollipop"), a / "lollipop.toml");
  EXPECT_EQ(findBundledScene("lollipop.toml"), a / "lollipop.toml");
  EXPECT_EQ(findBundledScene("penny"), b / "penny.toml");
  EXPECT_EQ(findBundledScene("folder"), std::nullopt) << "a folder is no scene";
  fs::create_directories(a / "nested");
  writeCatalogFile(a / "nested" / "deep.toml", "# Deep.\n");
  EXPECT_EQ(findBundledScene("nested/deep"), std::nullopt) << "a name with a folder is a path, not a bundled name";
  EXPECT_EQ(findBundledScene(""), std::nullopt);
  EXPECT_EQ(findBundledScene("berry"), std::nullopt);
}

TEST_F(SceneCatalogTest, BundledScenesAreSortedByNameAndAnEarlierFolderHidesALatersScene) {
  const fs::path a = folder("a"), b = folder("b");
  writeCatalogFile(a / "zeta.toml", "# The last one. Really.\n[ball]\n");
  writeCatalogFile(a / "lollipop.toml", "# From a.\n");
  writeCatalogFile(b / "lollipop.toml", "# From b.\n");
  writeCatalogFile(b / "alpha.toml", "[ball]\nradius = 1\n");
  writeCatalogFile(b / "notes.txt", "# Not a scene.\n");
  fs::create_directories(b / "folder.toml");
  setProgramSceneFolders({a, b});
  const std::vector<BundledScene> scenes = bundledScenes();
  ASSERT_EQ(scenes.size(), 3U);
  EXPECT_EQ(scenes[0].name, "alpha");
  EXPECT_EQ(scenes[0].file, b / "alpha.toml");
  EXPECT_EQ(scenes[0].description, "");
  EXPECT_EQ(scenes[1].name, "lollipop");
  EXPECT_EQ(scenes[1].file, a / "lollipop.toml");
  EXPECT_EQ(scenes[1].description, "From a.");
  EXPECT_EQ(scenes[2].name, "zeta");
  EXPECT_EQ(scenes[2].description, "The last one.");
}

TEST_F(SceneCatalogTest, AnExistingPathIsTakenAsGivenElseTheBundledScene) {
  const fs::path a = folder("a"), b = folder("b");
  writeCatalogFile(a / "catalog-lollipop.toml", "# From a.\n");
  writeCatalogFile(b / "catalog-lollipop.toml", "# From b.\n");
  setProgramSceneFolders({a});
  EXPECT_EQ(resolveScene((b / "catalog-lollipop.toml").string()), b / "catalog-lollipop.toml");
  EXPECT_EQ(resolveScene("catalog-lollipop"), a / "catalog-lollipop.toml");
  EXPECT_EQ(resolveScene("catalog-lollipop.toml"), a / "catalog-lollipop.toml");
}

TEST_F(SceneCatalogTest, NoSuchSceneIsBadInputSayingWhereItLookedAndTheNearestName) {
  const fs::path a = folder("a"), missing = folder("missing", false);
  writeCatalogFile(a / "lollipop.toml", "# Lollipop.\n");
  writeCatalogFile(a / "penny.toml", "# Penny.\n");
  setProgramSceneFolders({a, missing});
  try {
    (void)resolveScene("lolipop");
    FAIL() << "resolved";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_EQ(e.where().file, "lolipop");
    EXPECT_EQ(e.message(), "cannot read the scene file: there is none; looked in the working directory (" +
                               fs::current_path().string() + "), " + a.string() + ", " + missing.string() +
                               "; did you mean 'lollipop'?; the bundled scenes (`rollspin scenes`): lollipop, penny");
  }
  // A path with a folder is looked for there alone; the nearest bundled name is still offered.
  const Error withFolder = noSuchScene(SourceLoc{"s.toml", 3, 1}, "extends", "parts/pennny.toml", "parts/");
  EXPECT_EQ(withFolder.message(),
            "extends: there is none; looked in parts/; did you mean 'penny'?; the bundled "
            "scenes (`rollspin scenes`): lollipop, penny");
  EXPECT_EQ(std::string(withFolder.what()).rfind("s.toml:3:1: extends: there is none", 0), 0U) << withFolder.what();
}

TEST_F(SceneCatalogTest, NoSuchSceneWithNothingBundledSaysOnlyWhereItLooked) {
  setProgramSceneFolders({folder("missing", false)});
  const Error e = noSuchScene(SourceLoc{"x"}, "cannot read", "far/away.toml", "far/");
  EXPECT_EQ(e.message(), "cannot read: there is none; looked in far/");
}

}  // namespace
}  // namespace rollspin::scene
