// GifWriter on synthetic frames (no GL), decoded with libavcodec: the
// palette frames it asks for (at most 60, spread over the clip, both ends
// included), a palette made from the frames previewed, or from the first
// frame when none were, a still background that keeps its pixels while
// something moves, 1-bit alpha at 128, odd sizes, 1/100 s delays, and the
// metadata comments only a finished GIF carries.
#include "media/gif_writer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "media/video_probe.hpp"
#include "support/test_files.hpp"

namespace rollspin::media {
namespace gif_writer_test {

namespace fs = std::filesystem;

Image flatGifFrame(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b, std::uint8_t a = 255) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = r;
      p[1] = g;
      p[2] = b;
      p[3] = a;
    }
  return image;
}

GifSettings gifSettings(int width, int height) {
  GifSettings s;
  s.width = width;
  s.height = height;
  s.fpsNum = 25;
  return s;
}

std::vector<std::string> gifDirEntries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(GifWriter, AsksForAtMostSixtyPaletteFramesSpreadOverTheWholeClip) {
  const fs::path dir = test::freshTempDir("gif_preview_frames");
  const GifWriter writer(dir / "clip.gif", gifSettings(8, 8));
  EXPECT_TRUE(writer.previewFrames(0).empty());
  EXPECT_EQ(writer.previewFrames(1), std::vector<long long>{0});
  EXPECT_EQ(writer.previewFrames(4), (std::vector<long long>{0, 1, 2, 3})) << "a short clip: every frame";
  for (const long long count : {59LL, 60LL, 61LL, 119LL, 1000LL, 123457LL}) {
    SCOPED_TRACE(count);
    const std::vector<long long> frames = writer.previewFrames(count);
    ASSERT_EQ(frames.size(), static_cast<std::size_t>(std::min(count, GifWriter::kPaletteFrames)));
    EXPECT_EQ(frames.front(), 0);
    EXPECT_EQ(frames.back(), count - 1) << "the last frame is seen too";
    // Evenly spread: every step is the mean step rounded down or up.
    const double step = double(count - 1) / double(frames.size() - 1);
    for (std::size_t k = 1; k < frames.size(); ++k) {
      const long long d = frames[k] - frames[k - 1];
      EXPECT_GE(d, static_cast<long long>(std::floor(step)));
      EXPECT_LE(d, static_cast<long long>(std::ceil(step)));
    }
  }
}

// Frame 0 red, frame 1 green: only a palette made from both frames holds green.
TEST(GifWriter, ThePaletteComesFromThePreviewedFrames) {
  const fs::path dir = test::freshTempDir("gif_palette");
  const Image red = flatGifFrame(16, 16, 230, 20, 20);
  const Image green = flatGifFrame(16, 16, 20, 200, 40);
  {
    GifWriter writer(dir / "clip.gif", gifSettings(16, 16));
    ASSERT_EQ(writer.previewFrames(2), (std::vector<long long>{0, 1}));
    writer.preview(red.view());
    writer.preview(green.view());
    writer.write(red.view());
    writer.write(green.view());
    writer.finish();
  }
  const test::VideoProbe probe = test::probeVideo(dir / "clip.gif", {0, 1});
  ASSERT_EQ(probe.kept.size(), 2u);
  for (int c = 0; c < 3; ++c) {
    EXPECT_NEAR(int(probe.kept[0].pixel(8, 8)[c]), int(red.pixel(8, 8)[c]), 3) << c;
    EXPECT_NEAR(int(probe.kept[1].pixel(8, 8)[c]), int(green.pixel(8, 8)[c]), 3) << c;
  }
}

TEST(GifWriter, WithoutPreviewThePaletteIsTheFirstFramesAndPreviewComesTooLate) {
  const fs::path dir = test::freshTempDir("gif_no_preview");
  const Image blue = flatGifFrame(16, 16, 30, 40, 210);
  GifWriter writer(dir / "clip.gif", gifSettings(16, 16));
  writer.write(blue.view());
  try {
    writer.preview(blue.view());
    ADD_FAILURE() << "a palette frame after the frames was taken";
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 1);
    EXPECT_NE(e.message().find("palette frames come before its frames"), std::string::npos) << e.what();
  }
  writer.write(blue.view());
  const test::VideoProbe probe = test::probeVideo(writer.finish(), {1});
  ASSERT_EQ(probe.kept.size(), 1u);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(probe.kept[0].pixel(3, 3)[c]), int(blue.pixel(3, 3)[c]), 3) << c;
}

// A gradient backdrop (which the dither must not let crawl) and a small
// square moving across it: far from the square, frames 1 and 2 are the
// same pixels.
TEST(GifWriter, AStillBackgroundKeepsItsPixelsWhileSomethingMoves) {
  const fs::path dir = test::freshTempDir("gif_still_background");
  const int w = 64, h = 32;
  auto frameAt = [&](int k) {
    Image image(w, h);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        std::uint8_t* p = image.pixel(x, y);
        p[0] = static_cast<std::uint8_t>(40 + 3 * x);
        p[1] = static_cast<std::uint8_t>(60 + 2 * y + x);
        p[2] = static_cast<std::uint8_t>(200 - 2 * x);
        p[3] = 255;
        if (x >= 4 + 6 * k && x < 10 + 6 * k && y >= 2 && y < 8) {
          p[0] = static_cast<std::uint8_t>(250 - 7 * y);
          p[1] = static_cast<std::uint8_t>(90 + 11 * x);
          p[2] = static_cast<std::uint8_t>(30 + 5 * (x + y));
        }
      }
    return image;
  };
  {
    GifWriter writer(dir / "clip.gif", gifSettings(w, h));
    for (long long k : writer.previewFrames(3)) writer.preview(frameAt(int(k)).view());
    for (int k = 0; k < 3; ++k) writer.write(frameAt(k).view());
    writer.finish();
  }
  const test::VideoProbe probe = test::probeVideo(dir / "clip.gif", {1, 2});
  ASSERT_EQ(probe.kept.size(), 2u);
  int differing = 0;
  for (int y = 12; y < h; ++y)  // below the square's rows
    for (int x = 0; x < w; ++x) differing += std::memcmp(probe.kept[0].pixel(x, y), probe.kept[1].pixel(x, y), 4) != 0;
  EXPECT_EQ(differing, 0);
}

TEST(GifWriter, AlphaIsOneBitTransparentBelow128) {
  const fs::path dir = test::freshTempDir("gif_alpha");
  GifSettings s = gifSettings(16, 8);
  s.alpha = true;
  Image frame = flatGifFrame(16, 8, 200, 100, 50);
  // Columns 0-3: alpha 127, 4-7: 128, 8-11: 0, 12-15: 255.
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 16; ++x) frame.pixel(x, y)[3] = std::array<std::uint8_t, 4>{127, 128, 0, 255}[x / 4];
  {
    GifWriter writer(dir / "clip.gif", s);
    writer.write(frame.view());
    writer.finish();
  }
  const test::VideoProbe probe = test::probeVideo(dir / "clip.gif", {0});
  ASSERT_EQ(probe.kept.size(), 1u);
  for (int x = 0; x < 16; ++x) {
    const int want = frame.pixel(x, 4)[3] < 128 ? 0 : 255;
    EXPECT_EQ(int(probe.kept[0].pixel(x, 4)[3]), want) << "column " << x << ", alpha " << int(frame.pixel(x, 4)[3]);
  }
}

// No chroma subsampling: any size; delays are 1/100 s, 4 at 25 fps.
TEST(GifWriter, TakesOddSizesAndTimesFramesInHundredths) {
  const fs::path dir = test::freshTempDir("gif_odd");
  {
    GifWriter writer(dir / "clip.gif", gifSettings(33, 17));
    for (int k = 0; k < 5; ++k) writer.write(flatGifFrame(33, 17, 10, 10, static_cast<std::uint8_t>(50 * k)).view());
    writer.finish();
  }
  const test::VideoProbe probe = test::probeVideo(dir / "clip.gif");
  EXPECT_EQ(probe.codec, "gif");
  EXPECT_EQ(probe.width, 33);
  EXPECT_EQ(probe.height, 17);
  ASSERT_EQ(probe.ptsSeconds.size(), 5u);
  for (std::size_t k = 0; k < 5; ++k) EXPECT_NEAR(probe.ptsSeconds[k], 0.04 * double(k), 1e-9) << k;
}

TEST(GifWriter, AFrameOfAnotherSizeIsRefusedNamingTheFile) {
  const fs::path dir = test::freshTempDir("gif_frame_size");
  GifWriter writer(dir / "clip.gif", gifSettings(16, 16));
  try {
    writer.write(flatGifFrame(8, 16, 0, 0, 0).view());
    ADD_FAILURE() << "written";
  } catch (const Error& e) {
    EXPECT_EQ(e.where().file, (dir / "clip.gif").string());
    EXPECT_NE(e.message().find("frame of 8x16 for a 16x16 GIF"), std::string::npos) << e.what();
  }
}

TEST(GifWriter, OnlyAFinishedGifCarriesItsMetadata) {
  const fs::path dir = test::freshTempDir("gif_metadata");
  GifSettings s = gifSettings(16, 16);
  s.metadata = OutputMetadata{"Title", "[ball]\nradius = 7\n", "render: clip\n", "A ball.", "rollspin test"};
  const Image frame = flatGifFrame(16, 16, 90, 90, 90);
  fs::path finished, partial;
  {
    GifWriter writer(dir / "whole.gif", s);
    for (int k = 0; k < 2; ++k) writer.write(frame.view());
    finished = writer.finish();
  }
  {
    GifWriter writer(dir / "cut.gif", s);
    for (int k = 0; k < 2; ++k) writer.write(frame.view());
    partial = writer.finishPartial();
  }
  EXPECT_EQ(partial, dir / "cut.partial.gif");
  EXPECT_EQ(gifDirEntries(dir), (std::vector<std::string>{"cut.partial.gif", "whole.gif"})) << "no temporaries";
  const OutputMetadata back = parseOutputMetadata(test::readFile(finished), finished.string());
  EXPECT_EQ(back.scene, s.metadata->scene);
  EXPECT_EQ(back.job, s.metadata->job);
  EXPECT_EQ(back.description, s.metadata->description);
  EXPECT_EQ(test::readFile(partial).find("radius = 7"), std::string::npos) << "a partial GIF has no comments";
  EXPECT_EQ(test::probeVideo(finished).ptsSeconds.size(), 2u) << "the comments leave the frames playable";
  EXPECT_EQ(test::probeVideo(partial).ptsSeconds.size(), 2u);
}

}  // namespace gif_writer_test
}  // namespace rollspin::media
