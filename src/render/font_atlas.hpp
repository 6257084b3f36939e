// FontAtlas — glyphs of one TrueType font baked at one pixel size into a
// single-channel coverage atlas with stb_truetype: ASCII, Greek, and the few
// symbols the labels use (⟨ ⟩ ° · − ≈ ×). Plain data, no GL.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace rollspin::render {

struct GlyphQuad {
  float x0, y0, x1, y1;  // pixels, relative to the pen (y down)
  float s0, t0, s1, t1;  // atlas texture coordinates
};

class FontAtlas {
 public:
  // Throws Error (Runtime) when the font cannot be read or parsed.
  FontAtlas(const std::filesystem::path& fontFile, float pixelHeight);

  [[nodiscard]] int atlasWidth() const { return width_; }
  [[nodiscard]] int atlasHeight() const { return height_; }
  [[nodiscard]] const std::vector<std::uint8_t>& coverage() const { return coverage_; }
  [[nodiscard]] float pixelHeight() const { return pixelHeight_; }
  [[nodiscard]] float ascent() const { return ascent_; }

  // Quads for a UTF-8 string starting at the pen (x, baseline y); returns the
  // advance width. Unknown code points render as '?'.
  float layout(std::string_view utf8, float x, float y, std::vector<GlyphQuad>* quads) const;
  // Whether the atlas has the code point (else it renders as '?').
  [[nodiscard]] bool hasGlyph(char32_t codePoint) const { return glyphs_.contains(codePoint); }

 private:
  struct Glyph {
    float x0, y0, x1, y1, s0, t0, s1, t1, advance;
  };
  std::map<char32_t, Glyph> glyphs_;
  std::vector<std::uint8_t> coverage_;
  int width_ = 0, height_ = 0;
  float pixelHeight_ = 0.0f, ascent_ = 0.0f;
};

// The advance widths alone of the glyphs a FontAtlas of the same font and
// size bakes: what measuring text needs, without rasterising an atlas.
// width(s) equals FontAtlas::layout(s, 0, 0, nullptr) to the bit (the same
// glyph set, each advance scale · advanceWidth as stb_truetype packs it,
// summed in the same order, unknown code points as '?').
class FontAdvances {
 public:
  // Throws Error (Runtime) when the font cannot be read or parsed.
  FontAdvances(const std::filesystem::path& fontFile, float pixelHeight);
  [[nodiscard]] float width(std::string_view utf8) const;

 private:
  std::map<char32_t, float> advances_;
};

// A font file's bytes, read on the first call for that path and shared
// after it (FontAtlas and FontAdvances parse them). Throws Error (Runtime)
// when the file cannot be read.
[[nodiscard]] std::shared_ptr<const std::vector<unsigned char>> fontFileBytes(const std::filesystem::path& fontFile);

// The default label font (DejaVu Sans from fonts-dejavu-core).
[[nodiscard]] std::filesystem::path defaultFontFile(bool bold);

// UTF-8 → code points (invalid bytes become U+FFFD).
[[nodiscard]] std::u32string decodeUtf8(std::string_view utf8);

}  // namespace rollspin::render
