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
  // splits it into two congruent lobes, drawn as a band of half-width
  // kSeamHalfWidth around kSeamSamples points of it.
  constexpr double a = 0.72, b = 0.28;
  constexpr int kSeamSamples = 96 * 24;
  constexpr double kSeamHalfWidth = 0.045;  // radians on the unit sphere
  const double c = 2.0 * std::sqrt(a * b);
  const double texel = std::numbers::pi / height;
  // Only texels nearer than this to a seam sample take any white (the edge
  // is smoothed over 1.5 texels, half of it outside the band).
  const double reach = kSeamHalfWidth + texel;
  const double cosReach = std::cos(reach);
  auto direction = [&](int x, int y) {
    const double theta = std::numbers::pi * (y + 0.5) / height;
    const double phi = 2.0 * std::numbers::pi * (x + 0.5) / width - std::numbers::pi;
    return glm::dvec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  };
  // The nearest seam sample's cosine for every texel, found by visiting from
  // each sample only the texels within `reach` of it (a band of rows, and in
  // each row the longitudes within reach): the same maximum as comparing
  // every texel with every sample, for the texels the band can touch, at a
  // small fraction of the work.
  std::vector<double> nearestCos(static_cast<std::size_t>(width) * height, -2.0);
  for (int k = 0; k < kSeamSamples; ++k) {
    const double t = 2.0 * std::numbers::pi * k / kSeamSamples;
    const glm::dvec3 p(a * std::cos(t) + b * std::cos(3 * t), a * std::sin(t) - b * std::sin(3 * t),
                       c * std::sin(2 * t));
    const double thetaP = std::acos(std::clamp(p.z, -1.0, 1.0));
    const double phiP = std::atan2(p.y, p.x);
    const int yFirst = std::max(0, int(std::floor((thetaP - reach) / texel - 0.5)));
    const int yLast = std::min(height - 1, int(std::ceil((thetaP + reach) / texel - 0.5)));
    for (int y = yFirst; y <= yLast; ++y) {
      const double theta = std::numbers::pi * (y + 0.5) / height;
      // cos d = cos θ cos θp + sin θ sin θp cos Δφ ≥ cos(reach)
      const double sines = std::sin(theta) * std::sin(thetaP);
      const double needed = sines > 0 ? (cosReach - std::cos(theta) * std::cos(thetaP)) / sines : -2.0;
      if (needed > 1.0) continue;
      const double halfSpan = needed <= -1.0 ? std::numbers::pi : std::acos(needed);
      const double xCentre = (phiP + std::numbers::pi) * width / (2.0 * std::numbers::pi) - 0.5;
      const double xHalf = halfSpan * width / (2.0 * std::numbers::pi);
      const int xFirst = int(std::floor(xCentre - xHalf)) - 1, xLast = int(std::ceil(xCentre + xHalf)) + 1;
      const int count = std::min(width, xLast - xFirst + 1);
      for (int i = 0; i < count; ++i) {
        const int x = ((xFirst + i) % width + width) % width;
        double& best = nearestCos[static_cast<std::size_t>(y) * width + x];
        best = std::max(best, glm::dot(direction(x, y), p));
      }
    }
  }
  auto tex = std::make_shared<TextureImage>();
  tex->width = width;
  tex->height = height;
  tex->rgba.resize(static_cast<std::size_t>(width) * height * 4);
  constexpr double felt[3] = {0.80, 0.88, 0.22};
  for (std::size_t i = 0; i < nearestCos.size(); ++i) {
    const double dist = nearestCos[i] < cosReach ? reach * 2.0 : std::acos(std::clamp(nearestCos[i], -1.0, 1.0));
    const double seamWeight = std::clamp((kSeamHalfWidth - dist) / (1.5 * texel) + 0.5, 0.0, 1.0);
    std::uint8_t* px = &tex->rgba[i * 4];
    for (int ch = 0; ch < 3; ++ch) {
      const double white = ch == 2 ? 0.92 : 0.97;
      const double v = (1.0 - seamWeight) * felt[ch] + seamWeight * white;
      px[ch] = static_cast<std::uint8_t>(std::lround(255.0 * std::clamp(v, 0.0, 1.0)));
    }
    px[3] = 255;
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

std::shared_ptr<const TextureImage> checkerTexture(glm::vec3 color, glm::vec3 color2, int cellPixels) {
  // The sRGB transfer function (IEC 61966-2-1), rounded to bytes.
  auto encode = [](float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float srgb = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(255.0f * srgb));
  };
  auto image = std::make_shared<TextureImage>();
  image->width = image->height = 2 * cellPixels;
  image->rgba.reserve(static_cast<std::size_t>(image->width) * image->height * 4);
  for (int y = 0; y < image->height; ++y)
    for (int x = 0; x < image->width; ++x) {
      const glm::vec3& c = ((x / cellPixels) + (y / cellPixels)) % 2 == 0 ? color : color2;
      image->rgba.insert(image->rgba.end(), {encode(c.r), encode(c.g), encode(c.b), 255});
    }
  return image;
}

}  // namespace rollspin::render
