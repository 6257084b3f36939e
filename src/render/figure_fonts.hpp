// FigureFonts — a figure's label fonts for cairo through fontconfig and
// FreeType: the family asked for, and DejaVu Sans for any character it
// lacks (Latin Modern has no ⟩), so a label never shows a missing-glyph box.
#pragma once

#include <cairo.h>
#include <fontconfig/fontconfig.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

namespace rollspin::render {

class FigureFonts {
 public:
  explicit FigureFonts(std::string family) : family_(std::move(family)) {}
  ~FigureFonts();
  FigureFonts(const FigureFonts&) = delete;
  FigureFonts& operator=(const FigureFonts&) = delete;

  struct Face {
    FcPattern* pattern = nullptr;
    cairo_font_face_t* face = nullptr;
    FcCharSet* charset = nullptr;  // owned by pattern
    double heightPerEm = 1.0;      // ascent + descent at size 1
  };
  // The family's face (fallback: DejaVu Sans's) at a weight, made once.
  const Face& face(bool bold, bool fallback);

  // The text split into runs, each in the first face that has its characters.
  struct Run {
    const Face* face;
    std::string utf8;
  };
  std::vector<Run> runs(const std::string& text, bool bold);

 private:
  std::string family_;
  std::map<std::pair<bool, bool>, Face> faces_;
};

// fontconfig's best match for a family at a weight (the caller owns it).
[[nodiscard]] FcPattern* matchFont(const std::string& family, bool bold);
// Whether a match is of that family (fontconfig substitutes silently).
[[nodiscard]] bool sameFamily(FcPattern* match, const std::string& family);

}  // namespace rollspin::render
