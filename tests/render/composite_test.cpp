// The CPU composite (render/composite.hpp): out = c + (1 − a)·backdrop per
// channel on premultiplied words, covered pixels kept, empty ones the
// backdrop's; and the sRGB encoding of a backdrop. No GL.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>

#include "render/composite.hpp"

namespace rollspin::render {
namespace {

std::uint32_t word(std::uint32_t r, std::uint32_t g, std::uint32_t b, std::uint32_t a) {
  return r | (g << 8u) | (b << 16u) | (a << 24u);
}

TEST(Composite, CoveredPixelsKeepTheirWordAndEmptyOnesTakeTheBackdrop) {
  const std::array<std::uint32_t, 3> in{word(10, 20, 30, 255), 0u, word(1, 2, 3, 255)};
  std::array<std::uint32_t, 3> out{};
  compositeSpan(in.data(), in.data() + in.size(), out.data(), glm::vec3(1.0f, 0.5f, 0.0f), 255u);
  EXPECT_EQ(out[0], in[0]);
  EXPECT_EQ(out[2], in[2]);
  // 0.5 · 255 = 127.5 rounds to 128.
  EXPECT_EQ(out[1], word(255, 128, 0, 255));
}

TEST(Composite, APartlyCoveredPixelIsItsColourOverTheBackdrop) {
  // Premultiplied (40, 0, 200) at a = 100 over (0.2, 0.4, 1): 155 uncovered.
  const std::uint32_t in = word(40, 0, 200, 100);
  std::uint32_t out = 0;
  compositeSpan(&in, &in + 1, &out, glm::vec3(0.2f, 0.4f, 1.0f), 255u);
  const auto behind = [](float b) { return static_cast<std::uint32_t>(b * 155.0f + 0.5f); };
  EXPECT_EQ(out, word(40 + behind(0.2f), 0 + behind(0.4f), std::min(200u + behind(1.0f), 255u), 255));
  EXPECT_EQ(out >> 16u & 0xFFu, 255u);  // 200 + 155 clamped
  // A transparent list keeps the scene's alpha.
  compositeSpan(&in, &in + 1, &out, glm::vec3(0.0f), 0u);
  EXPECT_EQ(out, in);
}

TEST(Composite, SrgbEncodingFollowsThePiecewiseCurve) {
  const glm::vec3 e = encodeSrgb(glm::vec3(0.0f, 0.002f, 0.5f));
  EXPECT_FLOAT_EQ(e.x, 0.0f);
  EXPECT_FLOAT_EQ(e.y, 12.92f * 0.002f);
  EXPECT_NEAR(e.z, 1.055f * std::pow(0.5f, 1.0f / 2.4f) - 0.055f, 1e-6f);
  EXPECT_NEAR(e.z, 0.7354f, 1e-4f);
  const glm::vec3 clamped = encodeSrgb(glm::vec3(-1.0f, 2.0f, 1.0f));
  EXPECT_FLOAT_EQ(clamped.x, 0.0f);
  EXPECT_NEAR(clamped.y, 1.0f, 1e-6f);
  EXPECT_NEAR(clamped.z, 1.0f, 1e-6f);
}

}  // namespace
}  // namespace rollspin::render
