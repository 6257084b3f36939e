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

}  // namespace rollspin::render
