// The tennis-ball texture: each texel's seam distance comes from the seam
// samples near it only; it must be what comparing the texel with every
// sample gives (the definition), and the seam must split the felt in two.
#include "render/procedural_textures.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

namespace rollspin::render {
namespace {

// The definition, slowly: the colour of texel (x, y) from its distance to
// the nearest of all 2304 seam samples.
std::array<int, 3> texelByDefinition(int width, int x, int y) {
  const int height = width / 2;
  constexpr double a = 0.72, b = 0.28;
  const double c = 2.0 * std::sqrt(a * b);
  const double theta = std::numbers::pi * (y + 0.5) / height;
  const double phi = 2.0 * std::numbers::pi * (x + 0.5) / width - std::numbers::pi;
  const glm::dvec3 d(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
  double best = -1.0;
  for (int k = 0; k < 96 * 24; ++k) {
    const double t = 2.0 * std::numbers::pi * k / (96 * 24);
    const glm::dvec3 p(a * std::cos(t) + b * std::cos(3 * t), a * std::sin(t) - b * std::sin(3 * t),
                       c * std::sin(2 * t));
    best = std::max(best, glm::dot(d, p));
  }
  const double dist = std::acos(std::clamp(best, -1.0, 1.0));
  const double weight = std::clamp((0.045 - dist) / (1.5 * std::numbers::pi / height) + 0.5, 0.0, 1.0);
  const double felt[3] = {0.80, 0.88, 0.22}, white[3] = {0.97, 0.97, 0.92};
  std::array<int, 3> rgb{};
  for (int ch = 0; ch < 3; ++ch) rgb[ch] = int(std::lround(255.0 * ((1.0 - weight) * felt[ch] + weight * white[ch])));
  return rgb;
}

TEST(TennisBall, EveryTexelIsWhatTheNearestOfAllSeamSamplesGives) {
  // Every texel of a small texture, and a deterministic spread of the
  // default 1024-wide one's (its poles and seam crossings included).
  for (const int width : {128, 1024}) {
    const auto texture = tennisBallTexture(width);
    ASSERT_EQ(texture->width, width);
    ASSERT_EQ(texture->height, width / 2);
    int checked = 0, seam = 0;
    const int step = width == 128 ? 1 : 61;
    for (int y = 0; y < width / 2; y += width == 128 ? 1 : 7)
      for (int x = y % step; x < width; x += step) {
        const std::array<int, 3> expected = texelByDefinition(width, x, y);
        const std::uint8_t* px = &texture->rgba[(std::size_t(y) * width + x) * 4];
        for (int ch = 0; ch < 3; ++ch)
          ASSERT_EQ(int(px[ch]), expected[ch]) << "width " << width << " texel " << x << "," << y;
        EXPECT_EQ(int(px[3]), 255);
        seam += expected[2] > 100;
        ++checked;
      }
    EXPECT_GT(seam, checked / 50) << "the seam's white should be a visible share of the texels";
    EXPECT_LT(seam, checked / 3);
  }
}

TEST(TennisBall, IsDrawnOncePerWidth) {
  EXPECT_EQ(tennisBallTexture(64).get(), tennisBallTexture(64).get());
  EXPECT_NE(tennisBallTexture(64).get(), tennisBallTexture(128).get());
}

}  // namespace
}  // namespace rollspin::render
