// The title band across the top of the image (the views' text blocks are
// placed per clip: clip_layout.hpp). Plain DrawList labels.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "render/draw_list.hpp"

namespace rollspin::draw {

// The title's size and lines in an image `width` wide: 1.35 em on one line
// where it fits, else as small as 1 em to stay on one line, else broken at
// spaces at 1 em (shrunk further only for one word wider than the image,
// never under leastPx); where the band would take over 60 % of the image's
// height, as many lines as fit, set smaller (one line at the least size).
// A figure's title starts at 1 em (bold at the body size).
struct TitleLines {
  float sizePx = 0.0f;
  std::vector<std::string> lines;
};
TitleLines titleLines(const std::string& title, float text, float width, float height, float leastPx,
                      bool figure = false);

// The band's height for `lines` lines of title: 2.4 em for one, 1.4 em
// more for each further line (a figure's: 2.0 em for one).
int titleBandHeight(std::size_t lines, float text, bool figure = false);

// A figure gives its title at most this share of its height; a title that
// needs more (at a narrow width in large text) is left out of the figure.
inline constexpr float kFigureTitleShare = 0.2f;
bool titleFitsFigure(const std::string& title, float text, float width, float height, float leastPx);

// A band across the top of the image holding the (centred) title, as tall
// as `bandLines` lines (the most any title of the clip takes, so the views
// never jump); returns its height in pixels. An empty title keeps the band.
int addTitleBand(render::DrawList& list, const std::string& title, float text, std::size_t bandLines = 1,
                 float leastPx = 0.0f, bool figure = false);

// A figure's caption below its views (where it would break narrower than
// kLeastCaptionEm in its view): bold at the body size `text`, centred,
// broken at spaces onto lines of even length across 0.94 of `width`.
std::vector<std::string> captionBandLines(const std::string& caption, float text, float width);
// The band's height for `lines` lines: 1.4 em a line and 0.6 em more.
int captionBandHeight(std::size_t lines, float text);
// The band across the bottom of the image, `bandLines` lines tall (the
// most any caption of the clip takes), holding `caption` in `color`.
void addCaptionBand(render::DrawList& list, const std::string& caption, float text, std::size_t bandLines,
                    glm::vec4 color);

}  // namespace rollspin::draw
