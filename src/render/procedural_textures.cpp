#include "render/procedural_textures.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <mutex>
#include <numbers>
#include <vector>

namespace rollspin::render {

namespace {

std::shared_ptr<const TextureImage> drawTennisBall(int width) {
  const int height = width / 2;
  // The classic seam: (a cos t + b cos 3t, a sin t − b sin 3t, 2√(ab) sin 2t)
  // has constant norm a + b = 1 — a closed curve on the unit sphere that
  // splits it into two congruent lobes.
  constexpr double a = 0.72, b = 0.28;
  const double c = 2.0 * std::sqrt(a * b);
  auto seamPoint = [&](double t) {
    return glm::dvec3(a * std::cos(t) + b * std::cos(3 * t), a * std::sin(t) - b * std::sin(3 * t), c * std::sin(2 * t));
  };
  // Nearest seam point: a coarse scan, then a fine scan around the best
  // coarse sample (the seam is smooth, so this finds the true nearest point).
  constexpr int kCoarse = 96, kFine = 24;
  std::vector<glm::dvec3> fine;
  for (int k = 0; k < kCoarse * kFine; ++k) fine.push_back(seamPoint(2.0 * std::numbers::pi * k / (kCoarse * kFine)));
  auto tex = std::make_shared<TextureImage>();
  tex->width = width;
  tex->height = height;
  tex->rgba.resize(static_cast<std::size_t>(width) * height * 4);
  constexpr double kSeamHalfWidth = 0.045;  // radians on the unit sphere
  for (int y = 0; y < height; ++y) {
    const double theta = std::numbers::pi * (y + 0.5) / height;
    for (int x = 0; x < width; ++x) {
      const double phi = 2.0 * std::numbers::pi * (x + 0.5) / width - std::numbers::pi;
      const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      int bestK = 0;
      double best = -2.0;
      for (int k = 0; k < kCoarse; ++k) {
        const double dot = glm::dot(d, fine[static_cast<std::size_t>(k * kFine)]);
        if (dot > best) {
          best = dot;
          bestK = k;
        }
      }
      constexpr int kAll = kCoarse * kFine;
      for (int f = -kFine; f <= kFine; ++f)
        best = std::max(best, glm::dot(d, fine[static_cast<std::size_t>((bestK * kFine + f + kAll) % kAll)]));
      const double dist = std::acos(std::clamp(best, -1.0, 1.0));
      // Smooth edge over ~1.5 texels.
      const double texel = std::numbers::pi / height;
      const double seamWeight = std::clamp((kSeamHalfWidth - dist) / (1.5 * texel) + 0.5, 0.0, 1.0);
      const double felt[3] = {0.80, 0.88, 0.22};
      std::uint8_t* px = &tex->rgba[(static_cast<std::size_t>(y) * width + x) * 4];
      for (int ch = 0; ch < 3; ++ch) {
        const double white = ch == 2 ? 0.92 : 0.97;
        const double v = (1.0 - seamWeight) * felt[ch] + seamWeight * white;
        px[ch] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0)));
      }
      px[3] = 255;
    }
  }
  return tex;
}

}  // namespace

// Drawn once per width and shared (the image is immutable): a process that
// makes a drawer per figure size or per clip does not pay for it again.
std::shared_ptr<const TextureImage> tennisBallTexture(int width) {
  static std::mutex mutex;
  static std::map<int, std::shared_ptr<const TextureImage>> drawn;
  const std::lock_guard<std::mutex> lock(mutex);
  auto& texture = drawn[width];
  if (!texture) texture = drawTennisBall(width);
  return texture;
}

}  // namespace rollspin::render
