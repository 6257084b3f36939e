// Captions as text through the CLI (label gl): a storyboard's title and
// captions become a subtitle track (mov_text in MP4 and MOV, webvtt in
// WebM, as ffprobe names it) and sidecar files (NAME.vtt; NAME.srt with
// --subtitles srt), read back with the ffmpeg tool and a WebVTT parser here
// and checked against the scene's captions and timing; shards joined give
// the whole clip's track; render.burn_captions = false leaves the text out
// of the pixels. Clips are 96×64 at 2 fps (31 frames): a few seconds each.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "support/cli_runner.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

struct Cue {
  double start = 0.0, end = 0.0;  // seconds
  std::string text;
};

// "hh:mm:ss.mmm" or "mm:ss.mmm" (WebVTT), "hh:mm:ss,mmm" (SubRip).
double parseClock(std::string t) {
  for (char& c : t)
    if (c == ',') c = '.';
  double seconds = 0.0;
  std::size_t start = 0;
  while (true) {
    const std::size_t colon = t.find(':', start);
    if (colon == std::string::npos) return seconds * 60.0 + std::stod(t.substr(start));
    seconds = seconds * 60.0 + std::stod(t.substr(start, colon - start));
    start = colon + 1;
  }
}

// WebVTT (and SubRip, whose blocks start with a number line): each block
// with a "-->" line is a cue, its following lines the text; cue settings
// after the end time are ignored; entities decoded.
std::vector<Cue> parseCues(const std::string& document) {
  std::vector<Cue> cues;
  std::vector<std::string> lines;
  std::size_t start = 0;
  while (start < document.size()) {
    const std::size_t end = std::min(document.find('\n', start), document.size());
    std::string line = document.substr(start, end - start);
    if (!line.empty() && line.back() == '\r') line.pop_back();
    lines.push_back(line);
    start = end + 1;
  }
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::size_t arrow = lines[i].find(" --> ");
    if (arrow == std::string::npos) continue;
    Cue cue;
    cue.start = parseClock(lines[i].substr(0, arrow));
    const std::string rest = lines[i].substr(arrow + 5);
    cue.end = parseClock(rest.substr(0, rest.find(' ')));
    for (++i; i < lines.size() && !lines[i].empty(); ++i) cue.text += (cue.text.empty() ? "" : "\n") + lines[i];
    --i;
    for (const auto& [entity, c] : {std::pair{"&lt;", "<"}, {"&gt;", ">"}, {"&amp;", "&"}})
      for (std::size_t p; (p = cue.text.find(entity)) != std::string::npos;)
        cue.text.replace(p, std::strlen(entity), c);
    cues.push_back(cue);
  }
  return cues;
}

// scenes/storyboard.toml at 2 fps: an opening hold of round(0.5·2) = 1
// frame, the line's 3 s = 6 frames, the circle's 7 s = 14, the rest's 2.5 s
// = 5, the last line's 3/1.5 = 2 s = 4, a closing hold of 1: 31 frames.
// The opening hold shows the first segment, the closing hold the last, so
// the captions change at frames 7, 21 and 26: 3.5 s, 10.5 s and 13 s, and
// the clip ends at 15.5 s. Each cue: the title, then the caption (as the
// scene file writes them).
const char* kTitle = "A rolling ball is a spin-1/2 in a field";
std::vector<Cue> storyboardCues() {
  const double fps = 2.0;
  const std::vector<std::pair<long long, const char*>> segments{
      {1 + 6, "a straight roll: a constant field, one axis"},
      {14, "once around: δ = 2π√(1 + (r/R)²) = 2π√10 ≈ 19.87 rad"},
      {5, "back where the circle began, but turned by 58.4°"},
      {4 + 1, "rolling on: the turn stays"}};
  std::vector<Cue> cues;
  long long frame = 0;
  for (const auto& [frames, caption] : segments) {
    cues.push_back({double(frame) / fps, double(frame + frames) / fps, std::string(kTitle) + "\n" + caption});
    frame += frames;
  }
  return cues;
}

void expectCues(const std::vector<Cue>& actual, const std::vector<Cue>& expected, const std::string& what) {
  ASSERT_EQ(actual.size(), expected.size()) << what;
  for (std::size_t k = 0; k < actual.size(); ++k) {
    EXPECT_NEAR(actual[k].start, expected[k].start, 0.0015) << what << " cue " << k;  // milliseconds, rounded
    EXPECT_NEAR(actual[k].end, expected[k].end, 0.0015) << what << " cue " << k;
    EXPECT_EQ(actual[k].text, expected[k].text) << what << " cue " << k;
  }
}

std::vector<std::string> story(const fs::path& out, std::vector<std::string> extra = {}) {
  std::vector<std::string> args{"render", test::shippedScenePath("storyboard"), "-o", out.string(), "--quiet"};
  for (const char* s : {"render.width=96", "render.height=64", "animation.fps=2"}) {
    args.push_back("--set");
    args.push_back(s);
  }
  args.insert(args.end(), extra.begin(), extra.end());
  return args;
}

std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// A command's standard output ("" when it fails).
std::string commandOutput(const std::string& command) {
  std::string out;
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) return out;
  char buffer[4096];
  for (std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, pipe)) > 0;) out.append(buffer, n);
  return pclose(pipe) == 0 ? out : std::string();
}

// What ffprobe says of the first subtitle stream: "codec,default-flag".
std::string probeSubtitleStream(const fs::path& video) {
  std::string out = commandOutput(
      "ffprobe -v error -select_streams s -show_entries stream=codec_name:"
      "stream_disposition=default -of csv=p=0 " +
      shellQuote(video.string()));
  while (!out.empty() && (out.back() == '\n' || out.back() == ',')) out.pop_back();
  return out;
}

// The in-band track, converted to WebVTT by the ffmpeg tool.
std::vector<Cue> trackCues(const fs::path& video) {
  return parseCues(
      commandOutput("ffmpeg -nostdin -v error -i " + shellQuote(video.string()) + " -map 0:s:0 -f webvtt -"));
}

bool haveFfmpegTools() { return std::system("command -v ffmpeg >/dev/null && command -v ffprobe >/dev/null") == 0; }

TEST(SubtitlesCli, EveryVideoFormatCarriesTheScenesCaptionsAsATrackAndSidecars) {
  if (!haveFfmpegTools()) GTEST_SKIP() << "the ffmpeg and ffprobe tools are missing (Debian: apt-get install ffmpeg)";
  const fs::path dir = test::freshTempDir("subtitles_formats");
  const std::vector<Cue> expected = storyboardCues();
  struct Case {
    const char* file;
    std::vector<std::string> flags;
    const char* codec;
  };
  for (const Case& c : {Case{"a.mp4", {}, "mov_text"}, Case{"b.webm", {"--subtitles", "srt"}, "webvtt"},
                        Case{"c.mov", {"--subtitles", "none"}, "mov_text"}}) {
    const fs::path video = dir / c.file;
    const auto r = test::runRollspin(story(video, c.flags));
    ASSERT_EQ(r.exitCode, 0) << c.file << ": " << r.err;
    // Burned captions: WebM's track is there for whoever wants it, not
    // flagged default; MP4 and MOV mark their one text track enabled whatever
    // rollspin asks (libavformat's mov muxer), which ffprobe shows as default.
    const bool webm = std::string(c.codec) == "webvtt";
    EXPECT_EQ(probeSubtitleStream(video), std::string(c.codec) + (webm ? ",0" : ",1")) << c.file;
    expectCues(trackCues(video), expected, std::string(c.file) + "'s track");
    const fs::path vtt = fs::path(video).replace_extension(".vtt"), srt = fs::path(video).replace_extension(".srt");
    const bool none = !c.flags.empty() && c.flags[1] == "none", withSrt = !c.flags.empty() && c.flags[1] == "srt";
    EXPECT_EQ(fs::exists(vtt), !none) << vtt;
    EXPECT_EQ(fs::exists(srt), withSrt) << srt;
    if (!none) {
      const std::string document = test::readFile(vtt);
      EXPECT_EQ(document.rfind("WEBVTT\n", 0), 0u) << document;
      expectCues(parseCues(document), expected, vtt.string());
    }
    if (withSrt) expectCues(parseCues(test::readFile(srt)), expected, srt.string());
  }
}

// Parts of a split render carry their own frames' cues and no sidecars;
// joined, the track and the sidecar are the whole render's.
TEST(SubtitlesCli, ShardsJoinedCarryTheWholeClipsTrack) {
  if (!haveFfmpegTools()) GTEST_SKIP() << "the ffmpeg and ffprobe tools are missing (Debian: apt-get install ffmpeg)";
  const fs::path dir = test::freshTempDir("subtitles_shards");
  ASSERT_EQ(test::runRollspin(story(dir / "whole.mp4")).exitCode, 0);
  std::vector<std::string> join{"join", "-o", (dir / "joined.mp4").string(), "--quiet"};
  for (int k = 1; k <= 3; ++k) {
    const auto r = test::runRollspin(story(dir / "s.mp4", {"--shard", fmt::format("{}/3", k)}));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    join.push_back((dir / fmt::format("s.part-{}-of-3.mp4", k)).string());
  }
  for (int k = 1; k <= 3; ++k) EXPECT_FALSE(fs::exists(dir / fmt::format("s.part-{}-of-3.vtt", k))) << k;
  EXPECT_FALSE(fs::exists(dir / "s.vtt"));
  // The second part starts inside the circle's cue (frames 7 … 20): its
  // track opens with the rest of it.
  const std::vector<Cue> second = trackCues(dir / "s.part-2-of-3.mp4");
  ASSERT_FALSE(second.empty());
  EXPECT_EQ(second.front().start, 0.0);
  EXPECT_EQ(second.front().text, storyboardCues()[1].text);
  const auto r = test::runRollspin(join);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(probeSubtitleStream(dir / "joined.mp4"), probeSubtitleStream(dir / "whole.mp4"));
  expectCues(trackCues(dir / "joined.mp4"), storyboardCues(), "the joined track");
  EXPECT_EQ(test::readFile(dir / "joined.vtt"), test::readFile(dir / "whole.vtt"));
}

// A two-step storyboard whose second step is a hold at the first's end:
// the same pose on both sides of the caption change.
constexpr const char* kTwoCaptions = R"(
[surface]
kind = "plane"
[render]
title = "T"
width = 96
height = 64
[animation]
fps = 4
[[segment]]
path = { kind = "line", length = 2 }
duration = 1
caption = "first"
[[segment]]
hold = 1
caption = "second"
)";

TEST(SubtitlesCli, BurnCaptionsFalseLeavesTheTextOutOfThePixels) {
  if (!haveFfmpegTools()) GTEST_SKIP() << "the ffmpeg and ffprobe tools are missing (Debian: apt-get install ffmpeg)";
  const fs::path dir = test::freshTempDir("subtitles_burn");
  const fs::path scene = dir / "two.toml";
  std::FILE* f = std::fopen(scene.c_str(), "w");
  ASSERT_NE(f, nullptr);
  std::fputs(kTwoCaptions, f);
  std::fclose(f);
  // 4 fps: opening hold 2 frames, the line 4 (frames 2 … 5, ending at s = 2),
  // the hold 4 (frames 6 … 9) at s = 2, closing hold 2: frames 5 and 6 show
  // one pose under two captions.
  auto frames = [&](const char* folder, const char* burn) {
    std::vector<std::string> args{"render", scene.string(),          "--frames", "5:6",
                                  "-o",     (dir / folder).string(), "--quiet"};
    if (burn != nullptr) args.insert(args.end(), {"--set", std::string("render.burn_captions=") + burn});
    const auto r = test::runRollspin(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return std::pair{test::readFile(dir / folder / "frame_00005.png"),
                     test::readFile(dir / folder / "frame_00006.png")};
  };
  const auto burned = frames("default", nullptr), explicitTrue = frames("true", "true"),
             bare = frames("false", "false");
  ASSERT_FALSE(burned.first.empty());
  EXPECT_NE(burned.first, burned.second) << "the caption change should show in the default's pixels";
  EXPECT_TRUE(explicitTrue == burned) << "burn_captions = true must be the default's pixels";
  EXPECT_TRUE(bare.first == bare.second) << "without burned captions the same pose is the same pixels";
  EXPECT_NE(bare.first, burned.first);
  // The clip's track is then the only caption: flagged to show unasked.
  const fs::path video = dir / "two.webm";
  const auto r = test::runRollspin(
      {"render", scene.string(), "-o", video.string(), "--quiet", "--set", "render.burn_captions=false"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(probeSubtitleStream(video), "webvtt,1");
  // Opening hold + line: frames 0 … 5 (0 – 1.5 s); the hold and the closing hold: 6 … 11 (1.5 – 3 s).
  expectCues(trackCues(video), {{0.0, 1.5, "T\nfirst"}, {1.5, 3.0, "T\nsecond"}}, "two.webm's track");
}

TEST(SubtitlesCli, BadSubtitlesValueIsExit2NamingTheFlag) {
  const fs::path dir = test::freshTempDir("subtitles_bad");
  const auto r = test::runRollspin(story(dir / "s.mp4", {"--subtitles", "ass"}));
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("--subtitles ass"), std::string::npos) << r.err;
  EXPECT_TRUE(fs::is_empty(dir));
  const auto still = test::runRollspin({"render", test::shippedScenePath("storyboard"), "--still", "--subtitles", "vtt",
                                        "-o", (dir / "s.png").string()});
  EXPECT_EQ(still.exitCode, 2) << still.err;
  EXPECT_NE(still.err.find("--subtitles"), std::string::npos) << still.err;
}

}  // namespace
}  // namespace rollspin
