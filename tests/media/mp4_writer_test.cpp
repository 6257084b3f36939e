// Mp4Writer on synthetic frames (no GL): what a player sees (codec, pixel
// format, BT.709 tags, timestamps, faststart), colours that survive the
// RGBA → yuv420p → RGBA round trip, and every failure leaving nothing behind.
#include "media/mp4_writer.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "media/h264_levels.hpp"
#include "media/video_probe.hpp"
#include "support/test_files.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

// Flat colour blocks (chroma subsampling cannot blur them away) and a bar
// that moves one block per frame, so every frame differs.
media::Image blockFrame(int width, int height, int k) {
  media::Image image(width, height);
  static const std::uint8_t kColours[4][3] = {{200, 30, 30}, {30, 160, 60}, {40, 60, 210}, {235, 235, 235}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int block = (x / 16 + y / 16 + k) % 4;
      std::uint8_t* p = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) p[c] = kColours[block][c];
      p[3] = 255;
    }
  return image;
}

std::vector<fs::path> entriesIn(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename());
  return out;
}

TEST(Mp4Writer, WritesH264Yuv420pTaggedBt709WithMonotonicTimestamps) {
  const fs::path dir = test::freshTempDir("mp4_tags");
  const fs::path out = dir / "clip.mp4";
  media::Mp4Settings settings{64, 48, 12};
  {
    media::Mp4Writer writer(out, settings);
    for (int k = 0; k < 24; ++k) writer.write(blockFrame(64, 48, k).view());
    EXPECT_FALSE(fs::exists(out)) << "the final name appears only on finish()";
    EXPECT_EQ(writer.finish(), out);
  }
  EXPECT_EQ(entriesIn(dir), std::vector<fs::path>{"clip.mp4"}) << "no temporary file left";
  const test::VideoProbe probe = test::probeVideo(out, {5});
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.pixelFormat, "yuv420p");
  EXPECT_EQ(probe.colorSpace, "bt709");
  EXPECT_EQ(probe.colorPrimaries, "bt709");
  EXPECT_EQ(probe.colorTransfer, "bt709");
  EXPECT_EQ(probe.colorRange, "tv");
  EXPECT_EQ(probe.chromaLocation, "center") << "the converter's chroma is each 2x2 block's mean";
  EXPECT_EQ(probe.width, 64);
  EXPECT_EQ(probe.height, 48);
  EXPECT_DOUBLE_EQ(probe.frameRate, 12.0);
  EXPECT_TRUE(probe.indexBeforeData) << "+faststart: moov before mdat";
  ASSERT_EQ(probe.ptsSeconds.size(), 24u);
  for (std::size_t k = 0; k < probe.ptsSeconds.size(); ++k)
    EXPECT_NEAR(probe.ptsSeconds[k], double(k) / 12.0, 1e-6) << "frame " << k;

  // Flat blocks away from their edges: the BT.709 round trip is within a few
  // levels (8-bit limited-range YUV quantisation plus CRF 18).
  ASSERT_EQ(probe.kept.size(), 1u);
  const media::Image expected = blockFrame(64, 48, 5);
  double worst = 0.0;
  for (int y = 4; y < 48; y += 16)
    for (int x = 4; x < 64; x += 16)
      for (int c = 0; c < 3; ++c)
        worst =
            std::max(worst, std::abs(double(probe.kept[0].pixel(x + 4, y + 4)[c]) - expected.pixel(x + 4, y + 4)[c]));
  EXPECT_LE(worst, 6.0);
}

// The level libx264 tags is the lowest of Table A-1 that holds the size and
// rate (h264_levels.cpp's table, written from the standard, not from x264):
// a size and rate at each level's edge: 640x360@30 is 3.0, 1920x1080@60 4.2,
// 4096x2160@60 exactly 5.2's MaxMBPS, 8192x4320@30 (the largest frame) 6.0.
// Two flat frames each (ultrafast: one reference, far inside every DPB).
TEST(Mp4Writer, TagsTheLowestH264LevelThatHoldsTheSizeAndRate) {
  const fs::path dir = test::freshTempDir("mp4_levels");
  struct Case {
    int width, height, fps, level;
  };
  for (const Case c :
       {Case{640, 360, 30, 30}, Case{1920, 1080, 60, 42}, Case{4096, 2160, 60, 52}, Case{8192, 4320, 30, 60}}) {
    const auto expected = media::lowestH264Level(c.width, c.height, c.fps);
    ASSERT_TRUE(expected.has_value()) << c.width << "x" << c.height;
    EXPECT_EQ(expected->idc, c.level) << c.width << "x" << c.height << "@" << c.fps << ": Table A-1";
    const fs::path out = dir / fmt::format("{}x{}.mp4", c.width, c.height);
    media::Mp4Settings settings{c.width, c.height, c.fps};
    settings.preset = "ultrafast";
    media::Mp4Writer writer(out, settings);
    media::Image flat(c.width, c.height);
    for (int k = 0; k < 2; ++k) writer.write(flat.view());
    writer.finish();
    EXPECT_EQ(test::probeVideo(out).level, c.level) << c.width << "x" << c.height << "@" << c.fps << ": x264's tag";
    fs::remove(out);
  }
}

TEST(Mp4Writer, FinishPartialGivesAShorterPlayableVideoUnderAPartialName) {
  const fs::path dir = test::freshTempDir("mp4_partial");
  const fs::path out = dir / "clip.mp4";
  {
    media::Mp4Writer writer(out, {32, 32, 10});
    for (int k = 0; k < 5; ++k) writer.write(blockFrame(32, 32, k).view());
    EXPECT_EQ(writer.finishPartial(), dir / "clip.partial.mp4");
  }
  EXPECT_FALSE(fs::exists(out));
  EXPECT_EQ(entriesIn(dir), std::vector<fs::path>{"clip.partial.mp4"});
  EXPECT_EQ(test::probeVideo(dir / "clip.partial.mp4").ptsSeconds.size(), 5u);
}

TEST(Mp4Writer, NothingIsLeftWithoutFramesOrWithoutFinish) {
  const fs::path dir = test::freshTempDir("mp4_nothing");
  {
    media::Mp4Writer writer(dir / "a.mp4", {32, 32, 10});
    EXPECT_TRUE(writer.finishPartial().empty());
  }
  {
    media::Mp4Writer writer(dir / "b.mp4", {32, 32, 10});
    writer.write(blockFrame(32, 32, 0).view());
  }  // destroyed unfinished (an error elsewhere)
  EXPECT_TRUE(entriesIn(dir).empty());
}

TEST(Mp4Writer, RefusesOddSizesAndMissingEncodersUpFront) {
  const fs::path dir = test::freshTempDir("mp4_refuse");
  try {
    media::Mp4Writer writer(dir / "odd.mp4", {33, 32, 10});
    FAIL() << "odd width accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 2);
    EXPECT_NE(std::string(e.what()).find("even"), std::string::npos) << e.what();
  }
  media::Mp4Settings settings{32, 32, 10};
  settings.encoder = "no-such-encoder";
  try {
    media::Mp4Writer writer(dir / "codec.mp4", settings);
    FAIL() << "unknown encoder accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 1);
    EXPECT_NE(std::string(e.what()).find("no-such-encoder"), std::string::npos) << e.what();
  }
  EXPECT_TRUE(entriesIn(dir).empty());
}

TEST(Mp4Writer, UnwritableFolderIsAClearRuntimeError) {
  const fs::path dir = test::freshTempDir("mp4_unwritable");
  std::ofstream(dir / "file") << "x";
  try {
    media::Mp4Writer writer(dir / "file" / "clip.mp4", {32, 32, 10});  // a file as the folder
    FAIL() << "no error";
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 1);
    EXPECT_NE(std::string(e.what()).find("cannot create"), std::string::npos) << e.what();
  }
}

TEST(Mp4Writer, FullDiskIsAClearRuntimeError) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  try {
    media::Mp4Writer writer("/dev/full", {64, 48, 10});
    for (int k = 0; k < 40; ++k) writer.write(blockFrame(64, 48, k).view());
    writer.finish();
    FAIL() << "writing to /dev/full succeeded";
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 1);
    EXPECT_NE(std::string(e.what()).find("No space left"), std::string::npos) << e.what();
  }
}

// A frame is converted to yuv420p only where it differs from the frame
// before (media/yuv420_converter), into a frame the encoder may still hold
// (x264's lookahead). Lossless (crf 0), every frame of a clip must decode to
// the same pixels as the same frame written alone, converted whole.
TEST(Mp4Writer, ChangedBlocksOnlyEncodeAsWholeFrames) {
  const int width = 96, height = 64, frames = 10;
  auto frameAt = [&](int k) {
    media::Image image = blockFrame(width, height, 0);
    // A small square moving over the still blocks, and one pixel that flips.
    for (int y = 20; y < 30; ++y)
      for (int x = 5 * k; x < 5 * k + 10; ++x) std::fill_n(image.pixel(x, y), 3, static_cast<std::uint8_t>(20 * k));
    if (k % 3 == 0) image.pixel(width - 1, 0)[2] = 0;
    return image;
  };
  media::Mp4Settings lossless{width, height, 30};
  lossless.crf = 0;
  const fs::path dir = test::freshTempDir("mp4_changed_blocks");
  {
    media::Mp4Writer writer(dir / "clip.mp4", lossless);
    for (int k = 0; k < frames; ++k) writer.write(frameAt(k).view());
    writer.finish();
  }
  std::set<long long> all;
  for (int k = 0; k < frames; ++k) all.insert(k);
  const test::VideoProbe clip = test::probeVideo(dir / "clip.mp4", all);
  ASSERT_EQ(clip.kept.size(), static_cast<std::size_t>(frames));
  for (int k = 0; k < frames; ++k) {
    const fs::path alone = dir / fmt::format("alone_{}.mp4", k);
    {
      media::Mp4Writer writer(alone, lossless);
      writer.write(frameAt(k).view());
      writer.finish();
    }
    const test::VideoProbe single = test::probeVideo(alone, {0});
    ASSERT_EQ(single.kept.size(), 1u);
    EXPECT_TRUE(clip.kept[k].rgba == single.kept[0].rgba) << "frame " << k << " of the clip differs from it alone";
  }
}

// Other pixel formats (here yuv444p; ProRes in MOV) are converted by swscale
// in its slice threads (ROLLSPIN_CONVERT_THREADS, else one per core). Slices
// split the output rows: the bytes must not depend on the thread count, for
// rows stored top-down or bottom-up (a GL read-back).
TEST(Mp4Writer, ConversionThreadsDoNotChangeTheBytes) {
  const int width = 160, height = 90;
  media::Image image(width, height);
  std::vector<std::string> videos;
  media::VideoSettings settings = media::mp4VideoSettings(media::Mp4Settings{width, height, 12});
  settings.pixelFormat = "yuv444p";
  for (const char* threads : {"1", "3", "7"}) {
    ASSERT_EQ(setenv("ROLLSPIN_CONVERT_THREADS", threads, 1), 0);
    const fs::path dir = test::freshTempDir(std::string("mp4_sws_threads_") + threads);
    const fs::path out = dir / "clip.mp4";
    {
      media::VideoWriter writer(out, settings);
      for (int k = 0; k < 6; ++k) {
        // Gradients, so every row differs from its neighbours in every channel.
        for (int y = 0; y < height; ++y)
          for (int x = 0; x < width; ++x) {
            std::uint8_t* p = image.pixel(x, y);
            p[0] = static_cast<std::uint8_t>(x + 2 * y + 3 * k);
            p[1] = static_cast<std::uint8_t>(3 * y + x / 4 + k);
            p[2] = static_cast<std::uint8_t>(2 * (x + y) - 5 * k);
            p[3] = 255;
          }
        media::ImageView view = image.view();
        if (k % 2 == 1) view.rows = media::RowOrder::BottomUp;
        writer.write(view);
      }
      writer.finish();
    }
    videos.push_back(test::readFile(out));
  }
  unsetenv("ROLLSPIN_CONVERT_THREADS");
  ASSERT_FALSE(videos[0].empty());
  EXPECT_TRUE(videos[0] == videos[1]) << "1 and 3 conversion threads wrote different videos";
  EXPECT_TRUE(videos[0] == videos[2]) << "1 and 7 conversion threads wrote different videos";
}

}  // namespace
}  // namespace rollspin
