// media/: PNG round trips, row order, comparison metrics and the heat map.
#include <gtest/gtest.h>

#include <fstream>

#include "core/error.hpp"
#include "media/image_compare.hpp"
#include "media/image_io.hpp"
#include "support/cli_runner.hpp"

namespace rollspin::media {
namespace {

Image gradient(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(x * 7);
      p[1] = static_cast<std::uint8_t>(y * 11);
      p[2] = static_cast<std::uint8_t>((x + y) * 3);
      p[3] = static_cast<std::uint8_t>(255 - x);
    }
  return img;
}

TEST(ImageView, BottomUpRowsAreReadTopFirst) {
  const Image img = gradient(4, 3);
  // Store the rows bottom-up, as GL returns them.
  std::vector<std::uint8_t> flipped;
  for (int y = img.height - 1; y >= 0; --y) flipped.insert(flipped.end(), img.pixel(0, y), img.pixel(0, y) + 16);
  const ImageView view{4, 3, 16, flipped.data(), RowOrder::BottomUp};
  EXPECT_EQ(copyTopDown(view).rgba, img.rgba);
}

TEST(ImageIo, PngRoundTripKeepsRgbaExactly) {
  const auto dir = test::freshTempDir("media_png");
  const Image img = gradient(17, 9);
  writePng(dir / "a.png", img.view(), PngChannels::Rgba);
  const Image back = loadImage(dir / "a.png", {});
  EXPECT_EQ(back.width, 17);
  EXPECT_EQ(back.height, 9);
  EXPECT_EQ(back.rgba, img.rgba);
}

TEST(ImageIo, RgbPngDropsAlpha) {
  const auto dir = test::freshTempDir("media_rgb");
  const Image img = gradient(5, 5);
  writePng(dir / "a.png", img.view(), PngChannels::Rgb);
  const Image back = loadImage(dir / "a.png", {});
  for (int i = 0; i < 25; ++i) {
    EXPECT_EQ(back.rgba[i * 4 + 0], img.rgba[i * 4 + 0]);
    EXPECT_EQ(back.rgba[i * 4 + 3], 255);
  }
}

TEST(ImageIo, MissingAndCorruptFilesAreBadInput) {
  const auto dir = test::freshTempDir("media_bad");
  try {
    (void)loadImage(dir / "missing.png", SourceLoc{"scene.toml", 3, 1});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_EQ(e.where().line, 3);
  }
  std::ofstream(dir / "corrupt.png") << "\x89PNG not really";
  EXPECT_THROW((void)loadImage(dir / "corrupt.png", {}), Error);
}

TEST(ImageCompare, IdenticalImagesHaveNoDifference) {
  const Image img = gradient(8, 8);
  const ImageDifference d = compareImages(img.view(), img.view());
  EXPECT_EQ(d.maxOverall(), 0);
  EXPECT_EQ(d.meanOverall(), 0.0);
  EXPECT_EQ(d.differingPixels, 0);
}

TEST(ImageCompare, ReportsPerChannelMaxMeanAndCount) {
  const Image a = gradient(10, 10);
  Image b = a;
  b.pixel(3, 4)[1] = static_cast<std::uint8_t>(a.pixel(3, 4)[1] + 20);
  b.pixel(7, 1)[2] = static_cast<std::uint8_t>(a.pixel(7, 1)[2] + 5);
  const ImageDifference d = compareImages(a.view(), b.view());
  EXPECT_EQ(d.maxDelta[0], 0);
  EXPECT_EQ(d.maxDelta[1], 20);
  EXPECT_EQ(d.maxDelta[2], 5);
  EXPECT_DOUBLE_EQ(d.meanDelta[1], 20.0 / 100.0);
  EXPECT_EQ(d.differingPixels, 2);
  const Image heat = differenceHeatMap(a.view(), b.view());
  EXPECT_EQ(heat.width, 10);
  // A differing pixel is brighter than an equal one.
  EXPECT_GT(int(heat.pixel(3, 4)[0]) + heat.pixel(3, 4)[1] + heat.pixel(3, 4)[2],
            int(heat.pixel(0, 0)[0]) + heat.pixel(0, 0)[1] + heat.pixel(0, 0)[2]);
}

}  // namespace
}  // namespace rollspin::media
