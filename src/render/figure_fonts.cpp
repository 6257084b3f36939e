#include "render/figure_fonts.hpp"

#include <cairo-ft.h>

#include "core/error.hpp"
#include "core/text.hpp"
#include "render/font_atlas.hpp"
#include "render/vector_figure.hpp"

namespace rollspin::render {

namespace {

std::string encodeUtf8(const std::u32string& text) {
  std::string out;
  for (char32_t c : text) {
    if (c < 0x80) {
      out += static_cast<char>(c);
    } else if (c < 0x800) {
      out += static_cast<char>(0xC0 | (c >> 6));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else if (c < 0x10000) {
      out += static_cast<char>(0xE0 | (c >> 12));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    } else {
      out += static_cast<char>(0xF0 | (c >> 18));
      out += static_cast<char>(0x80 | ((c >> 12) & 0x3F));
      out += static_cast<char>(0x80 | ((c >> 6) & 0x3F));
      out += static_cast<char>(0x80 | (c & 0x3F));
    }
  }
  return out;
}

}  // namespace

FcPattern* matchFont(const std::string& family, bool bold) {
  FcPattern* pattern = FcPatternCreate();
  FcPatternAddString(pattern, FC_FAMILY, reinterpret_cast<const FcChar8*>(family.c_str()));
  FcPatternAddInteger(pattern, FC_WEIGHT, bold ? FC_WEIGHT_BOLD : FC_WEIGHT_REGULAR);
  FcPatternAddInteger(pattern, FC_SLANT, FC_SLANT_ROMAN);
  FcConfigSubstitute(nullptr, pattern, FcMatchPattern);
  FcDefaultSubstitute(pattern);
  FcResult result = FcResultNoMatch;
  FcPattern* match = FcFontMatch(nullptr, pattern, &result);
  FcPatternDestroy(pattern);
  return match;
}

bool sameFamily(FcPattern* match, const std::string& family) {
  FcChar8* name = nullptr;
  for (int i = 0; FcPatternGetString(match, FC_FAMILY, i, &name) == FcResultMatch; ++i)
    if (asciiLowercase(reinterpret_cast<const char*>(name)) == asciiLowercase(family)) return true;
  return false;
}

FigureFonts::~FigureFonts() {
  for (auto& [key, f] : faces_) {
    cairo_font_face_destroy(f.face);
    FcPatternDestroy(f.pattern);
  }
}

const FigureFonts::Face& FigureFonts::face(bool bold, bool fallback) {
  const auto key = std::make_pair(bold, fallback);
  auto it = faces_.find(key);
  if (it != faces_.end()) return it->second;
  Face f;
  f.pattern = matchFont(fallback ? "DejaVu Sans" : family_, bold);
  if (f.pattern == nullptr) throw runtimeError({family_}, "fontconfig found no font for the figure's labels");
  f.face = cairo_ft_font_face_create_for_pattern(f.pattern);
  FcPatternGetCharSet(f.pattern, FC_CHARSET, 0, &f.charset);
  // The GL labels size text by stb_truetype's "pixel height" (ascent −
  // descent); the same metric here keeps the figure's text the same size.
  cairo_surface_t* scratch = cairo_image_surface_create(CAIRO_FORMAT_A8, 1, 1);
  cairo_t* cr = cairo_create(scratch);
  cairo_font_options_t* unhinted = cairo_font_options_create();
  cairo_font_options_set_hint_metrics(unhinted, CAIRO_HINT_METRICS_OFF);  // else rounded to whole units
  cairo_set_font_options(cr, unhinted);
  cairo_font_options_destroy(unhinted);
  cairo_set_font_face(cr, f.face);
  constexpr double kProbe = 1000.0;
  cairo_set_font_size(cr, kProbe);
  cairo_font_extents_t e;
  cairo_font_extents(cr, &e);
  if (e.ascent + e.descent > 0.0) f.heightPerEm = (e.ascent + e.descent) / kProbe;
  cairo_destroy(cr);
  cairo_surface_destroy(scratch);
  return faces_.emplace(key, f).first->second;
}

std::vector<FigureFonts::Run> FigureFonts::runs(const std::string& text, bool bold) {
  const Face& primary = face(bold, false);
  std::vector<Run> out;
  std::u32string current;
  const Face* currentFace = nullptr;
  for (char32_t c : decodeUtf8(text)) {
    const bool has = primary.charset == nullptr || FcCharSetHasChar(primary.charset, c) || c == U' ';
    const Face* f = has ? &primary : &face(bold, true);
    if (f != currentFace && !current.empty()) {
      out.push_back({currentFace, encodeUtf8(current)});
      current.clear();
    }
    currentFace = f;
    current += c;
  }
  if (!current.empty()) out.push_back({currentFace, encodeUtf8(current)});
  return out;
}

double figureFontHeightPerEm(const std::string& family) {
  FigureFonts fonts(family);
  return fonts.face(false, false).heightPerEm;
}

void checkFigureFont(const std::string& family, const SourceLoc& where) {
  FcPattern* match = matchFont(family, false);
  const bool found = match != nullptr && sameFamily(match, family);
  if (match != nullptr) FcPatternDestroy(match);
  if (!found)
    throw badInput(where,
                   "figure.font: no font family '{}' is installed (`fc-list : family` lists them; "
                   "Debian's fonts-lmodern gives \"Latin Modern Roman\")",
                   family);
}

}  // namespace rollspin::render
