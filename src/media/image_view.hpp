// ImageView / Image — 8-bit RGBA pixels as plain data. An ImageView borrows
// (width, height, stride in bytes, row order); an Image owns tightly packed
// top-down rows. media/ never knows where pixels came from.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

namespace rollspin::media {

enum class RowOrder { TopDown, BottomUp };

struct ImageView {
  int width = 0;
  int height = 0;
  std::ptrdiff_t stride = 0;  // bytes from one stored row to the next
  const std::uint8_t* rgba = nullptr;
  RowOrder rows = RowOrder::TopDown;

  // Pointer to the row that is `y` from the top, whatever the storage order.
  [[nodiscard]] const std::uint8_t* rowFromTop(int y) const {
    const int stored = rows == RowOrder::TopDown ? y : height - 1 - y;
    return rgba + static_cast<std::ptrdiff_t>(stored) * stride;
  }
};

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4, top row first

  Image() = default;
  Image(int w, int h) : width(w), height(h), rgba(static_cast<std::size_t>(w) * h * 4, 0) {}
  [[nodiscard]] ImageView view() const {
    return {width, height, std::ptrdiff_t{width} * 4, rgba.data(), RowOrder::TopDown};
  }
  [[nodiscard]] std::uint8_t* pixel(int x, int y) {
    return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
  }
  [[nodiscard]] const std::uint8_t* pixel(int x, int y) const {
    return rgba.data() + (static_cast<std::size_t>(y) * width + x) * 4;
  }
};

// A cross-fade: into = weight · from + (1 − weight) · into, per byte,
// rounded (premultiplied or opaque RGBA blend linearly). Same size.
void crossFade(Image& into, const Image& from, double weight);

// A tightly packed top-down copy of any view.
[[nodiscard]] Image copyTopDown(const ImageView& view);

}  // namespace rollspin::media
