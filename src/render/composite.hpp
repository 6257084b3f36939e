// The CPU composite of a read-back scene: the scene is premultiplied colour
// over transparent black, sRGB-encoded bytes as blending left them; a view's
// backdrop goes behind it with the "over" operator, out = c + (1 − a)·backdrop
// per channel (exact for any stack of blended layers). Plain functions, no GL.
#pragma once

#include <glm/glm.hpp>

#include <cstdint>

namespace rollspin::render {

// sRGB encoding of a linear colour, clamped to [0, 1] (the piecewise curve:
// 12.92·c below 0.0031308, 1.055·c^(1/2.4) − 0.055 above).
[[nodiscard]] glm::vec3 encodeSrgb(const glm::vec3& linear);

// Packed little-endian RGBA8 words [begin, end) over `backdrop` (encoded,
// in [0, 1]) into `out`: per channel c + round((1 − a)·255·backdrop),
// clamped to 255; alpha at least opaqueAlpha. Pixels the scene covers fully
// keep their word, and those it leaves empty take the backdrop's, computed
// once.
void compositeSpan(const std::uint32_t* begin, const std::uint32_t* end, std::uint32_t* out, const glm::vec3& backdrop,
                   std::uint32_t opaqueAlpha);

}  // namespace rollspin::render
