#include "media/image_view.hpp"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>

namespace rollspin::media {

void crossFade(Image& into, const Image& from, double weight) {
  assert(into.width == from.width && into.height == from.height);
  // Weights in 1/256ths: integer blending, the same on every machine.
  const int w = static_cast<int>(std::lround(std::clamp(weight, 0.0, 1.0) * 256.0));
  for (std::size_t i = 0; i < into.rgba.size(); ++i)
    into.rgba[i] = static_cast<std::uint8_t>((w * from.rgba[i] + (256 - w) * into.rgba[i] + 128) >> 8);
}

Image copyTopDown(const ImageView& view) {
  Image out(view.width, view.height);
  for (int y = 0; y < view.height; ++y)
    std::memcpy(out.pixel(0, y), view.rowFromTop(y), static_cast<std::size_t>(view.width) * 4);
  return out;
}

}  // namespace rollspin::media
