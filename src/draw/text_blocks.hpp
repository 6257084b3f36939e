// The title band across the top of the image (the views' text blocks are
// placed per clip: clip_layout.hpp). Plain DrawList labels.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "render/draw_list.hpp"

namespace rollspin::draw {

// A band across the top of the image holding the (centred) title; returns
// its height in pixels. An empty title keeps the band (views never jump).
int addTitleBand(render::DrawList& list, const std::string& title, float text);

}  // namespace rollspin::draw
