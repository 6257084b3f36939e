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

#include <algorithm>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>

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
constexpr Range kRanges[] = {{0x20, 0x7E},     {0xA0, 0xFF},     {0x391, 0x3C9},   {0x3D1, 0x3D1},   {0x3D5, 0x3D6},
                             {0x3F5, 0x3F5},   {0x2010, 0x2027}, {0x2030, 0x2033}, {0x2070, 0x208E}, {0x210F, 0x210F},
                             {0x2190, 0x21FF}, {0x2200, 0x22FF}, {0x25CF, 0x25CF}, {0x27E8, 0x27E9}};

// The font file's bytes and stb_truetype's view of them (which points into
// the bytes: keep both together).
struct LoadedFont {
  std::shared_ptr<const std::vector<unsigned char>> ttf;
  stbtt_fontinfo info{};
};

void loadFont(const std::filesystem::path& fontFile, LoadedFont& font) {
  font.ttf = fontFileBytes(fontFile);
  const unsigned char* data = font.ttf->data();
  if (font.ttf->empty() || !stbtt_InitFont(&font.info, data, stbtt_GetFontOffsetForIndex(data, 0)))
    throw runtimeError({fontFile.string()}, "not a TrueType font");
}

// Whether the atlas keeps the code point (the font has it; a space always).
bool baked(const stbtt_fontinfo& info, char32_t cp) {
  return stbtt_FindGlyphIndex(&info, static_cast<int>(cp)) != 0 || cp == ' ';
}

// The pixels stb_truetype's packer needs for every range at least (its
// rectangles' total area, as stbtt_PackFontRangesGatherRects sizes them
// with padding 1 and no oversampling): an atlas side whose square holds
// fewer cannot pack them, so trying it would only rasterise in vain.
long long packedArea(const stbtt_fontinfo& info, float scale) {
  long long area = 0;
  bool missingGlyphAdded = false;
  for (const Range& r : kRanges)
    for (char32_t cp = r.first; cp <= r.last; ++cp) {
      const int glyph = stbtt_FindGlyphIndex(&info, static_cast<int>(cp));
      if (glyph == 0 && missingGlyphAdded) continue;
      int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
      stbtt_GetGlyphBitmapBoxSubpixel(&info, glyph, scale, scale, 0, 0, &x0, &y0, &x1, &y1);
      area += static_cast<long long>(x1 - x0 + 1) * (y1 - y0 + 1);
      if (glyph == 0) missingGlyphAdded = true;
    }
  return area;
}
}  // namespace

// Read once per process: the measuring advances and every atlas size read
// the same two files (about 700 KiB each), and a file read through a
// growing vector is copied over and over.
std::shared_ptr<const std::vector<unsigned char>> fontFileBytes(const std::filesystem::path& fontFile) {
  static std::mutex mutex;
  static std::map<std::filesystem::path, std::shared_ptr<const std::vector<unsigned char>>> read;
  const std::lock_guard<std::mutex> lock(mutex);
  if (const auto it = read.find(fontFile); it != read.end()) return it->second;
  auto unreadable = [&] {
    return runtimeError({fontFile.string()},
                        "cannot read the label font (install fonts-dejavu-core, or turn "
                        "labels off with render.labels = false)");
  };
  // Opened at its end: the size first, then one read into one allocation.
  std::ifstream in(fontFile, std::ios::binary | std::ios::ate);
  if (!in) throw unreadable();
  auto bytes =
      std::make_shared<std::vector<unsigned char>>(static_cast<std::size_t>(std::max<std::streamoff>(in.tellg(), 0)));
  in.seekg(0);
  in.read(reinterpret_cast<char*>(bytes->data()), static_cast<std::streamsize>(bytes->size()));
  if (!in) throw unreadable();
  return read.emplace(fontFile, std::move(bytes)).first->second;
}

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
  LoadedFont font;
  loadFont(fontFile, font);
  const std::vector<unsigned char>& ttf = *font.ttf;
  const stbtt_fontinfo& info = font.info;
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
  // Grow the atlas until everything fits (large labels for 8K stills),
  // from the first side whose square can hold the glyphs at all.
  const long long leastArea = packedArea(info, stbtt_ScaleForPixelHeight(&info, pixelHeight));
  for (int side = 256;; side *= 2) {
    if (side > 8192)
      throw runtimeError({fontFile.string()}, "label size {} px too large for a glyph atlas", pixelHeight);
    if (static_cast<long long>(side) * side < leastArea) continue;
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
      if (!baked(info, cp)) continue;
      stbtt_aligned_quad q;
      float x = 0, y = 0;
      stbtt_GetPackedQuad(packed[i].data(), width_, height_, static_cast<int>(k), &x, &y, &q, 0);
      glyphs_[cp] = Glyph{q.x0, q.y0, q.x1, q.y1, q.s0, q.t0, q.s1, q.t1, x};
    }
}

FontAdvances::FontAdvances(const std::filesystem::path& fontFile, float pixelHeight) {
  LoadedFont font;
  loadFont(fontFile, font);
  // stbtt_PackFontRanges sets each packed glyph's xadvance to this product.
  const float scale = stbtt_ScaleForPixelHeight(&font.info, pixelHeight);
  for (const Range& r : kRanges)
    for (char32_t cp = r.first; cp <= r.last; ++cp) {
      if (!baked(font.info, cp)) continue;
      int advance = 0, leftSideBearing = 0;
      stbtt_GetGlyphHMetrics(&font.info, stbtt_FindGlyphIndex(&font.info, static_cast<int>(cp)), &advance,
                             &leftSideBearing);
      advances_[cp] = scale * advance;
    }
}

float FontAdvances::width(std::string_view utf8) const {
  float x = 0.0f;
  for (char32_t cp : decodeUtf8(utf8)) {
    auto it = advances_.find(cp);
    if (it == advances_.end()) it = advances_.find(U'?');
    x += it->second;
  }
  return x;
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
