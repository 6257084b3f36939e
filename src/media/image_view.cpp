#include "media/image_view.hpp"

#include <cstring>

namespace rollspin::media {

Image copyTopDown(const ImageView& view) {
  Image out(view.width, view.height);
  for (int y = 0; y < view.height; ++y)
    std::memcpy(out.pixel(0, y), view.rowFromTop(y), static_cast<std::size_t>(view.width) * 4);
  return out;
}

}  // namespace rollspin::media
