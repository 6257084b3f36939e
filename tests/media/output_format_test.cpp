// The output-format table and chooseFormat (no encoder): names and
// extensions are unambiguous, every row is reachable by render.format and
// (files) by its extensions, and a mismatch names the formats that fit.
#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"
#include "media/h264_levels.hpp"
#include "media/output_format.hpp"

namespace rollspin {
namespace {

using media::OutputUse;

std::string badInputMessage(const std::optional<std::string>& requested, const std::string& output, OutputUse use) {
  try {
    (void)media::chooseFormat(requested, SourceLoc{"scene.toml", 3, 10}, output, use);
  } catch (const Error& e) {
    EXPECT_EQ(e.exitCode(), 2);
    return e.what();
  }
  ADD_FAILURE() << "accepted: " << output;
  return "";
}

TEST(OutputFormat, NamesAndExtensionsAreUnambiguousAndEveryRowIsReachable) {
  std::set<std::pair<std::string, OutputUse>> names;
  std::set<std::string> extensions;
  for (const media::OutputFormat& f : media::kOutputFormats) {
    SCOPED_TRACE(std::string(f.name));
    EXPECT_TRUE(names.emplace(std::string(f.name), f.use()).second) << "one row per name and use";
    EXPECT_TRUE(media::isOutputFormatName(f.name));
    if (f.kind == media::OutputKind::Figure) continue;
    EXPECT_EQ(&media::chooseFormat(std::string(f.name), {}, "", f.use()), &f) << "by render.format";
    std::string rest(f.extensions);
    while (!rest.empty()) {
      const std::string ext = rest.substr(0, rest.find(' '));
      rest = rest.find(' ') == std::string::npos ? "" : rest.substr(rest.find(' ') + 1);
      EXPECT_TRUE(extensions.insert(ext).second) << ext << " names one format";
      EXPECT_EQ(&media::chooseFormat(std::nullopt, {}, "out/clip" + ext, f.use()), &f) << ext;
      EXPECT_EQ(&media::chooseFormat(std::string(f.name), {}, "out/CLIP" + ext, f.use()), &f) << "case-blind";
    }
  }
  EXPECT_FALSE(media::isOutputFormatName("avi"));
}

TEST(OutputFormat, DefaultsAndFolders) {
  EXPECT_EQ(media::chooseFormat(std::nullopt, {}, "", OutputUse::Animation).name, "mp4");
  EXPECT_EQ(media::chooseFormat(std::nullopt, {}, "", OutputUse::Still).name, "png");
  EXPECT_EQ(media::chooseFormat(std::nullopt, {}, "frames/", OutputUse::Animation).kind,
            media::OutputKind::FrameFolder);
  EXPECT_EQ(media::chooseFormat(std::nullopt, {}, "frames", OutputUse::Animation).kind, media::OutputKind::FrameFolder);
  EXPECT_EQ(media::chooseFormat(std::nullopt, {}, "x.jpeg", OutputUse::Still).name, "jpg");
  // render.format names the clip's format: a still of the scene keeps its own choice.
  EXPECT_EQ(media::chooseFormat(std::string("webm"), {}, "x.jpg", OutputUse::Still).name, "jpg");
  EXPECT_EQ(media::chooseFormat(std::string("gif"), {}, "", OutputUse::Still).name, "png");
}

TEST(OutputFormat, AMismatchNamesTheFormatsThatFit) {
  const std::string stillToVideo = badInputMessage(std::nullopt, "x.mp4", OutputUse::Still);
  EXPECT_NE(stillToVideo.find("animation format"), std::string::npos) << stillToVideo;
  EXPECT_NE(stillToVideo.find("jpg (.jpg, .jpeg)"), std::string::npos) << stillToVideo;
  const std::string videoToJpeg = badInputMessage(std::nullopt, "x.jpg", OutputUse::Animation);
  EXPECT_NE(videoToJpeg.find("still format"), std::string::npos) << videoToJpeg;
  for (const char* name : {"mp4", "webm", "gif", "mov", "png (a folder of frames)"})
    EXPECT_NE(videoToJpeg.find(name), std::string::npos) << videoToJpeg;
  const std::string unknown = badInputMessage(std::nullopt, "x.avi", OutputUse::Animation);
  EXPECT_NE(unknown.find(".avi"), std::string::npos) << unknown;
  const std::string contradiction = badInputMessage(std::string("gif"), "x.mp4", OutputUse::Animation);
  EXPECT_NE(contradiction.find("render.format = \"gif\""), std::string::npos) << contradiction;
  const std::string stillFormat = badInputMessage(std::string("jpg"), "", OutputUse::Animation);
  EXPECT_NE(stillFormat.find("still format"), std::string::npos) << stillFormat;
  EXPECT_NE(stillFormat.find("scene.toml:3:10"), std::string::npos) << "keeps the key's place: " << stillFormat;
}

// H.264's largest frame is level 6.2's 139,264 macroblocks: 8192x4320 fits
// (512 x 270 = 138,240), 8192x8192 (262,144) and 8192x4352 (139,264 + 512
// over the line by one row) do not; sizes round up to whole macroblocks.
TEST(H264Levels, TheLargestFrameIsLevel62sAndOnlyMp4EncodesH264) {
  EXPECT_EQ(media::h264Macroblocks(8192, 4320), 138240);
  EXPECT_EQ(media::h264Macroblocks(8190, 4322), 512 * 271);
  EXPECT_TRUE(media::h264HoldsFrame(8192, 4320));
  EXPECT_TRUE(media::h264HoldsFrame(4352, 8192)) << "4352 x 8192 is 272 x 512 = 139,264: exactly the limit";
  EXPECT_FALSE(media::h264HoldsFrame(8192, 8192));
  EXPECT_FALSE(media::h264HoldsFrame(8192, 4368)) << "273 rows of 512";
  EXPECT_FALSE(media::lowestH264Level(8192, 8192, 1).has_value());
  EXPECT_FALSE(media::lowestH264Level(8192, 4320, 121).has_value()) << "6.2's MaxMBPS allows 120 fps at 8K";
  EXPECT_EQ(media::lowestH264Level(8192, 4320, 120)->idc, 62);
  EXPECT_EQ(media::lowestH264Level(1280, 720, 30)->idc, 31);
  for (const media::OutputFormat& f : media::kOutputFormats) EXPECT_EQ(f.encodesH264(), f.name == "mp4") << f.name;
}

}  // namespace
}  // namespace rollspin
