// Yuv420Converter: the BT.709 limited-range values of known colours, every
// colour within rounding of the matrix in double precision, and a frame
// converted after others (only its changed blocks) equal to the same frame
// converted whole, for rows stored either way and sizes that are not a
// multiple of the block.
#include "media/yuv420_converter.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <tuple>
#include <vector>

namespace rollspin {
namespace {

struct Planes {
  int width, height;
  std::vector<std::uint8_t> y, u, v, a;
  Planes(int w, int h, bool alpha) : width(w), height(h), y(w * h), u(w * h / 4), v(w * h / 4), a(alpha ? w * h : 0) {}
  media::Yuv420Planes view() {
    return {y.data(), u.data(), v.data(), a.empty() ? nullptr : a.data(), width, width / 2, width / 2, width};
  }
  bool operator==(const Planes&) const = default;
};

// Studio-range BT.709 values of the primaries (ITU-R BT.709 colour bars).
TEST(Yuv420Converter, KnownColours) {
  struct Case {
    int r, g, b, y, cb, cr;
  };
  for (const Case& c :
       {Case{255, 255, 255, 235, 128, 128}, Case{0, 0, 0, 16, 128, 128}, Case{128, 128, 128, 126, 128, 128},
        Case{255, 0, 0, 63, 102, 240}, Case{0, 255, 0, 173, 42, 26}, Case{0, 0, 255, 32, 240, 118}}) {
    EXPECT_EQ(media::bt709Luma(c.r, c.g, c.b), c.y) << c.r << "," << c.g << "," << c.b;
    EXPECT_EQ(media::bt709Cb(4 * c.r, 4 * c.g, 4 * c.b), c.cb) << c.r << "," << c.g << "," << c.b;
    EXPECT_EQ(media::bt709Cr(4 * c.r, 4 * c.g, 4 * c.b), c.cr) << c.r << "," << c.g << "," << c.b;
  }
}

// The fixed-point result is the matrix's value rounded, give or take the
// coefficients' own rounding (at most 1.5 · 2^-16 each, × 255 < 0.006).
TEST(Yuv420Converter, WithinRoundingOfTheMatrix) {
  const double kr = 0.2126, kb = 0.0722, kg = 1 - kr - kb;
  double worst = 0.0;
  for (int r = 0; r < 256; r += 3)
    for (int g = 0; g < 256; g += 5)
      for (int b = 0; b < 256; b += 7) {
        const double luma = kr * r + kg * g + kb * b;
        const double y = 16 + 219.0 / 255 * luma;
        const double cb = 128 + 224.0 / 255 * (b - luma) / (2 * (1 - kb));
        const double cr = 128 + 224.0 / 255 * (r - luma) / (2 * (1 - kr));
        worst = std::max({worst, std::abs(media::bt709Luma(r, g, b) - y),
                          std::abs(media::bt709Cb(4 * r, 4 * g, 4 * b) - cb),
                          std::abs(media::bt709Cr(4 * r, 4 * g, 4 * b) - cr)});
      }
  EXPECT_LE(worst, 0.5 + 0.006);
}

// Chroma comes from the mean of each 2×2 block; luma and alpha per pixel.
TEST(Yuv420Converter, ChromaIsTheBlockMean) {
  media::Image image(2, 2);
  const std::uint8_t colours[4][4] = {{255, 0, 0, 10}, {0, 255, 0, 20}, {0, 0, 255, 30}, {255, 255, 255, 40}};
  for (int k = 0; k < 4; ++k) std::copy_n(colours[k], 4, image.pixel(k % 2, k / 2));
  Planes out(2, 2, true);
  media::Yuv420Converter converter(2, 2);
  EXPECT_EQ(converter.convert(image.view(), out.view()), 4);
  EXPECT_EQ(out.y, (std::vector<std::uint8_t>{63, 173, 32, 235}));
  EXPECT_EQ(out.u[0], media::bt709Cb(510, 510, 510));
  EXPECT_EQ(out.v[0], media::bt709Cr(510, 510, 510));
  EXPECT_EQ(out.u[0], 128);
  EXPECT_EQ(out.a, (std::vector<std::uint8_t>{10, 20, 30, 40}));
}

// Frames that change in small rectangles (one pixel, alpha alone, a band),
// not at all, or everywhere; stored top-down or bottom-up. After each, the
// planes must equal a fresh one-thread converter's, and only changed blocks
// convert, whether the frame is converted in one band or several threads'.
TEST(Yuv420Converter, ChangedBlocksOnlyGiveTheWholeFrame) {
  for (const auto& [width, height, threads] : {std::tuple{70, 6, 1}, std::tuple{64, 48, 1}, std::tuple{2, 2, 1},
                                               std::tuple{96, 260, 3}, std::tuple{64, 48, 3}}) {
    SCOPED_TRACE(testing::Message() << width << "x" << height << ", " << threads << " threads");
    std::mt19937 random(width * 31 + height);
    std::uniform_int_distribution<int> level(0, 255);
    media::Image image(width, height);
    for (auto& byte : image.rgba) byte = static_cast<std::uint8_t>(level(random));

    Planes incremental(width, height, true);
    media::Yuv420Converter converter(width, height, threads);
    for (int frame = 0; frame < 12; ++frame) {
      long long expectedConverted = -1;
      if (frame == 3) {
        expectedConverted = 0;  // unchanged
      } else if (frame == 4) {
        image.pixel(width - 1, height - 1)[1] ^= 1;  // one pixel: its block
        const int blockWidth = width % 32 == 0 ? 32 : std::min(32, width % 32);
        expectedConverted = 2LL * blockWidth;
      } else if (frame == 5) {
        image.pixel(0, 0)[3] ^= 0x80;  // alpha alone
        expectedConverted = 2LL * std::min(32, width);
      } else if (frame == 8) {
        for (auto& byte : image.rgba) byte = static_cast<std::uint8_t>(level(random));
      } else if (frame > 0) {
        const int x0 = level(random) % width, y0 = level(random) % height;
        const int x1 = std::min(width, x0 + 1 + level(random) % 40), y1 = std::min(height, y0 + 1 + level(random) % 5);
        for (int y = y0; y < y1; ++y)
          for (int x = x0; x < x1; ++x) image.pixel(x, y)[level(random) % 4] = static_cast<std::uint8_t>(level(random));
      }
      // Odd frames are handed over bottom-up, as a GL read-back is.
      media::Image flipped(width, height);
      for (int y = 0; y < height; ++y) std::copy_n(image.pixel(0, y), width * 4, flipped.pixel(0, height - 1 - y));
      media::ImageView view = image.view();
      if (frame % 2 == 1)
        view = {width, height, std::ptrdiff_t{width} * 4, flipped.rgba.data(), media::RowOrder::BottomUp};

      const long long converted = converter.convert(view, incremental.view());
      if (frame == 0) {
        EXPECT_EQ(converted, static_cast<long long>(width) * height);
      }
      if (expectedConverted >= 0) {
        EXPECT_EQ(converted, expectedConverted) << "frame " << frame;
      }

      Planes whole(width, height, true);
      media::Yuv420Converter fresh(width, height);
      fresh.convert(image.view(), whole.view());
      ASSERT_TRUE(incremental == whole) << "frame " << frame << " differs from the same frame converted whole";
    }
  }
}

// forget(): the planes were replaced, so everything converts again.
TEST(Yuv420Converter, ForgetConvertsEverything) {
  media::Image image(64, 4);
  Planes out(64, 4, false);
  media::Yuv420Converter converter(64, 4);
  converter.convert(image.view(), out.view());
  EXPECT_EQ(converter.convert(image.view(), out.view()), 0);
  converter.forget();
  EXPECT_EQ(converter.convert(image.view(), out.view()), 64 * 4);
}

}  // namespace
}  // namespace rollspin
