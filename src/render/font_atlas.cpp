#include "render/font_atlas.hpp"

#define STB_TRUETYPE_IMPLEMENTATION
#define STB_RECT_PACK_IMPLEMENTATION
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wsign-compare"
#pragma GCC diagnostic ignored "-Wunused-parameter"
#include <stb/stb_rect_pack.h>
#include <stb/stb_truetype.h>
#pragma GCC diagnostic pop

#include <fstream>
#include <iterator>

#include "core/error.hpp"

namespace rollspin::render {

namespace {
struct Range {
  char32_t first, last;
};
// What labels and titles use: ASCII; Latin-1 (° ± ² ³ ¹ · × ÷ and accented
// letters such as ê); Greek with its variant forms (ϑ ϕ ϖ ϵ); general
// punctuation (‐ – — ‘ ’ “ ” • … ′ ″); superscripts and subscripts
// (⁰ ⁱ ⁴…⁹ ⁺ ⁻ ⁼ ⁽ ⁾ ⁿ, ₀…₉ ₊ ₋); ℏ; arrows (→ ↦ ⇒); mathematical operators
// (− √ ≈ ∫ ∮ ∞ …); ● and ⟨ ⟩. A code point outside them renders as '?'.
constexpr Range kRanges[] = {{0x20, 0x7E},     {0xA0, 0xFF},     {0x391, 0x3C9},   {0x3D1, 0x3D1},
                             {0x3D5, 0x3D6},   {0x3F5, 0x3F5},   {0x2010, 0x2027}, {0x2030, 0x2033},
                             {0x2070, 0x208E}, {0x210F, 0x210F}, {0x2190, 0x21FF}, {0x2200, 0x22FF},
                             {0x25CF, 0x25CF}, {0x27E8, 0x27E9}};
}  // namespace

std::u32string decodeUtf8(std::string_view s) {
  std::u32string out;
  for (std::size_t i = 0; i < s.size();) {
    const auto c = static_cast<unsigned char>(s[i]);
    int len = c < 0x80 ? 1 : (c >> 5) == 6 ? 2 : (c >> 4) == 14 ? 3 : (c >> 3) == 30 ? 4 : 0;
    if (len == 0 || i + len > s.size()) {
      out.push_back(0xFFFD);
      ++i;
      continue;
    }
    char32_t cp = len == 1 ? c : len == 2 ? (c & 0x1F) : len == 3 ? (c & 0x0F) : (c & 0x07);
    for (int k = 1; k < len; ++k) cp = (cp << 6) | (static_cast<unsigned char>(s[i + k]) & 0x3F);
    out.push_back(cp);
    i += len;
  }
  return out;
}

std::filesystem::path defaultFontFile(bool bold) {
  return bold ? "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf"
              : "/usr/share/fonts/truetype/dejavu/DejaVuSans.ttf";
}

FontAtlas::FontAtlas(const std::filesystem::path& fontFile, float pixelHeight) : pixelHeight_(pixelHeight) {
  std::ifstream in(fontFile, std::ios::binary);
  if (!in)
    throw runtimeError({fontFile.string()}, "cannot read the label font (install fonts-dejavu-core, or turn "
                                            "labels off with render.labels = false)");
  const std::vector<unsigned char> ttf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  stbtt_fontinfo info;
  if (!stbtt_InitFont(&info, ttf.data(), stbtt_GetFontOffsetForIndex(ttf.data(), 0)))
    throw runtimeError({fontFile.string()}, "not a TrueType font");
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&info, &ascent, &descent, &gap);
  ascent_ = ascent * stbtt_ScaleForPixelHeight(&info, pixelHeight);

  std::vector<stbtt_pack_range> ranges;
  std::vector<std::vector<stbtt_packedchar>> packed;
  for (const Range& r : kRanges) packed.emplace_back(r.last - r.first + 1);
  for (std::size_t i = 0; i < std::size(kRanges); ++i) {
    stbtt_pack_range pr{};
    pr.font_size = pixelHeight;
    pr.first_unicode_codepoint_in_range = static_cast<int>(kRanges[i].first);
    pr.num_chars = static_cast<int>(packed[i].size());
    pr.chardata_for_range = packed[i].data();
    ranges.push_back(pr);
  }
  // Grow the atlas until everything fits (large labels for 8K stills).
  for (int side = 256;; side *= 2) {
    if (side > 8192) throw runtimeError({fontFile.string()}, "label size {} px too large for a glyph atlas", pixelHeight);
    width_ = height_ = side;
    coverage_.assign(static_cast<std::size_t>(side) * side, 0);
    stbtt_pack_context pc;
    if (!stbtt_PackBegin(&pc, coverage_.data(), side, side, 0, 1, nullptr)) continue;
    stbtt_PackSetOversampling(&pc, 1, 1);
    const int ok = stbtt_PackFontRanges(&pc, ttf.data(), 0, ranges.data(), static_cast<int>(ranges.size()));
    stbtt_PackEnd(&pc);
    if (ok) break;
  }
  for (std::size_t i = 0; i < std::size(kRanges); ++i)
    for (std::size_t k = 0; k < packed[i].size(); ++k) {
      const char32_t cp = kRanges[i].first + static_cast<char32_t>(k);
      if (stbtt_FindGlyphIndex(&info, static_cast<int>(cp)) == 0 && cp != ' ') continue;
      stbtt_aligned_quad q;
      float x = 0, y = 0;
      stbtt_GetPackedQuad(packed[i].data(), width_, height_, static_cast<int>(k), &x, &y, &q, 0);
      glyphs_[cp] = Glyph{q.x0, q.y0, q.x1, q.y1, q.s0, q.t0, q.s1, q.t1, x};
    }
}

float FontAtlas::layout(std::string_view utf8, float x, float y, std::vector<GlyphQuad>* quads) const {
  const float start = x;
  for (char32_t cp : decodeUtf8(utf8)) {
    auto it = glyphs_.find(cp);
    if (it == glyphs_.end()) it = glyphs_.find(U'?');
    const Glyph& g = it->second;
    if (quads != nullptr && g.x1 > g.x0)
      quads->push_back({x + g.x0, y + g.y0, x + g.x1, y + g.y1, g.s0, g.t0, g.s1, g.t1});
    x += g.advance;
  }
  return x - start;
}

}  // namespace rollspin::render
