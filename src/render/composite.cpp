#include "render/composite.hpp"

#include <algorithm>
#include <cmath>

namespace rollspin::render {

glm::vec3 encodeSrgb(const glm::vec3& linear) {
  glm::vec3 out;
  for (int k = 0; k < 3; ++k) {
    const float c = std::clamp(linear[k], 0.0f, 1.0f);
    out[k] = c < 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
  }
  return out;
}

void compositeSpan(const std::uint32_t* begin, const std::uint32_t* end, std::uint32_t* out, const glm::vec3& backdrop,
                   std::uint32_t opaqueAlpha) {
  auto over = [&](std::uint32_t t) {
    const std::uint32_t a = t >> 24u;
    const float uncovered = float(255u - a);
    std::uint32_t word = std::max(a, opaqueAlpha) << 24u;
    for (int c = 0; c < 3; ++c) {
      const auto behind = static_cast<std::uint32_t>(backdrop[c] * uncovered + 0.5f);
      word |= std::min(((t >> (8 * c)) & 0xFFu) + behind, 255u) << (8 * c);
    }
    return word;
  };
  const std::uint32_t empty = over(0u);
  for (const std::uint32_t* p = begin; p != end; ++p, ++out) {
    const std::uint32_t t = *p;
    *out = t >= 0xFF000000u ? t : t == 0u ? empty : over(t);
  }
}

}  // namespace rollspin::render
