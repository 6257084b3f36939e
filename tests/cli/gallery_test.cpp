// The gallery cannot rot: every scene in scenes/ loads, solves and renders a
// small still through the CLI, and every fact label it prints uses only
// glyphs the font atlas has (a missing one would render as '?').
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <sstream>

#include "draw/draw_facts.hpp"
#include "jobs/render_jobs.hpp"
#include "media/image_io.hpp"
#include "render/font_atlas.hpp"
#include "support/cli_runner.hpp"
#include "support/sweep.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

TEST(Gallery, EverySceneRendersAStill) {
  ASSERT_GE(test::bundledSceneFiles().size(), 14u);
  const fs::path dir = test::freshTempDir("gallery");
  for (const fs::path& file : test::sweep(test::bundledSceneFiles())) {
    const std::string name = file.stem().string();
    const fs::path out = dir / (name + ".png");
    const auto r = test::runRollspin(
        {"render", file.string(), "--still", "--width", "192", "--height", "108", "--verbose", "-o", out.string()});
    ASSERT_EQ(r.exitCode, 0) << name << ": " << r.err;
    const media::Image img = media::loadImage(out, {});
    EXPECT_EQ(img.width, 192) << name;
    // Something was drawn: many distinct pixel values, not a blank view.
    std::vector<std::uint32_t> values;
    for (std::size_t i = 0; i < img.rgba.size(); i += 4)
      values.push_back(std::uint32_t(img.rgba[i]) << 16 | std::uint32_t(img.rgba[i + 1]) << 8 | img.rgba[i + 2]);
    std::sort(values.begin(), values.end());
    EXPECT_GT(std::unique(values.begin(), values.end()) - values.begin(), 200) << name;
    // The facts stage runs exactly when the scene has facts to show.
    const bool hasFacts = !scene::resolveFacts(model::loadScene(file.string(), {})).empty();
    EXPECT_EQ(r.err.find("rollspin: stage: facts") != std::string::npos, hasFacts) << name;
  }
}

TEST(Gallery, FactsAreComputedOnlyWhenTheImageShowsThem) {
  const fs::path dir = test::freshTempDir("gallery_facts");
  auto factsRan = [&](const std::string& name, const std::vector<std::string>& sets) {
    std::vector<std::string> args{"render",  (test::sourceDir() / "scenes" / (name + ".toml")).string(),
                                  "--still", "--width",
                                  "96",      "--height",
                                  "54",      "--verbose",
                                  "-o",      (dir / "a.png").string()};
    for (const auto& s : sets) args.insert(args.end(), {"--set", s});
    const auto r = test::runRollspin(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return r.err.find("rollspin: stage: facts") != std::string::npos;
  };
  EXPECT_TRUE(factsRan("lollipop", {}));
  EXPECT_FALSE(factsRan("lollipop", {"render.labels=false"}));    // delta is text only
  EXPECT_FALSE(factsRan("lollipop", {"render.layout=twin"}));     // its lines belong to the ball view
  EXPECT_TRUE(factsRan("tennis-ball", {"render.labels=false"}));  // the marks are drawn
  EXPECT_FALSE(factsRan("tennis-ball", {"render.layout=twin"}));
  EXPECT_TRUE(factsRan("berry", {"render.labels=false"}));  // the cone of B in the twin
  EXPECT_FALSE(factsRan("berry", {"render.labels=false", "render.layout=ball"}));
}

TEST(Gallery, FactLabelsUseOnlyGlyphsTheAtlasHas) {
  const render::FontAtlas atlas(render::defaultFontFile(false), 16.0f);
  int scenesWithFacts = 0;
  for (const fs::path& file : test::bundledSceneFiles()) {
    const scene::SceneSpec spec = model::loadScene(file.string(), {});
    const model::RollingModel model = model::buildSceneModel(spec);
    const auto facts = motion::makeSceneFacts(spec, model);
    if (!facts) continue;
    ++scenesWithFacts;
    const double L = model.path->length();
    for (double s : {0.0, 0.3 * L, L}) {
      for (const draw::FactLine& fact : draw::factLines(*facts, motion::solveFrame(spec, model, s), L)) {
        const std::string& line = fact.text;
        for (char32_t c : render::decodeUtf8(line))
          EXPECT_TRUE(atlas.hasGlyph(c)) << file.stem() << ": U+" << std::hex << std::uint32_t(c) << " in: " << line;
      }
    }
  }
  EXPECT_GE(scenesWithFacts, 4);
}

// A clip prints "…" for the circuit's values until its last frame (no line
// jumps); a still has no later frame, so it prints them, in the same lines.
TEST(Gallery, StillsPrintTheCircuitsValuesWhereAClipWaits) {
  int scenesThatWait = 0;
  for (const fs::path& file : test::bundledSceneFiles()) {
    const scene::SceneSpec spec = model::loadScene(file.string(), {});
    const model::RollingModel model = model::buildSceneModel(spec);
    const auto facts = motion::makeSceneFacts(spec, model);
    if (!facts) continue;
    const double L = model.path->length();
    motion::FrameOrientations frame = motion::solveFrame(spec, model, 0.3 * L);
    const std::vector<draw::FactLine> clip = draw::factLines(*facts, frame, L);
    frame.still = true;
    const std::vector<draw::FactLine> still = draw::factLines(*facts, frame, L);
    ASSERT_EQ(still.size(), clip.size()) << file.stem();
    bool waits = false;
    for (std::size_t i = 0; i < clip.size(); ++i) {
      waits = waits || clip[i].text.find("…") != std::string::npos;
      EXPECT_EQ(still[i].text.find("…"), std::string::npos) << file.stem() << ": " << still[i].text;
    }
    scenesThatWait += waits ? 1 : 0;
  }
  EXPECT_GE(scenesThatWait, 2);  // at least a delta (lollipop) and a phase split (berry)
}

}  // namespace
}  // namespace rollspin
