// Every row of the output-format table (media/output_formats.def) opened
// through openSink on synthetic frames (no GL) and decoded with libavcodec:
// codec, pixel format, profile, frame count and timestamps, colours and
// alpha against the frames written, the partial output after an interrupt
// and nothing left behind when a sink is dropped unfinished. A new format
// must add its expectations here (the walk fails on a row it does not know).
#include <gtest/gtest.h>

#include <cmath>
#include <map>

#include "core/error.hpp"
#include "media/image_io.hpp"
#include "media/sink_factory.hpp"
#include "media/video_probe.hpp"
#include "support/test_files.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

// Flat colour blocks that move one block per frame; alpha in bands across
// the width: opaque, transparent, and (for full alpha) a half-transparent one.
media::Image testFrame(int width, int height, int k, bool alpha) {
  media::Image image(width, height);
  static const std::uint8_t kColours[4][3] = {{200, 30, 30}, {30, 160, 60}, {40, 60, 210}, {235, 235, 235}};
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      const int block = (x / 16 + y / 16 + k) % 4;
      std::uint8_t* p = image.pixel(x, y);
      for (int c = 0; c < 3; ++c) p[c] = kColours[block][c];
      p[3] = !alpha ? 255 : x < width / 2 ? 255 : x < 3 * width / 4 ? 0 : 160;
    }
  return image;
}

struct Expected {
  std::string codec, streamPixelFormat, decodedPixelFormat, profile;
  double meanTolerance;  // mean |Δ| over RGB of opaque pixels
};

// name + alpha → what a decoder must see.
const std::map<std::pair<std::string, bool>, Expected> kExpected{
    {{"mp4", false}, {"h264", "yuv420p", "yuv420p", "High", 6.0}},
    {{"webm", false}, {"vp9", "yuv420p", "yuv420p", "Profile 0", 6.0}},
    {{"webm", true}, {"vp9", "yuv420p", "yuva420p", "Profile 0", 6.0}},
    {{"mov", false}, {"prores", "yuv422p10le", "yuv422p10le", "HQ", 3.0}},
    {{"mov", true}, {"prores", "yuva444p12le", "yuva444p12le", "4444", 3.0}},
    // 256 colours, Bayer-dithered: exact on flat blocks up to the palette's rounding.
    {{"gif", false}, {"gif", "bgra", "bgra", "", 6.0}},
    {{"gif", true}, {"gif", "bgra", "bgra", "", 6.0}},
};

struct Mean {
  double colour = 0.0;
  int maxAlphaError = 0;
};

// Mean colour difference over pixels opaque in `expected`, and the largest
// alpha difference (alpha only where the format keeps it).
Mean compare(const media::Image& decoded, const media::Image& expected, media::AlphaSupport alpha) {
  Mean m;
  long long n = 0;
  for (int y = 0; y < expected.height; ++y)
    for (int x = 0; x < expected.width; ++x) {
      const std::uint8_t* a = decoded.pixel(x, y);
      const std::uint8_t* b = expected.pixel(x, y);
      int wantAlpha = b[3];
      if (alpha == media::AlphaSupport::None) wantAlpha = 255;
      if (alpha == media::AlphaSupport::Binary) wantAlpha = b[3] < 128 ? 0 : 255;
      // Block and alpha edges: chroma subsampling blurs them; skip 2 px.
      const bool edge = x % 16 < 2 || x % 16 > 13 || y % 16 < 2 || y % 16 > 13 ||
                        std::abs(x - expected.width / 2) < 3 || std::abs(x - 3 * expected.width / 4) < 3;
      if (edge) continue;
      m.maxAlphaError = std::max(m.maxAlphaError, std::abs(int(a[3]) - wantAlpha));
      if (b[3] != 255) continue;
      for (int c = 0; c < 3; ++c) m.colour += std::abs(int(a[c]) - int(b[c]));
      n += 3;
    }
  m.colour /= double(std::max<long long>(n, 1));
  return m;
}

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

media::SinkOptions options(const fs::path& path, bool alpha) {
  media::SinkOptions o;
  o.path = path;
  o.width = 64;
  o.height = 48;
  o.fpsNum = 10;
  o.fpsDen = 1;
  o.alpha = alpha;
  return o;
}

// Writes `count` frames the way the animation job does (the preview pass first).
void writeClip(media::FrameSink& sink, int count, bool alpha) {
  for (long long k : sink.previewFrames(count)) sink.preview(testFrame(64, 48, int(k), alpha).view());
  for (int k = 0; k < count; ++k) sink.write(testFrame(64, 48, k, alpha).view());
}

TEST(FormatSinks, EveryVideoRowDecodesToItsCodecPixelFormatFramesColoursAndAlpha) {
  int rows = 0;
  for (const media::OutputFormat& format : media::kOutputFormats) {
    if (format.kind != media::OutputKind::Video) continue;
    for (const bool alpha : {false, true}) {
      if (alpha && format.alpha == media::AlphaSupport::None) continue;
      SCOPED_TRACE(std::string(format.name) + (alpha ? " with alpha" : ""));
      const auto expected = kExpected.find({std::string(format.name), alpha});
      ASSERT_NE(expected, kExpected.end()) << "a table row without expectations in this test";
      ++rows;
      const fs::path dir = test::freshTempDir("format_" + std::string(format.name) + (alpha ? "_alpha" : ""));
      const fs::path file = dir / ("clip" + format.defaultExtension());
      {
        const auto sink = media::openSink(format, options(file, alpha));
        writeClip(*sink, 12, alpha);
        EXPECT_EQ(sink->framesWritten(), 12);
        EXPECT_EQ(sink->finish(), file);
      }
      EXPECT_EQ(filesIn(dir), std::vector<std::string>{file.filename().string()}) << "no temporary file left";
      const test::VideoProbe probe = test::probeVideo(file, {5});
      const Expected& e = expected->second;
      EXPECT_EQ(probe.codec, e.codec);
      EXPECT_EQ(probe.pixelFormat, e.streamPixelFormat);
      EXPECT_EQ(probe.decodedPixelFormat, e.decodedPixelFormat);
      EXPECT_EQ(probe.profile, e.profile);
      EXPECT_EQ(probe.width, 64);
      EXPECT_EQ(probe.height, 48);
      if (format.name == "webm") {
        EXPECT_EQ(probe.alphaMode, alpha ? "1" : "");
        EXPECT_EQ(probe.chromaLocation, "center") << "the converter's chroma is each 2x2 block's mean";
      }
      if (format.name != "gif") {  // GIF: RGB palette entries, no colour tags
        EXPECT_EQ(probe.colorSpace, "bt709");
        EXPECT_EQ(probe.colorPrimaries, "bt709");
        EXPECT_EQ(probe.colorTransfer, "bt709");
      }
      ASSERT_EQ(probe.ptsSeconds.size(), 12u);
      for (std::size_t k = 0; k < 12; ++k) EXPECT_NEAR(probe.ptsSeconds[k], double(k) / 10.0, 1e-6) << k;
      ASSERT_EQ(probe.kept.size(), 1u);
      const Mean m = compare(probe.kept[0], testFrame(64, 48, 5, alpha), format.alpha);
      std::fprintf(stderr, "%s%s: frame 5 mean |dRGB| %.2f, max |dA| %d\n", std::string(format.name).c_str(),
                   alpha ? " (alpha)" : "", m.colour, m.maxAlphaError);
      EXPECT_LE(m.colour, e.meanTolerance);
      // Alpha: 8-bit after a 10/12-bit or VP9 round trip; 1-bit GIF exact.
      EXPECT_LE(m.maxAlphaError, alpha ? 6 : 0);
      if (HasFailure()) media::writePng(dir / "decoded_frame_5.png", probe.kept[0].view(), media::PngChannels::Rgba);
    }
  }
  EXPECT_EQ(rows, int(kExpected.size())) << "every expectation met a row";
}

TEST(FormatSinks, EveryVideoRowLeavesAPlayablePartialOrNothing) {
  for (const media::OutputFormat& format : media::kOutputFormats) {
    if (format.kind != media::OutputKind::Video) continue;
    SCOPED_TRACE(std::string(format.name));
    const fs::path dir = test::freshTempDir("partial_" + std::string(format.name));
    const fs::path file = dir / ("clip" + format.defaultExtension());
    {
      const auto sink = media::openSink(format, options(file, false));
      writeClip(*sink, 3, false);
      EXPECT_EQ(sink->finishPartial(), dir / ("clip.partial" + format.defaultExtension()));
    }
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"clip.partial" + format.defaultExtension()});
    EXPECT_EQ(test::probeVideo(dir / ("clip.partial" + format.defaultExtension())).ptsSeconds.size(), 3u);
    fs::remove_all(dir);
    fs::create_directories(dir);
    {
      const auto sink = media::openSink(format, options(file, false));
      EXPECT_TRUE(sink->finishPartial().empty()) << "no frame: nothing";
    }
    {
      const auto sink = media::openSink(format, options(file, false));
      writeClip(*sink, 2, false);
    }  // dropped unfinished (an error elsewhere)
    EXPECT_TRUE(filesIn(dir).empty());
  }
}

TEST(FormatSinks, StillRowsWriteOneImageAtomicallyJpegWithoutAlpha) {
  const fs::path dir = test::freshTempDir("format_stills");
  for (const char* name : {"png", "jpg"}) {
    const media::OutputFormat* format = media::findOutputFormat(name, media::OutputUse::Still);
    ASSERT_NE(format, nullptr) << name;
    const fs::path file = dir / (std::string("still") + format->defaultExtension());
    media::SinkOptions o = options(file, format->alpha != media::AlphaSupport::None);
    {
      const auto sink = media::openSink(*format, o);
      sink->write(testFrame(64, 48, 1, o.alpha).view());
      EXPECT_FALSE(fs::exists(file)) << "written on finish, not before";
      EXPECT_THROW(sink->write(testFrame(64, 48, 1, o.alpha).view()), Error) << "one frame only";
      EXPECT_EQ(sink->finish(), file);
    }
    const media::Image back = media::loadImage(file, {});
    const Mean m = compare(back, testFrame(64, 48, 1, o.alpha), format->alpha);
    EXPECT_LE(m.colour, std::string(name) == "png" ? 0.0 : 3.0) << name;
    EXPECT_EQ(m.maxAlphaError, 0) << name;
    {
      const auto sink = media::openSink(*format, options(dir / "interrupted.png", false));
      EXPECT_TRUE(sink->finishPartial().empty());
    }
  }
  EXPECT_EQ(filesIn(dir), (std::vector<std::string>{"still.jpg", "still.png"}));
}

TEST(FormatSinks, JpegQualityChangesTheFile) {
  const fs::path dir = test::freshTempDir("format_jpeg_quality");
  const media::OutputFormat& jpg = *media::findOutputFormat("jpg", media::OutputUse::Still);
  std::vector<std::uintmax_t> sizes;
  for (int q : {40, 92}) {
    media::SinkOptions o = options(dir / ("q" + std::to_string(q) + ".jpg"), false);
    o.jpegQuality = q;
    const auto sink = media::openSink(jpg, o);
    sink->write(testFrame(64, 48, 0, false).view());
    sizes.push_back(fs::file_size(sink->finish()));
  }
  EXPECT_LT(sizes[0], sizes[1]);
}

TEST(FormatSinks, GifLoopsByDefaultAndPlaysOnceWhenAsked) {
  const fs::path dir = test::freshTempDir("format_gif_loop");
  const media::OutputFormat& gif = *media::findOutputFormat("gif", media::OutputUse::Animation);
  for (const bool loop : {true, false}) {
    media::SinkOptions o = options(dir / (loop ? "loop.gif" : "once.gif"), false);
    o.loop = loop;
    const auto sink = media::openSink(gif, o);
    writeClip(*sink, 3, false);
    const std::string bytes = test::readFile(sink->finish());
    // The NETSCAPE2.0 application extension is what makes a GIF loop.
    EXPECT_EQ(bytes.find("NETSCAPE2.0") != std::string::npos, loop);
  }
}

}  // namespace
}  // namespace rollspin
