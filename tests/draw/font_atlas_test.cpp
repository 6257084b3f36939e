// The label font's atlas: every symbol the labels, titles and captions use
// is baked (a missing one renders as '?'), and UTF-8 decodes as expected;
// the advances text is measured with equal the atlas's own, to the bit.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "core/error.hpp"
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
    for (char32_t c : symbols)
      EXPECT_TRUE(atlas.hasGlyph(c)) << "U+" << std::hex << std::uint32_t(c) << " bold " << bold;
  }
}

TEST(FontAtlas, LaysAnEnDashOutAsItsOwnGlyphNotAsTheReplacement) {
  const render::FontAtlas atlas(render::defaultFontFile(false), 18.0f);
  std::vector<render::GlyphQuad> dash, question;
  atlas.layout("–", 0.0f, 0.0f, &dash);
  atlas.layout("?", 0.0f, 0.0f, &question);
  ASSERT_EQ(dash.size(), 1u);
  ASSERT_EQ(question.size(), 1u);
  EXPECT_NE(dash[0].s0, question[0].s0);                                // a different place in the atlas
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

// UTF-8 of one code point (at most three bytes: the atlas's ranges end below U+10000).
std::string utf8Of(char32_t cp) {
  std::string s;
  if (cp < 0x80) {
    s += char(cp);
  } else if (cp < 0x800) {
    s += char(0xC0 | (cp >> 6));
    s += char(0x80 | (cp & 0x3F));
  } else {
    s += char(0xE0 | (cp >> 12));
    s += char(0x80 | ((cp >> 6) & 0x3F));
    s += char(0x80 | (cp & 0x3F));
  }
  return s;
}

// textWidthPx measures with FontAdvances instead of a 64 px atlas: every
// code point (baked ones, and others that fall back to '?') and whole
// lines must measure exactly as the atlas lays them out, and the glyph
// set must be the atlas's.
TEST(FontAdvances, MeasureExactlyAsTheAtlasLaysOut) {
  for (bool bold : {false, true})
    for (float px : {64.0f, 13.0f}) {
      const render::FontAtlas atlas(render::defaultFontFile(bold), px);
      const render::FontAdvances advances(render::defaultFontFile(bold), px);
      int baked = 0;
      for (char32_t cp = 0x20; cp < 0x2800; ++cp) {
        const std::string s = utf8Of(cp);
        baked += atlas.hasGlyph(cp) ? 1 : 0;
        ASSERT_EQ(advances.width(s), atlas.layout(s, 0.0f, 0.0f, nullptr))
            << "U+" << std::hex << std::uint32_t(cp) << " bold " << bold << " at " << px << " px";
      }
      EXPECT_GT(baked, 600);
      for (const std::string line :
           {"s = 3.78 of 18.85", "ψ = −521.5°, ⟨ψ|σ|ψ⟩ ≈ 0.25 ℏ", "Landau–Zener → |1⟩", "\xff?"})
        EXPECT_EQ(advances.width(line), atlas.layout(line, 0.0f, 0.0f, nullptr)) << line;
    }
}

// The font file is read once per process and its bytes shared: the same
// bytes as the file, the same buffer on every later call.
TEST(FontAtlas, ReadsEachFontFileOnce) {
  const fs::path file = render::defaultFontFile(true);
  const auto first = render::fontFileBytes(file);
  const render::FontAtlas atlas(file, 11.0f);
  const render::FontAdvances advances(file, 64.0f);
  EXPECT_EQ(render::fontFileBytes(file).get(), first.get());
  ASSERT_EQ(first->size(), fs::file_size(file));
  std::ifstream in(file, std::ios::binary);
  const std::vector<unsigned char> direct((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_TRUE(direct == *first);
  EXPECT_THROW((void)render::fontFileBytes("/nonexistent/font.ttf"), Error);
}

// The atlas starts at the first side whose square can hold its glyphs'
// rectangles: the side it ends at is still the least one the packer fits
// them in (the sizes each label size got when every side from 256 up was
// tried), and every glyph is baked.
TEST(FontAtlas, SkipsOnlySidesTooSmallForItsGlyphs) {
  const std::pair<float, int> sides[] = {{13.0f, 256}, {16.0f, 512}, {48.0f, 1024}, {90.0f, 2048}};
  for (const auto& [px, side] : sides) {
    const render::FontAtlas atlas(render::defaultFontFile(false), px);
    EXPECT_EQ(atlas.atlasWidth(), side) << px << " px";
    EXPECT_TRUE(atlas.hasGlyph(U'ψ') && atlas.hasGlyph(U'⟩')) << px << " px";
  }
}

}  // namespace
}  // namespace rollspin
