// A figure's layout (render::figureLayout) as JSON: `render --still -o
// FIG.pdf --layout-json FILE`, for checking a figure by script.
#include <fmt/format.h>

#include <string>

#include "render/vector_figure.hpp"

namespace rollspin::render {

namespace {

std::string jsonEscaped(const std::string& text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '"' || c == '\\') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

}  // namespace

std::string figureLayoutJson(const FigureLayout& layout) {
  std::string out =
      fmt::format("{{\n  \"width_pt\": {:.3f}, \"height_pt\": {:.3f},\n", layout.widthPt, layout.heightPt);
  auto boxes = [&](const char* name, const std::vector<FigureBox>& list) {
    out += fmt::format("  \"{}\": [", name);
    for (std::size_t i = 0; i < list.size(); ++i)
      out += fmt::format("{}[{:.3f}, {:.3f}, {:.3f}, {:.3f}]", i ? ", " : "", list[i].x0, list[i].y0, list[i].x1,
                         list[i].y1);
    out += "],\n";
  };
  auto segments = [&](const char* name, const std::vector<FigureLayout::Segment>& list, bool last) {
    out += fmt::format("  \"{}\": [", name);
    for (std::size_t i = 0; i < list.size(); ++i)
      out += fmt::format("{}[{:.3f}, {:.3f}, {:.3f}, {:.3f}, {:.3f}]", i ? ", " : "", list[i].a.x, list[i].a.y,
                         list[i].b.x, list[i].b.y, list[i].halfWidth);
    out += last ? "]\n" : "],\n";
  };
  boxes("views", layout.views);
  boxes("plates", layout.plates);
  out += "  \"texts\": [\n";
  for (std::size_t i = 0; i < layout.texts.size(); ++i) {
    const FigureLayout::Text& t = layout.texts[i];
    const std::string escaped = jsonEscaped(t.text);
    out += fmt::format(
        "    {{\"text\": \"{}\", \"box\": [{:.3f}, {:.3f}, {:.3f}, {:.3f}], \"anchor\": [{:.3f}, {:.3f}], "
        "\"free\": {}, \"view\": {}, \"size_pt\": {:.2f}}}{}\n",
        escaped, t.box.x0, t.box.y0, t.box.x1, t.box.y1, t.anchor.x, t.anchor.y, t.free, t.view, t.sizePt,
        i + 1 < layout.texts.size() ? "," : "");
  }
  out += "  ],\n";
  // Each text left out, with where it would be kept (null: nowhere tried).
  auto orNull = [](const std::optional<double>& v) { return v ? fmt::format("{:g}", *v) : std::string("null"); };
  out += "  \"left_out\": [";
  for (std::size_t i = 0; i < layout.leftOut.size(); ++i)
    out += fmt::format("{}\n    {{\"text\": \"{}\", \"kept_at_width_mm\": {}, \"kept_at_font_size_pt\": {}}}",
                       i ? "," : "", jsonEscaped(layout.leftOut[i].text), orNull(layout.leftOut[i].keptAtWidthMm),
                       orNull(layout.leftOut[i].keptAtFontPt));
  out += layout.leftOut.empty() ? "],\n" : "\n  ],\n";
  segments("arrows", layout.arrows, false);
  segments("paths", layout.paths, true);
  out += "}\n";
  return out;
}

}  // namespace rollspin::render
