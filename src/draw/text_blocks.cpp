#include "draw/text_blocks.hpp"

#include <algorithm>
#include <cmath>

#include "draw/clip_layout.hpp"
#include "draw/draw_style.hpp"

namespace rollspin::draw {

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

}  // namespace rollspin::draw
