#include "media/image_compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <vector>

namespace rollspin::media {

int ImageDifference::maxOverall() const { return *std::max_element(maxDelta.begin(), maxDelta.end()); }

double ImageDifference::meanOverall() const {
  return (meanDelta[0] + meanDelta[1] + meanDelta[2] + meanDelta[3]) / 4.0;
}

std::int64_t ImageDifference::pixelsAbove(int levels) const {
  std::int64_t count = 0;
  for (int d = std::max(0, levels + 1); d < 256; ++d) count += deltaHistogram[static_cast<std::size_t>(d)];
  return count;
}

ImageDifference compareImages(const ImageView& a, const ImageView& b) {
  ImageDifference d;
  std::array<std::int64_t, 4> sums{};
  for (int y = 0; y < a.height; ++y) {
    const std::uint8_t* ra = a.rowFromTop(y);
    const std::uint8_t* rb = b.rowFromTop(y);
    for (int x = 0; x < a.width; ++x) {
      int largest = 0;
      for (int c = 0; c < 4; ++c) {
        const int delta = std::abs(int(ra[x * 4 + c]) - int(rb[x * 4 + c]));
        d.maxDelta[c] = std::max(d.maxDelta[c], delta);
        sums[c] += delta;
        largest = std::max(largest, delta);
      }
      d.differingPixels += largest != 0 ? 1 : 0;
      ++d.deltaHistogram[static_cast<std::size_t>(largest)];
    }
  }
  const double count = std::max<double>(1.0, double(a.width) * a.height);
  for (int c = 0; c < 4; ++c) d.meanDelta[c] = double(sums[c]) / count;
  return d;
}

namespace {

double luma(const std::uint8_t* p) { return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]; }

// Separable Gaussian blur (11 taps, σ = 1.5, normalised), edges replicated.
std::vector<double> gaussianBlur(const std::vector<double>& in, int w, int h) {
  constexpr int radius = 5;
  std::array<double, 2 * radius + 1> taps{};
  double total = 0.0;
  for (int k = -radius; k <= radius; ++k) total += taps[k + radius] = std::exp(-k * k / (2.0 * 1.5 * 1.5));
  for (double& t : taps) t /= total;
  std::vector<double> rows(in.size()), out(in.size());
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0.0;
      for (int k = -radius; k <= radius; ++k)
        s += taps[k + radius] * in[std::size_t(y) * w + std::clamp(x + k, 0, w - 1)];
      rows[std::size_t(y) * w + x] = s;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double s = 0.0;
      for (int k = -radius; k <= radius; ++k)
        s += taps[k + radius] * rows[std::size_t(std::clamp(y + k, 0, h - 1)) * w + x];
      out[std::size_t(y) * w + x] = s;
    }
  return out;
}

}  // namespace

double structuralSimilarity(const ImageView& a, const ImageView& b) {
  const int w = a.width, h = a.height;
  if (w <= 0 || h <= 0) return 1.0;
  const std::size_t n = std::size_t(w) * h;
  std::vector<double> ya(n), yb(n), aa(n), bb(n), ab(n);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = std::size_t(y) * w + x;
      ya[i] = luma(a.rowFromTop(y) + x * 4);
      yb[i] = luma(b.rowFromTop(y) + x * 4);
      aa[i] = ya[i] * ya[i];
      bb[i] = yb[i] * yb[i];
      ab[i] = ya[i] * yb[i];
    }
  const auto ma = gaussianBlur(ya, w, h), mb = gaussianBlur(yb, w, h);
  const auto saa = gaussianBlur(aa, w, h), sbb = gaussianBlur(bb, w, h), sab = gaussianBlur(ab, w, h);
  constexpr double c1 = (0.01 * 255) * (0.01 * 255), c2 = (0.03 * 255) * (0.03 * 255);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double varA = saa[i] - ma[i] * ma[i], varB = sbb[i] - mb[i] * mb[i], cov = sab[i] - ma[i] * mb[i];
    sum +=
        ((2.0 * ma[i] * mb[i] + c1) * (2.0 * cov + c2)) / ((ma[i] * ma[i] + mb[i] * mb[i] + c1) * (varA + varB + c2));
  }
  return sum / double(n);
}

Image differenceHeatMap(const ImageView& a, const ImageView& b, int fullScale) {
  Image out(std::max(a.width, b.width), std::max(a.height, b.height));
  for (int y = 0; y < out.height; ++y) {
    for (int x = 0; x < out.width; ++x) {
      std::uint8_t* p = out.pixel(x, y);
      p[3] = 255;
      const bool inA = x < a.width && y < a.height, inB = x < b.width && y < b.height;
      if (!inA || !inB) {  // only one image has this pixel
        p[0] = 255;
        p[1] = 0;
        p[2] = 255;
        continue;
      }
      const std::uint8_t* pa = a.rowFromTop(y) + x * 4;
      const std::uint8_t* pb = b.rowFromTop(y) + x * 4;
      int delta = 0;
      for (int c = 0; c < 4; ++c) delta = std::max(delta, std::abs(int(pa[c]) - int(pb[c])));
      if (delta == 0) {
        // This pixel of A, dimmed: the picture stays recognisable under the colours.
        p[0] = p[1] = p[2] = static_cast<std::uint8_t>(std::lround(luma(pa) / 4.0));
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
    }
  }
  return out;
}

}  // namespace rollspin::media
