// Textures the project makes itself (no binary assets): the default ball is a
// tennis ball — optic yellow felt with the white seam curve — drawn
// equirectangularly (u = longitude, v = colatitude from +z), so its rotation
// is unmistakable from any side.
#pragma once

#include <memory>

#include "render/draw_list.hpp"

namespace rollspin::render {

// Drawn once per width in a process, then shared.
[[nodiscard]] std::shared_ptr<const TextureImage> tennisBallTexture(int width = 1024);

// The renderer's Pattern::Checker as an image, for a file format that has
// no procedural pattern (glTF): 2 × 2 cells of `cellPixels`, `color` (linear
// RGB, stored sRGB-encoded) in the top-left and bottom-right cell, `color2`
// in the others. Repeated at uv · patternScale / 2 it shows the cells the
// renderer draws at uv · patternScale (cell (0, 0) is `color`).
[[nodiscard]] std::shared_ptr<const TextureImage> checkerTexture(glm::vec3 color, glm::vec3 color2,
                                                                 int cellPixels = 32);

}  // namespace rollspin::render
