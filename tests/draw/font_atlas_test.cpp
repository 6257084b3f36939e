// The label font's atlas: every symbol the labels, titles and captions use
// is baked (a missing one renders as '?'), and UTF-8 decodes as expected.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "model/rolling_model.hpp"
#include "render/font_atlas.hpp"
#include "support/test_files.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

TEST(FontAtlas, HasTheSymbolsLabelsUse) {
  for (bool bold : {false, true}) {
    const render::FontAtlas atlas(render::defaultFontFile(bold), 18.0f);
    const std::u32string symbols =
        U"Landau–Zener — ‘a’ “b” • … · × ÷ ≈ √ ∫ ∞ − ± ° ² ³ ¹ ⁰ ⁴ ⁺ ⁻ ⁿ ₀ ₉ ₊ ₋ ′ ″ → ⇒ ℏ ê é ü "
        U"α β γ δ θ ϑ λ μ π ρ σ φ ϕ χ ψ ω Δ Σ Φ Ψ Ω |0⟩ ⟨ψ| ●";
    for (char32_t c : symbols) EXPECT_TRUE(atlas.hasGlyph(c)) << "U+" << std::hex << std::uint32_t(c) << " bold " << bold;
  }
}

TEST(FontAtlas, LaysAnEnDashOutAsItsOwnGlyphNotAsTheReplacement) {
  const render::FontAtlas atlas(render::defaultFontFile(false), 18.0f);
  std::vector<render::GlyphQuad> dash, question;
  atlas.layout("–", 0.0f, 0.0f, &dash);
  atlas.layout("?", 0.0f, 0.0f, &question);
  ASSERT_EQ(dash.size(), 1u);
  ASSERT_EQ(question.size(), 1u);
  EXPECT_NE(dash[0].s0, question[0].s0);  // a different place in the atlas
  EXPECT_LT(dash[0].y1 - dash[0].y0, question[0].y1 - question[0].y0);  // a dash is flat
}

// Every title and caption of the shipped scenes is drawable.
TEST(FontAtlas, EveryTitleAndCaptionInScenesHasItsGlyphs) {
  const render::FontAtlas regular(render::defaultFontFile(false), 18.0f);
  const render::FontAtlas bold(render::defaultFontFile(true), 18.0f);
  int texts = 0;
  for (const auto& entry : fs::directory_iterator(test::sourceDir() / "scenes")) {
    if (entry.path().extension() != ".toml") continue;
    const scene::SceneSpec spec = model::loadScene(entry.path().string(), {});
    std::vector<std::string> lines{spec.render.title};
    for (const auto& segment : spec.segments) {
      lines.push_back(segment.caption);
      if (segment.title) lines.push_back(*segment.title);
    }
    for (const std::string& line : lines) {
      if (line.empty()) continue;
      ++texts;
      for (char32_t c : render::decodeUtf8(line)) {
        EXPECT_TRUE(regular.hasGlyph(c) && bold.hasGlyph(c))
            << entry.path().filename() << ": U+" << std::hex << std::uint32_t(c) << " in: " << line;
      }
    }
  }
  EXPECT_GE(texts, 3);
}

}  // namespace
}  // namespace rollspin
