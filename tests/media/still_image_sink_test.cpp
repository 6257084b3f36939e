// media/still_image_sink: one frame, written on finish() as PNG or JPEG with its alpha, quality and metadata, or
// nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "media/image_compare.hpp"
#include "media/image_io.hpp"
#include "media/output_metadata.hpp"
#include "media/sink_factory.hpp"
#include "media/still_image_sink.hpp"
#include "support/test_files.hpp"

namespace rollspin::media {
namespace {

// Smooth colours (JPEG keeps them well) and an alpha that varies.
Image stillSinkFrame(int w, int h, int seed) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      std::uint8_t* p = img.pixel(x, y);
      p[0] = static_cast<std::uint8_t>(4 * x + seed);
      p[1] = static_cast<std::uint8_t>(5 * y + 2 * seed);
      p[2] = static_cast<std::uint8_t>(2 * (x + y));
      p[3] = static_cast<std::uint8_t>(255 - 3 * x);
    }
  return img;
}

std::vector<std::string> stillSinkEntries(const std::filesystem::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : std::filesystem::directory_iterator(dir)) out.push_back(e.path().filename().string());
  return out;
}

// The same image with every alpha at 255: what a file without alpha gives back.
Image opaqueCopy(Image img) {
  for (std::size_t k = 3; k < img.rgba.size(); k += 4) img.rgba[k] = 255;
  return img;
}

TEST(StillImageSink, WritesItsOneFrameOnlyOnFinishAtTheFinalName) {
  const auto dir = test::freshTempDir("still_sink_finish");
  const Image frame = stillSinkFrame(24, 16, 0);
  StillImageSink sink(dir / "still.png", StillEncoding::Png, true, 90);
  EXPECT_EQ(sink.framesWritten(), 0);
  sink.write(frame.view());
  EXPECT_EQ(sink.framesWritten(), 1);
  EXPECT_TRUE(stillSinkEntries(dir).empty()) << "nothing before finish()";
  EXPECT_EQ(sink.finish(), dir / "still.png");
  EXPECT_EQ(stillSinkEntries(dir), std::vector<std::string>{"still.png"});
  const Image back = loadImage(dir / "still.png", {});
  EXPECT_EQ(back.width, 24);
  EXPECT_EQ(back.height, 16);
  EXPECT_EQ(back.rgba, frame.rgba);
}

// Alpha is kept only in a PNG that asks for it; colours stay exact in PNG.
TEST(StillImageSink, KeepsAlphaOnlyInAPngThatAsksForIt) {
  const auto dir = test::freshTempDir("still_sink_alpha");
  const Image frame = stillSinkFrame(20, 12, 7);
  struct Case {
    const char* name;
    StillEncoding encoding;
    bool alpha;
  };
  for (const Case& c : {Case{"rgba.png", StillEncoding::Png, true}, Case{"rgb.png", StillEncoding::Png, false},
                        Case{"alpha.jpg", StillEncoding::Jpeg, true}}) {
    StillImageSink sink(dir / c.name, c.encoding, c.alpha, 100);
    sink.write(frame.view());
    (void)sink.finish();
    const Image back = loadImage(dir / c.name, {});
    const ImageDifference d =
        compareImages(back.view(), (c.alpha && c.encoding == StillEncoding::Png ? frame : opaqueCopy(frame)).view());
    EXPECT_EQ(d.maxDelta[3], 0) << c.name;
    if (c.encoding == StillEncoding::Png) EXPECT_EQ(d.maxOverall(), 0) << c.name;
    else EXPECT_LE(d.meanOverall(), 2.0) << c.name;
  }
}

// write() copies the frame, top row first, whatever the view's row order:
// the caller may reuse its buffer at once (a GL readback, bottom-up).
TEST(StillImageSink, CopiesTheFrameTopDownWhenItIsWritten) {
  const auto dir = test::freshTempDir("still_sink_copy");
  const Image frame = stillSinkFrame(6, 5, 3);
  std::vector<std::uint8_t> bottomUp;
  for (int y = frame.height - 1; y >= 0; --y)
    bottomUp.insert(bottomUp.end(), frame.pixel(0, y), frame.pixel(0, y) + 4 * frame.width);
  StillImageSink sink(dir / "copy.png", StillEncoding::Png, true, 90);
  sink.write(ImageView{6, 5, 24, bottomUp.data(), RowOrder::BottomUp});
  std::fill(bottomUp.begin(), bottomUp.end(), std::uint8_t{0});
  (void)sink.finish();
  EXPECT_EQ(loadImage(dir / "copy.png", {}).rgba, frame.rgba);
}

TEST(StillImageSink, ASecondFrameIsARuntimeErrorAndTheFirstIsKept) {
  const auto dir = test::freshTempDir("still_sink_second");
  const Image first = stillSinkFrame(8, 8, 0), second = stillSinkFrame(8, 8, 90);
  StillImageSink sink(dir / "one.png", StillEncoding::Png, true, 90);
  sink.write(first.view());
  try {
    sink.write(second.view());
    ADD_FAILURE() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Runtime);
    EXPECT_EQ(e.where().file, (dir / "one.png").string());
    EXPECT_NE(std::string(e.what()).find("a still image takes one frame"), std::string::npos) << e.what();
  }
  EXPECT_EQ(sink.framesWritten(), 1);
  (void)sink.finish();
  EXPECT_EQ(loadImage(dir / "one.png", {}).rgba, first.rgba);
}

TEST(StillImageSink, FinishingWithoutAFrameIsARuntimeErrorAndWritesNothing) {
  const auto dir = test::freshTempDir("still_sink_empty");
  for (const StillEncoding encoding : {StillEncoding::Png, StillEncoding::Jpeg}) {
    StillImageSink sink(dir / "none.png", encoding, false, 90);
    try {
      (void)sink.finish();
      ADD_FAILURE() << "expected an error";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::Runtime);
      EXPECT_NE(std::string(e.what()).find("no frame was rendered"), std::string::npos) << e.what();
    }
  }
  EXPECT_TRUE(stillSinkEntries(dir).empty());
}

// One frame is the whole still: there is no shorter still to finish early,
// and a sink dropped unfinished (an error elsewhere) leaves nothing either.
TEST(StillImageSink, APartialOrUnfinishedStillLeavesNothing) {
  const auto dir = test::freshTempDir("still_sink_partial");
  const Image frame = stillSinkFrame(8, 8, 0);
  {
    StillImageSink sink(dir / "partial.png", StillEncoding::Png, false, 90);
    sink.write(frame.view());
    EXPECT_EQ(sink.finishPartial(), std::filesystem::path());
  }
  {
    StillImageSink sink(dir / "dropped.jpg", StillEncoding::Jpeg, false, 90);
    sink.write(frame.view());
  }
  EXPECT_TRUE(stillSinkEntries(dir).empty());
}

TEST(StillImageSink, JpegQualityIsTheOneGiven) {
  const auto dir = test::freshTempDir("still_sink_quality");
  Image frame(48, 32);  // fine detail, which a low quality loses
  for (std::size_t k = 0; k < frame.rgba.size(); ++k) frame.rgba[k] = static_cast<std::uint8_t>((k * 37) % 251);
  double previous = 1e9;
  for (int quality : {20, 60, 98}) {
    const auto file = dir / ("q" + std::to_string(quality) + ".jpg");
    StillImageSink sink(file, StillEncoding::Jpeg, false, quality);
    sink.write(frame.view());
    (void)sink.finish();
    const double error = compareImages(loadImage(file, {}).view(), opaqueCopy(frame).view()).meanOverall();
    EXPECT_LT(error, previous) << "quality " << quality;
    previous = error;
  }
}

// The metadata goes into the file when given, in each encoding; none when not.
TEST(StillImageSink, WritesTheMetadataItWasGiven) {
  const auto dir = test::freshTempDir("still_sink_metadata");
  OutputMetadata m;
  m.title = "still";
  m.scene = "[ball]\nradius = 1\n";
  m.job = "render: still\n";
  m.description = "A ball on a plane.";
  m.software = "rollspin test";
  const Image frame = stillSinkFrame(8, 6, 1);
  for (const StillEncoding encoding : {StillEncoding::Png, StillEncoding::Jpeg}) {
    const std::string ext = encoding == StillEncoding::Png ? ".png" : ".jpg";
    StillImageSink with(dir / ("with" + ext), encoding, false, 90, m);
    with.write(frame.view());
    const OutputMetadata back = parseOutputMetadata(test::readFile(with.finish()), ext);
    EXPECT_EQ(back.scene, m.scene) << ext;
    EXPECT_EQ(back.job, m.job) << ext;
    EXPECT_EQ(back.description, m.description) << ext;
    EXPECT_EQ(back.software, m.software) << ext;
    StillImageSink without(dir / ("without" + ext), encoding, false, 90);
    without.write(frame.view());
    EXPECT_THROW((void)parseOutputMetadata(test::readFile(without.finish()), ext), Error) << ext;
  }
}

// The factories read what applies from SinkOptions: a PNG keeps alpha when
// asked, a JPEG never (and takes the quality), both at options.path.
TEST(StillImageSink, FactoriesTakeThePathAlphaQualityAndMetadataFromTheOptions) {
  const auto dir = test::freshTempDir("still_sink_factories");
  const Image frame = stillSinkFrame(16, 8, 5);
  SinkOptions o;
  o.alpha = true;
  o.jpegQuality = 100;
  o.metadata = OutputMetadata{"t", "scene", "job", "description", "software"};
  o.path = dir / "a.png";
  const auto png = openPngStillSink(o);
  png->write(frame.view());
  EXPECT_EQ(png->finish(), o.path);
  EXPECT_EQ(loadImage(o.path, {}).rgba, frame.rgba);
  EXPECT_EQ(parseOutputMetadata(test::readFile(o.path), "a.png").scene, "scene");
  o.path = dir / "a.jpg";
  const auto jpeg = openJpegStillSink(o);
  jpeg->write(frame.view());
  EXPECT_EQ(jpeg->finish(), o.path);
  const ImageDifference d = compareImages(loadImage(o.path, {}).view(), opaqueCopy(frame).view());
  EXPECT_EQ(d.maxDelta[3], 0) << "a JPEG has no alpha";
  EXPECT_LE(d.meanOverall(), 2.0) << "quality 100";
  EXPECT_EQ(parseOutputMetadata(test::readFile(o.path), "a.jpg").job, "job");
}

}  // namespace
}  // namespace rollspin::media
