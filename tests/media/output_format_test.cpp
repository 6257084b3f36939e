// The output-format table and chooseFormat (no encoder): names and
// extensions are unambiguous, every row is reachable by render.format and
// (files) by its extensions, and a mismatch names the formats that fit.
#include <gtest/gtest.h>

#include <set>

#include "core/error.hpp"
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
  EXPECT_EQ(media::chooseFormat(std::nullopt, {}, "frames/", OutputUse::Animation).kind, media::OutputKind::FrameFolder);
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

}  // namespace
}  // namespace rollspin
