// VideoWriter on synthetic frames (no GL), beyond what mp4_writer_test and
// format_sinks_test check through the format table: the partial name, the
// refusals before anything is created, an exact NTSC rational rate, frames
// stored bottom-up (a GL read-back) the right way up through both
// converters, the changed-blocks summary, caption text escaped for the ASS
// event it travels in, a device written in place, and a stale temporary of
// a dead run cleared.
#include "media/video_writer.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "core/temp_files.hpp"
#include "media/mp4_writer.hpp"
#include "media/sink_factory.hpp"
#include "media/video_probe.hpp"
#include "support/test_files.hpp"

namespace rollspin::media {
namespace video_writer_test {

namespace fs = std::filesystem;

std::vector<std::string> writerDirEntries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// Red on the top half, blue on the bottom: upside down is unmistakable.
Image redOverBlue(int width, int height) {
  Image image(width, height);
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = y < height / 2 ? 220 : 20;
      p[2] = y < height / 2 ? 20 : 220;
      p[1] = 30;
      p[3] = 255;
    }
  return image;
}

// The same pixels stored bottom row first, as glReadPixels leaves them.
std::vector<std::uint8_t> storedBottomUp(const Image& image) {
  std::vector<std::uint8_t> rows(image.rgba.size());
  const std::size_t row = static_cast<std::size_t>(image.width) * 4;
  for (int y = 0; y < image.height; ++y)
    std::copy_n(image.pixel(0, y), row, rows.data() + (image.height - 1 - y) * row);
  return rows;
}

TEST(VideoWriter, PartialNameGoesBeforeTheExtension) {
  EXPECT_EQ(partialName("out/clip.mp4"), fs::path("out/clip.partial.mp4"));
  EXPECT_EQ(partialName("a.b.webm"), fs::path("a.b.partial.webm")) << "only the last extension moves";
  EXPECT_EQ(partialName("/tmp/clip"), fs::path("/tmp/clip.partial"));
}

TEST(VideoWriter, RefusesAZeroSizeOrFrameRateBeforeCreatingAnything) {
  const fs::path dir = test::freshTempDir("writer_refuse");
  struct Case {
    int width, height, fpsNum, fpsDen;
    const char* says;
  };
  for (const Case c :
       {Case{0, 32, 10, 1, "non-zero width and height; got 0x32"},
        Case{32, 32, 0, 1, "expected frames per second > 0, got 0/1"},
        Case{32, 32, 10, 0, "expected frames per second > 0, got 10/0"}, Case{32, 32, -5, 1, "got -5/1"}}) {
    SCOPED_TRACE(c.says);
    Mp4Settings s{c.width, c.height, c.fpsNum, c.fpsDen};
    try {
      VideoWriter writer(dir / "clip.mp4", mp4VideoSettings(s));
      ADD_FAILURE() << "opened";
    } catch (const Error& e) {
      EXPECT_EQ(e.exitCode(), 2);
      EXPECT_EQ(e.where().file, (dir / "clip.mp4").string());
      EXPECT_NE(e.message().find(c.says), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(writerDirEntries(dir).empty());
}

TEST(VideoWriter, AFrameOfAnotherSizeIsARuntimeErrorNamingBothSizes) {
  const fs::path dir = test::freshTempDir("writer_frame_size");
  {
    VideoWriter writer(dir / "clip.mp4", mp4VideoSettings({32, 32, 10}));
    try {
      writer.write(Image(16, 32).view());
      ADD_FAILURE() << "written";
    } catch (const Error& e) {
      EXPECT_EQ(e.exitCode(), 1);
      EXPECT_EQ(e.where().file, (dir / "clip.mp4").string());
      EXPECT_NE(e.message().find("frame of 16x32 for a 32x32 video"), std::string::npos) << e.what();
    }
    EXPECT_EQ(writer.framesWritten(), 0);
  }
  EXPECT_TRUE(writerDirEntries(dir).empty()) << "dropped after the error: nothing left";
}

// 29.97 fps is 30000/1001 exactly: frame k at k·1001/30000 s, no drift.
TEST(VideoWriter, KeepsAnNtscRateExactlyRational) {
  const fs::path dir = test::freshTempDir("writer_ntsc");
  const fs::path out = dir / "clip.mp4";
  {
    VideoWriter writer(out, mp4VideoSettings({32, 32, 30000, 1001}));
    for (int k = 0; k < 6; ++k) writer.write(redOverBlue(32, 32).view());
    writer.finish();
  }
  const test::VideoProbe probe = test::probeVideo(out);
  EXPECT_EQ(probe.frameRateNum, 30000);
  EXPECT_EQ(probe.frameRateDen, 1001);
  ASSERT_EQ(probe.ptsTicks.size(), 6u);
  for (std::size_t k = 0; k < probe.ptsTicks.size(); ++k) {
    // ticks · num/den of the time base is exactly k · 1001/30000 s.
    EXPECT_EQ(probe.ptsTicks[k] * probe.timeBaseNum * 30000, static_cast<long long>(k) * 1001 * probe.timeBaseDen)
        << "frame " << k;
  }
}

// H.264 goes through rollspin's 4:2:0 converter, ProRes through swscale: both
// read rows from the top, whatever the storage order.
TEST(VideoWriter, FramesStoredBottomUpComeOutTheRightWayUp) {
  const fs::path dir = test::freshTempDir("writer_bottom_up");
  const Image image = redOverBlue(32, 32);
  const std::vector<std::uint8_t> rows = storedBottomUp(image);
  const ImageView bottomUp{32, 32, 32 * 4, rows.data(), RowOrder::BottomUp};
  for (const char* format : {"mp4", "mov"}) {
    SCOPED_TRACE(format);
    SinkOptions o;
    o.path = dir / (std::string("clip.") + format);
    o.width = o.height = 32;
    o.fpsNum = 10;
    const auto sink = openSink(*findOutputFormat(format, OutputUse::Animation), o);
    sink->write(bottomUp);
    sink->write(bottomUp);
    const test::VideoProbe probe = test::probeVideo(sink->finish(), {1});
    ASSERT_EQ(probe.kept.size(), 1u);
    for (const int y : {4, 27}) {
      const std::uint8_t* got = probe.kept[0].pixel(16, y);
      const std::uint8_t* want = image.pixel(16, y);
      for (int c = 0; c < 3; ++c) EXPECT_NEAR(int(got[c]), int(want[c]), 8) << "row " << y << " channel " << c;
    }
  }
}

// Two identical frames: the first is converted whole, the second not at all.
TEST(VideoWriter, SaysWhatShareOfThePixelsTheChangedBlocksConverterConverted) {
  const fs::path dir = test::freshTempDir("writer_summary");
  VideoWriter writer(dir / "clip.mp4", mp4VideoSettings({32, 32, 10}));
  EXPECT_EQ(writer.verboseSummary(), "") << "nothing converted yet";
  writer.write(redOverBlue(32, 32).view());
  writer.write(redOverBlue(32, 32).view());
  EXPECT_EQ(writer.verboseSummary(), "converted 50.0 % of the pixels to yuv420p; the rest were as in the frame before");
  EXPECT_EQ(writer.framesWritten(), 2);
  writer.finish();
}

// A caption travels as an ASS event, where braces and backslashes would open
// override codes: in the track they are full-width look-alikes.
TEST(VideoWriter, CaptionTextIsEscapedOutOfAssOverrideCodes) {
  const fs::path dir = test::freshTempDir("writer_captions");
  SinkOptions o;
  o.path = dir / "clip.mp4";
  o.width = o.height = 32;
  o.fpsNum = 10;
  o.subtitles = {{0, 2, "keep {\\b1}this"}};
  const auto sink = openSink(*findOutputFormat("mp4", OutputUse::Animation), o);
  EXPECT_TRUE(sink->carriesSubtitles());
  for (int k = 0; k < 2; ++k) sink->write(redOverBlue(32, 32).view());
  const std::string bytes = test::readFile(sink->finish());
  // mov_text keeps the event's text as UTF-8 in the sample.
  EXPECT_NE(bytes.find("keep \xef\xbd\x9b\xef\xbc\xbc"
                       "b1\xef\xbd\x9dthis"),
            std::string::npos);
  EXPECT_EQ(bytes.find("{\\b1}"), std::string::npos);
}

TEST(VideoWriter, ADeviceIsWrittenInPlace) {
  if (!fs::exists("/dev/null")) GTEST_SKIP() << "no /dev/null";
  VideoWriter writer("/dev/null", mp4VideoSettings({32, 32, 10}));
  writer.write(redOverBlue(32, 32).view());
  EXPECT_EQ(writer.finish(), fs::path("/dev/null"));
  EXPECT_TRUE(fs::is_character_file("/dev/null")) << "not replaced by a file";
}

// A run killed hard (kill -9) leaves ".NAME.PID.tmp"; the next writer of NAME
// removes it when that process is gone, and leaves other names alone.
TEST(VideoWriter, ClearsATemporaryLeftByADeadRun) {
  const fs::path dir = test::freshTempDir("writer_stale");
  // Above any pid_max Linux allows (2^22): no such process.
  const fs::path stale = dir / ".clip.mp4.4999999.tmp";
  std::ofstream(stale) << "half a video";
  std::ofstream(dir / ".other.mp4.4999999.tmp") << "not ours";
  {
    VideoWriter writer(dir / "clip.mp4", mp4VideoSettings({32, 32, 10}));
    writer.write(redOverBlue(32, 32).view());
    writer.finish();
  }
  EXPECT_EQ(writerDirEntries(dir), (std::vector<std::string>{".other.mp4.4999999.tmp", "clip.mp4"}));
}

}  // namespace video_writer_test
}  // namespace rollspin::media
