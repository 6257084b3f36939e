// Readback: the scene's pixels back to the CPU, composited over the views'
// backdrops (composite.hpp) and flipped top-down; the depth buffer for
// vector figures; the retained layer's edge tiles. Renderer-internal.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "media/image_view.hpp"
#include "render/draw_list.hpp"
#include "render/gl.hpp"
#include "render/layer_key.hpp"
#include "render/screen_bounds.hpp"

namespace rollspin::render {

// Reads the scene's pixels back; holds the rows, backdrops and row cuts it
// reuses from read to read (no allocation per rectangle).
class Readback {
 public:
  // The pixels of `r` (image rows, top-down) of the framebuffer `sceneFbo`
  // into `image`, composited over the list's views' backdrops.
  void pixels(const DrawList& list, media::Image& image, const PixelRect& r, GLuint sceneFbo);

 private:
  std::vector<std::uint32_t> rows_;                         // as read, bottom-up
  std::vector<std::pair<glm::vec3, glm::vec3>> backdrops_;  // per view, sRGB-encoded
  std::vector<int> cuts_;                                   // per row: where views begin and end
};

// The depth of the framebuffer `sceneFbo`, width × height, top-down.
void readDepth(GLuint sceneFbo, int width, int height, std::vector<float>& depth);

// The tiles of the framebuffer `sceneFbo` (the list's size) where the
// resolved scene covers pixels in part (alpha strictly between 0 and 1).
std::vector<PixelRect> partlyCoveredTiles(const DrawList& list, GLuint sceneFbo);

}  // namespace rollspin::render
