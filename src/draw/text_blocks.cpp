#include "draw/text_blocks.hpp"

#include <algorithm>
#include <cmath>

#include "draw/clip_layout.hpp"
#include "draw/draw_style.hpp"

namespace rollspin::draw {

TitleLines titleLines(const std::string& title, float text, float width, float height, float leastPx, bool figure) {
  // A figure's title is set bold at the body size (the least a bold face
  // may take to print at 6 pt): its caption is the paper's.
  const float room = 0.94f * width, least = std::max(text, leastPx), preferred = figure ? least : text * 1.35f;
  const float atPreferred = textWidthPx(title, preferred, true);
  if (atPreferred <= room) return {preferred, {title}};
  // Down to the body size on one line before it breaks.
  if (atPreferred * least / preferred <= room) return {preferred * room / atPreferred, {title}};
  TitleLines out{least, wrapText(title, least, true, room, true)};
  // The band takes at most 60 % of the image (a thumbnail, a tiny figure at
  // a large size): past that, as many lines as fit, set smaller.
  std::size_t most = 1;
  while (float(titleBandHeight(most + 1, text)) <= 0.6f * height) ++most;
  while (out.lines.size() > most && out.sizePx > std::min(least, leastPx)) {
    out.sizePx = std::max(std::min(least, leastPx), 0.95f * out.sizePx);
    out.lines = wrapText(title, out.sizePx, true, room, true);
  }
  if (out.lines.size() > most) {
    const float atSize = textWidthPx(title, out.sizePx, true);
    return {std::max(std::min(out.sizePx, leastPx), out.sizePx * room / atSize), {title}};
  }
  for (const std::string& line : out.lines) {
    const float w = textWidthPx(line, out.sizePx, true);
    if (w > room) out.sizePx = std::max(std::min(out.sizePx, leastPx), out.sizePx * room / w);
  }
  return out;
}

int titleBandHeight(std::size_t lines, float text, bool figure) {
  const float first = figure ? 2.0f : 2.4f;
  return static_cast<int>(std::lround(text * (first + 1.4f * float(std::max<std::size_t>(lines, 1) - 1))));
}

bool titleFitsFigure(const std::string& title, float text, float width, float height, float leastPx) {
  const std::size_t lines = titleLines(title, text, width, height, leastPx, true).lines.size();
  return float(titleBandHeight(lines, text, true)) <= kFigureTitleShare * height;
}

int addTitleBand(render::DrawList& list, const std::string& titleText, float text, std::size_t bandLines, float leastPx,
                 bool figure) {
  const int top = titleBandHeight(bandLines, text, figure);
  render::View band;
  band.width = list.width;
  band.height = top;
  band.backgroundBottom = band.backgroundTop;  // continues the views' top colour
  band.light.shadow = false;
  list.views.push_back(band);
  if (titleText.empty()) return top;
  // Never cut by the frame: a long title takes a smaller size, then more lines.
  const TitleLines title = titleLines(titleText, text, float(list.width), float(list.height), leastPx, figure);
  const float step = 1.4f * title.sizePx;
  for (std::size_t k = 0; k < title.lines.size(); ++k) {
    render::LabelItem line;
    line.text = title.lines[k];
    line.anchor =
        glm::vec3(0.5f * list.width, 0.5f * top + (float(k) - 0.5f * float(title.lines.size() - 1)) * step, 0.0f);
    line.align = render::Align::Center;
    line.sizePx = title.sizePx;
    line.bold = true;
    line.color = kTextColor;
    list.labels.push_back(line);
  }
  return top;
}

std::vector<std::string> captionBandLines(const std::string& caption, float text, float width) {
  return wrapText(caption, text, true, 0.94f * width, true);
}

int captionBandHeight(std::size_t lines, float text) {
  return static_cast<int>(std::lround(text * (0.6f + 1.4f * float(std::max<std::size_t>(lines, 1)))));
}

void addCaptionBand(render::DrawList& list, const std::string& caption, float text, std::size_t bandLines,
                    glm::vec4 color) {
  const int height = captionBandHeight(bandLines, text);
  render::View band;
  band.y = list.height - height;
  band.width = list.width;
  band.height = height;
  band.backgroundTop = band.backgroundBottom;  // continues the views' bottom colour
  band.light.shadow = false;
  list.views.push_back(band);
  const std::vector<std::string> lines =
      caption.empty() ? std::vector<std::string>{} : captionBandLines(caption, text, float(list.width));
  const float step = kLineStep * text;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    render::LabelItem line;
    line.text = lines[k];
    line.anchor =
        glm::vec3(0.5f * list.width,
                  float(band.y) + 0.5f * float(height) + (float(k) - 0.5f * float(lines.size() - 1)) * step, 0.0f);
    line.align = render::Align::Center;
    line.sizePx = text;
    line.bold = true;
    line.color = color;
    list.labels.push_back(line);
  }
}

}  // namespace rollspin::draw
