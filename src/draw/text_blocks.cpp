#include "draw/text_blocks.hpp"

#include <algorithm>
#include <cmath>

#include "draw/clip_layout.hpp"
#include "draw/draw_style.hpp"

namespace rollspin::draw {

// DejaVu Sans averages under 0.6 em per character (bold 0.66).
float sizeToFit(const std::vector<std::string>& lines, float widthPx, float preferred, bool bold) {
  std::size_t longest = 1;
  for (const auto& line : lines)
    longest = std::max<std::size_t>(longest, std::count_if(line.begin(), line.end(), [](char c) {
                                      return (static_cast<unsigned char>(c) & 0xC0) != 0x80;  // UTF-8 lead bytes
                                    }));
  return std::max(7.0f, std::min(preferred, widthPx / ((bold ? 0.66f : 0.6f) * float(longest))));
}

int addTitleBand(render::DrawList& list, const std::string& titleText, float text) {
  const int top = static_cast<int>(std::lround(text * 2.4f));
  render::View band;
  band.width = list.width;
  band.height = top;
  band.backgroundBottom = band.backgroundTop;  // continues the views' top colour
  band.light.shadow = false;
  list.views.push_back(band);
  render::LabelItem title;
  title.text = titleText;
  title.anchor = glm::vec3(0.5f * list.width, 0.5f * top, 0.0f);
  title.align = render::Align::Center;
  // Shrunk to fit the width when it is long: never cut by the frame.
  const float preferred = text * 1.35f, width = textWidthPx(titleText, preferred, true);
  title.sizePx = width > 0.94f * float(list.width) ? preferred * 0.94f * float(list.width) / width : preferred;
  title.bold = true;
  title.color = kTextColor;
  if (!titleText.empty()) list.labels.push_back(title);
  return top;
}

// It is the lecturer's own text, so it shows even with render.labels = false.
void addCaption(render::DrawList& list, const std::string& caption, int view) {
  if (caption.empty()) return;
  const render::View& v = list.views[static_cast<std::size_t>(view)];
  const float text = bodyTextPx(list.height);
  render::LabelItem label;
  label.view = view;
  label.text = caption;
  label.anchor = glm::vec3(0.5f * float(v.width), text * 0.8f + text * 2.1f, 0.0f);
  label.align = render::Align::Center;
  label.sizePx = sizeToFit({caption}, float(v.width) - 1.6f * text, text * 1.2f, true);
  label.bold = true;
  label.color = glm::vec4(0.55f, 0.12f, 0.02f, 1.0f);
  list.labels.push_back(label);
}

void addHeading(render::DrawList& list, const std::string& text, int view) {
  const float size = bodyTextPx(list.height);
  const float margin = size * 0.8f;
  render::LabelItem heading;
  heading.view = view;
  heading.text = text;
  heading.anchor = glm::vec3(margin, margin, 0.0f);
  heading.sizePx = size * 1.1f;
  heading.bold = true;
  heading.color = kTextColor;
  list.labels.push_back(heading);
}

void addCornerLines(render::DrawList& list, const std::vector<std::pair<std::string, glm::vec4>>& lines, int view) {
  const render::View& v = list.views[static_cast<std::size_t>(view)];
  const float text = bodyTextPx(list.height);
  const float margin = text * 0.8f;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    render::LabelItem l;
    l.view = view;
    l.text = lines[i].first;
    l.anchor = glm::vec3(margin, float(v.height) - margin - float(lines.size() - 1 - i) * text * 1.35f - 0.4f * text, 0.0f);
    l.sizePx = text;
    l.color = lines[i].second;
    list.labels.push_back(l);
  }
}

void addFactBlock(render::DrawList& list, const std::vector<std::string>& lines, int view, float top) {
  const float text = bodyTextPx(list.height);
  const float margin = text * 0.8f;
  const float size =
      sizeToFit(lines, float(list.views[static_cast<std::size_t>(view)].width) - 2.0f * margin, text * 0.9f, false);
  for (std::size_t i = 0; i < lines.size(); ++i) {
    render::LabelItem l;
    l.view = view;
    l.text = lines[i];
    l.anchor = glm::vec3(margin, top + float(i) * size * 1.45f, 0.0f);
    l.sizePx = size;
    l.color = kTextColor;
    list.labels.push_back(l);
  }
}

}  // namespace rollspin::draw
