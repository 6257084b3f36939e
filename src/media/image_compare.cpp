#include "media/image_compare.hpp"

#include <algorithm>
#include <cstdlib>

namespace rollspin::media {

int ImageDifference::maxOverall() const { return *std::max_element(maxDelta.begin(), maxDelta.end()); }

double ImageDifference::meanOverall() const {
  return (meanDelta[0] + meanDelta[1] + meanDelta[2] + meanDelta[3]) / 4.0;
}

ImageDifference compareImages(const ImageView& a, const ImageView& b) {
  ImageDifference d;
  std::array<std::int64_t, 4> sums{};
  for (int y = 0; y < a.height; ++y) {
    const std::uint8_t* ra = a.rowFromTop(y);
    const std::uint8_t* rb = b.rowFromTop(y);
    for (int x = 0; x < a.width; ++x) {
      bool differs = false;
      for (int c = 0; c < 4; ++c) {
        const int delta = std::abs(int(ra[x * 4 + c]) - int(rb[x * 4 + c]));
        d.maxDelta[c] = std::max(d.maxDelta[c], delta);
        sums[c] += delta;
        differs = differs || delta != 0;
      }
      d.differingPixels += differs ? 1 : 0;
    }
  }
  const double count = std::max<double>(1.0, double(a.width) * a.height);
  for (int c = 0; c < 4; ++c) d.meanDelta[c] = double(sums[c]) / count;
  return d;
}

Image differenceHeatMap(const ImageView& a, const ImageView& b, int fullScale) {
  Image out(a.width, a.height);
  for (int y = 0; y < a.height; ++y) {
    const std::uint8_t* ra = a.rowFromTop(y);
    const std::uint8_t* rb = b.rowFromTop(y);
    for (int x = 0; x < a.width; ++x) {
      int delta = 0;
      for (int c = 0; c < 4; ++c) delta = std::max(delta, std::abs(int(ra[x * 4 + c]) - int(rb[x * 4 + c])));
      std::uint8_t* p = out.pixel(x, y);
      if (delta == 0) {
        const int grey = (int(ra[0]) + ra[1] + ra[2]) / 12;  // dim context
        p[0] = p[1] = p[2] = static_cast<std::uint8_t>(grey);
      } else {
        // Ramp: 0 → blue, 1/3 → red, 2/3 → yellow, 1 → white; any
        // difference at all is at least clearly blue.
        const double t = std::clamp(double(delta) / fullScale, 0.0, 1.0);
        const double r = std::clamp(3.0 * t, 0.0, 1.0);
        const double g = std::clamp(3.0 * t - 1.0, 0.0, 1.0);
        const double bl = t < 1.0 / 3.0 ? 1.0 - 3.0 * t * 0.5 : std::clamp(3.0 * t - 2.0, 0.0, 1.0);
        p[0] = static_cast<std::uint8_t>(80 + 175 * r);
        p[1] = static_cast<std::uint8_t>(255 * g);
        p[2] = static_cast<std::uint8_t>(255 * bl);
      }
      p[3] = 255;
    }
  }
  return out;
}

}  // namespace rollspin::media
