// Image comparison for golden tests and `rollspin compare`: per-channel
// maximum and mean absolute difference (0–255 levels), the number of pixels
// where any channel differs, and a heat-map image of the difference.
#pragma once

#include <array>
#include <cstdint>

#include "media/image_view.hpp"

namespace rollspin::media {

struct ImageDifference {
  std::array<int, 4> maxDelta{};      // per channel R, G, B, A
  std::array<double, 4> meanDelta{};  // per channel, over all pixels
  std::int64_t differingPixels = 0;   // pixels with any channel differing
  [[nodiscard]] int maxOverall() const;
  [[nodiscard]] double meanOverall() const;  // mean of the channel means
};

// Preconditions: equal sizes (the caller reports size mismatches).
[[nodiscard]] ImageDifference compareImages(const ImageView& a, const ImageView& b);

// Heat map: black where equal, then blue → red → yellow → white with the
// largest channel difference (scaled so `fullScale` levels is white); the
// reference shows through as a dim grey so the location is recognisable.
[[nodiscard]] Image differenceHeatMap(const ImageView& a, const ImageView& b, int fullScale = 64);

}  // namespace rollspin::media
