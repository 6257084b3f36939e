// Image comparison for golden tests and `rollspin compare`: per-channel
// maximum and mean absolute difference (0–255 levels), how many pixels differ
// by more than a given level, the structural similarity (SSIM) of the
// luminance, and a heat-map image of the difference.
#pragma once

#include <array>
#include <cstdint>

#include "media/image_view.hpp"

namespace rollspin::media {

struct ImageDifference {
  std::array<int, 4> maxDelta{};      // per channel R, G, B, A
  std::array<double, 4> meanDelta{};  // per channel, over all pixels
  std::int64_t differingPixels = 0;   // pixels with any channel differing
  // deltaHistogram[d]: pixels whose largest channel difference is d.
  std::array<std::int64_t, 256> deltaHistogram{};
  [[nodiscard]] int maxOverall() const;
  [[nodiscard]] double meanOverall() const;  // mean of the channel means
  // Pixels whose largest channel difference exceeds `levels`.
  [[nodiscard]] std::int64_t pixelsAbove(int levels) const;
};

// Preconditions: equal sizes (the caller reports size mismatches).
[[nodiscard]] ImageDifference compareImages(const ImageView& a, const ImageView& b);

// Mean SSIM (Wang, Bovik, Sheikh & Simoncelli 2004) of the luma
// Y = 0.299 R + 0.587 G + 0.114 B (alpha ignored): local means, variances and
// covariance under an 11x11 Gaussian window of σ = 1.5 (edges replicated),
// C1 = (0.01·255)², C2 = (0.03·255)², averaged over every pixel. 1 for equal
// images; about 0.98–0.99 for faint noise of a few levels, lower for moved or
// missing shapes. Preconditions: equal sizes.
[[nodiscard]] double structuralSimilarity(const ImageView& a, const ImageView& b);

// Heat map, max(width) x max(height): a faint copy of A (a quarter of its
// luma, in grey) where the images agree; blue → red → yellow → white with
// the largest channel difference (scaled so `fullScale` levels is white)
// where they differ; magenta where only one image has pixels (a size
// mismatch).
[[nodiscard]] Image differenceHeatMap(const ImageView& a, const ImageView& b, int fullScale = 64);

}  // namespace rollspin::media
