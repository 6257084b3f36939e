// Text blocks in a view's pixels: the title band, a segment's caption, a
// view's heading, the lines pinned to its bottom-left corner and the fact
// block. Plain DrawList labels; sizes follow the image height (bodyTextPx).
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "render/draw_list.hpp"

namespace rollspin::draw {

// The text size, at most `preferred`, at which the longest line fits in
// `widthPx`: small images shrink their text rather than clip it.
float sizeToFit(const std::vector<std::string>& lines, float widthPx, float preferred, bool bold);

// A band across the top of the image holding the (centred) title; returns
// its height in pixels. An empty title keeps the band (views never jump).
int addTitleBand(render::DrawList& list, const std::string& title, float text);

// A storyboard segment's caption, centred under the view's heading row.
void addCaption(render::DrawList& list, const std::string& caption, int view);

// The view's bold heading in its top-left corner.
void addHeading(render::DrawList& list, const std::string& heading, int view);

// Lines (each with its colour) stacked up from the view's bottom-left corner.
void addCornerLines(render::DrawList& list, const std::vector<std::pair<std::string, glm::vec4>>& lines, int view);

// The fact lines from `top` down the view's left side, shrunk to fit its width.
void addFactBlock(render::DrawList& list, const std::vector<std::string>& lines, int view, float top);

}  // namespace rollspin::draw
