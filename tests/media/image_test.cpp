// media/: PNG round trips, row order, comparison metrics and the heat map.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "media/image_compare.hpp"
#include "media/image_io.hpp"
#include "support/test_files.hpp"

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

// A cross-fade between two surfaces' views: the ends are the images
// themselves, the middle the rounded mean of each byte.
TEST(ImageView, CrossFadeWeighsEachByteLinearly) {
  const Image from = gradient(16, 9);
  Image black(16, 9);
  Image none = black, all = black, half = black;
  crossFade(none, from, 0.0);
  crossFade(all, from, 1.0);
  crossFade(half, from, 0.5);
  EXPECT_EQ(none.rgba, black.rgba);
  EXPECT_EQ(all.rgba, from.rgba);
  for (std::size_t i = 0; i < from.rgba.size(); ++i) ASSERT_EQ(half.rgba[i], (from.rgba[i] + 1) / 2) << i;
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

// Found by fuzz_image: a JPEG whose Huffman table counts 734 codes made
// Debian's stb_image (2.27) write past its 257-entry size list, in the
// header read that loading and the size check both do. Refused first.
TEST(ImageIo, JpegWithAnOversizedHuffmanTableIsBadInput) {
  // The second starts with a fill byte before SOI (FF FF D8), which
  // stb_image skips as it skips any fill before a marker (found by CI's
  // fuzz_image run).
  for (const char* seed : {"crash-dht-overflow.jpg", "crash-fill-before-soi.jpg"}) {
    const auto path = test::sourceDir() / "tests/fuzz/seeds/image" / seed;
    try {
      (void)loadImage(path, SourceLoc{"ball.texture"});
      ADD_FAILURE() << seed << ": expected an error";
    } catch (const Error& e) {
      EXPECT_EQ(e.exitCode(), 2) << seed;
      EXPECT_NE(std::string(e.what()).find("Huffman table of more than 256 codes"), std::string::npos)
          << seed << ": " << e.what();
    }
  }
}

// Found by CI's fuzz_image run: a 12x8 PNG whose first IDAT chunk is empty
// made stb_image (2.27) call memcpy with a null buffer and a length of 0
// (undefined, harmless; its implementation file is built without that one
// check, src/media/CMakeLists.txt). What follows the empty chunk is not a
// chunk stb_image knows: the file is bad input, refused with its name.
TEST(ImageIo, PngWithAnEmptyFirstIdatChunkIsBadInput) {
  const auto path = test::sourceDir() / "tests/fuzz/seeds/image/crash-empty-idat.png";
  try {
    (void)loadImage(path, SourceLoc{"ball.texture"});
    ADD_FAILURE() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_NE(std::string(e.what()).find("crash-empty-idat.png"), std::string::npos) << e.what();
  }
}

// Found by CI's fuzz_image run: a 200-byte PNG whose second IDAT chunk
// claims more bytes than the file has made stb_image (2.27) grow its data
// buffer to 2 GiB before reading. Refused first, naming the chunk; a PNG
// whose chunks all fit still loads (the seeds' own PNGs).
TEST(ImageIo, PngChunkLongerThanTheFileIsBadInput) {
  const auto path = test::sourceDir() / "tests/fuzz/seeds/image/oom-idat-longer-than-file.png";
  try {
    (void)loadImage(path, SourceLoc{"ball.texture"});
    ADD_FAILURE() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_NE(std::string(e.what()).find("chunk claims"), std::string::npos) << e.what();
  }
  for (const char* seed : {"rgba.png", "pal8.png", "rgb48be.png"}) {
    const Image img = loadImage(test::sourceDir() / "tests/fuzz/seeds/image" / seed, SourceLoc{"ball.texture"});
    EXPECT_GT(img.width, 0) << seed;
  }
}

// Found by fuzz_image: a JPEG whose scan uses an AC table that no DHT
// segment defined made stb_image (2.27) decode with uninitialised tables and
// read a symbol id of -16711698 far outside its list. Refused first; the
// JPEG files ffmpeg and rollspin itself write still load.
TEST(ImageIo, JpegScanWithAnUndefinedHuffmanTableIsBadInput) {
  const auto seeds = test::sourceDir() / "tests/fuzz/seeds/image";
  try {
    (void)loadImage(seeds / "crash-scan-undefined-huffman-table.jpg", SourceLoc{"ball.texture"});
    ADD_FAILURE() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_NE(std::string(e.what()).find("a Huffman table no DHT segment defined"), std::string::npos) << e.what();
  }
  for (const char* seed : {"gray.jpg", "yuv420.jpg", "yuv444.jpg"})
    EXPECT_GT(loadImage(seeds / seed, SourceLoc{"ball.texture"}).width, 0) << seed;
  const auto dir = test::freshTempDir("media_jpeg_guard");
  Image img(33, 17);
  for (std::size_t k = 0; k < img.rgba.size(); ++k) img.rgba[k] = static_cast<std::uint8_t>(k * 7);
  writeJpeg(dir / "own.jpg", img.view(), 90);
  EXPECT_EQ(loadImage(dir / "own.jpg", {}).width, 33);
}

// Every input the image fuzzer keeps (tests/fuzz/seeds/image: the kinds
// stb_image reads and every file that once crashed it) loads or is bad
// input, here too: under scripts/sanitize.sh this runs with ASan and UBSan.
// At the fuzzer's 2048 x 2048 limit, as fuzz_image decodes them (a seed
// claims 16384 x 16384, which a texture may have, and is 1 GiB to decode).
TEST(ImageIo, EveryFuzzSeedLoadsOrIsBadInput) {
  int loaded = 0, refused = 0;
  for (const auto& e : std::filesystem::directory_iterator(test::sourceDir() / "tests/fuzz/seeds/image")) {
    const std::string bytes = test::readFile(e.path());
    try {
      const Image img =
          decodeImage(bytes, e.path().filename().string(), SourceLoc{"ball.texture"}, std::int64_t{2048} * 2048);
      EXPECT_GT(img.width, 0) << e.path().filename();
      ++loaded;
    } catch (const Error& err) {
      EXPECT_EQ(err.exitCode(), 2) << e.path().filename() << ": " << err.what();
      ++refused;
    }
  }
  EXPECT_GE(loaded, 11);
  EXPECT_GE(refused, 6);
}

// A header may claim far more pixels than the file holds: refused before
// anything is allocated for them (20000 x 20000 grey: 400 MB, within the
// 1 GiB stb_image itself accepts, and 1.6 GB once expanded to RGBA).
TEST(ImageIo, HugeClaimedSizeIsRefusedBeforeDecoding) {
  std::string png = test::readFile(test::sourceDir() / "tests/fuzz/seeds/image/gray.png");
  ASSERT_GT(png.size(), 24u);
  for (const int offset : {16, 20}) {  // IHDR width and height, big-endian
    png[offset] = 0;
    png[offset + 1] = 0;
    png[offset + 2] = '\x4e';  // 20000 = 0x4e20
    png[offset + 3] = '\x20';
  }
  try {
    (void)decodeImage(png, "huge.png", SourceLoc{"huge.png"});
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("claims 20000x20000 pixels"), std::string::npos) << e.what();
  }
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

// The heat map of two equal images is A itself at a quarter of its luma
// (it was horizontal stripes of column 0's grey); a difference is coloured.
TEST(ImageCompare, HeatMapIsAFaintCopyOfAUnderTheDifferences) {
  Image a(6, 5);
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      std::uint8_t* p = a.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(40 * x);
      p[1] = static_cast<std::uint8_t>(50 * y);
      p[2] = static_cast<std::uint8_t>(200 - 30 * x);
      p[3] = 255;
    }
  const Image same = differenceHeatMap(a.view(), a.view());
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x < a.width; ++x) {
      const std::uint8_t* p = a.pixel(x, y);
      const int grey = static_cast<int>(std::lround((0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2]) / 4.0));
      for (int c = 0; c < 3; ++c) ASSERT_EQ(same.pixel(x, y)[c], grey) << x << "," << y;
    }
  Image b = a;
  b.pixel(2, 3)[0] = static_cast<std::uint8_t>(a.pixel(2, 3)[0] + 1);
  const Image one = differenceHeatMap(a.view(), b.view());
  EXPECT_GT(one.pixel(2, 3)[2], 200) << "a one-level difference is clearly blue";
  EXPECT_EQ(one.pixel(1, 3)[0], same.pixel(1, 3)[0]);
  // Different sizes: the union, magenta where only one image has pixels.
  const Image wide(8, 4);
  const Image both = differenceHeatMap(a.view(), wide.view());
  EXPECT_EQ(both.width, 8);
  EXPECT_EQ(both.height, 5);
  EXPECT_EQ(both.pixel(7, 0)[0], 255);
  EXPECT_EQ(both.pixel(7, 0)[1], 0);
  EXPECT_EQ(both.pixel(0, 4)[2], 255);
}

TEST(ImageCompare, CountsPixelsAboveALevel) {
  Image a = gradient(10, 10), b = a;
  b.pixel(0, 0)[0] = static_cast<std::uint8_t>(a.pixel(0, 0)[0] ^ 3);  // 1..3 levels
  b.pixel(5, 5)[1] = static_cast<std::uint8_t>(a.pixel(5, 5)[1] + 10);
  const ImageDifference d = compareImages(a.view(), b.view());
  EXPECT_EQ(d.pixelsAbove(0), 2);
  EXPECT_EQ(d.pixelsAbove(3), 1);
  EXPECT_EQ(d.pixelsAbove(10), 0);
}

// SSIM: 1 for equal images, symmetric, near 1 for faint noise, far lower for
// a moved shape; checked against the closed form for constant images.
TEST(ImageCompare, StructuralSimilarity) {
  Image a(40, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      const bool square = x >= 10 && x < 20 && y >= 10 && y < 20;
      for (int c = 0; c < 3; ++c) a.pixel(x, y)[c] = square ? 220 : 30;
      a.pixel(x, y)[3] = 255;
    }
  EXPECT_NEAR(structuralSimilarity(a.view(), a.view()), 1.0, 1e-12);
  Image noisy = a;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x)
      for (int c = 0; c < 3; ++c)
        noisy.pixel(x, y)[c] = static_cast<std::uint8_t>(a.pixel(x, y)[c] + ((x * 7 + y * 3) % 3));
  Image moved(40, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) std::copy_n(a.pixel((x + 8) % 40, y), 4, moved.pixel(x, y));
  const double faint = structuralSimilarity(a.view(), noisy.view());
  const double shifted = structuralSimilarity(a.view(), moved.view());
  EXPECT_GT(faint, 0.95);
  EXPECT_LT(faint, 1.0);
  EXPECT_LT(shifted, 0.8);
  EXPECT_NEAR(structuralSimilarity(moved.view(), a.view()), shifted, 1e-12);
  // Constant images of luma μa, μb: SSIM = (2μaμb + C1)/(μa² + μb² + C1).
  Image dark(16, 16), light(16, 16);
  for (auto& v : dark.rgba) v = 50;
  for (auto& v : light.rgba) v = 100;
  const double c1 = 6.5025;
  EXPECT_NEAR(structuralSimilarity(dark.view(), light.view()), (2 * 50.0 * 100 + c1) / (2500.0 + 10000 + c1), 1e-9);
}

}  // namespace
}  // namespace rollspin::media
