// joinParts on small parts written in-process by the MP4 sink with their
// ContainerTags (no GL, no CLI): given in any order they make one clip on one
// timeline, tagged as the whole render, with the parts' remembered metadata
// and captions joined across a cut; parts that do not belong together are
// refused naming the part and what differs, and no refusal or stop leaves a
// file behind.
#include "media/join_parts.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <functional>
#include <set>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "media/container_tags.hpp"
#include "media/sink_factory.hpp"
#include "media/video_probe.hpp"
#include "support/test_files.hpp"

namespace rollspin::media {
namespace join_parts_test {

namespace fs = std::filesystem;

constexpr int kJoinSize = 32;
constexpr int kJoinClipFrames = 8;

// Clip frame k is one flat colour, far from its neighbours', so a frame out
// of place shows in the joined clip's pixels.
std::array<std::uint8_t, 3> joinColour(long long k) {
  return {static_cast<std::uint8_t>(20 + 28 * k), static_cast<std::uint8_t>(230 - 25 * k),
          static_cast<std::uint8_t>(k % 2 == 0 ? 40 : 200)};
}

struct JoinPart {
  long long first = 0, last = 0;  // the frames it holds, and its tags say
  long long clipFrames = kJoinClipFrames;
  std::string scene = "[ball]\nradius = 1\n";
  std::string version = "9.9.9";
  std::string encoder = "libx264 preset=medium crf=18";
  int width = kJoinSize;
  long long framesWritten = -1;  // -1: as its tags say (an interrupted part has fewer)
  const char* extension = ".mp4";
  bool tagged = true;
  OptionList remembered{};  // more container tags (what jobs/remembered_output reads)
  SubtitleCues cues{};      // in the part's own frames
};

fs::path writeJoinPart(const fs::path& file, const JoinPart& p) {
  SinkOptions o;
  o.path = file;
  o.width = p.width;
  o.height = kJoinSize;
  o.fpsNum = 10;
  o.fpsDen = 1;
  o.subtitles = p.cues;
  if (p.tagged) {
    ContainerTags tags;
    tags.sceneSha256 = sha256Hex(p.scene);
    tags.version = p.version;
    tags.encoderSettings = p.encoder;
    tags.firstFrame = p.first;
    tags.lastFrame = p.last;
    tags.clipFrames = p.clipFrames;
    o.containerMetadata = containerMetadata(tags);
  }
  o.containerMetadata.insert(o.containerMetadata.end(), p.remembered.begin(), p.remembered.end());
  const std::string name = std::string(p.extension).substr(1);
  const auto sink = openSink(*findOutputFormat(name, OutputUse::Animation), o);
  const long long count = p.framesWritten >= 0 ? p.framesWritten : p.last - p.first + 1;
  for (long long k = p.first; k < p.first + count; ++k) {
    Image frame(p.width, kJoinSize);
    const auto c = joinColour(k);
    for (int y = 0; y < kJoinSize; ++y)
      for (int x = 0; x < p.width; ++x) {
        std::copy(c.begin(), c.end(), frame.pixel(x, y));
        frame.pixel(x, y)[3] = 255;
      }
    sink->write(frame.view());
  }
  return sink->finish();
}

std::vector<std::string> joinDirEntries(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(JoinParts, PartsGivenInAnyOrderMakeOneClipOnOneTimeline) {
  const fs::path dir = test::freshTempDir("join_order");
  const long long total = 9;
  const fs::path a = writeJoinPart(dir / "a.mp4", {.first = 0, .last = 2, .clipFrames = total});
  const fs::path b = writeJoinPart(dir / "b.mp4", {.first = 3, .last = 5, .clipFrames = total});
  const fs::path c = writeJoinPart(dir / "c.mp4", {.first = 6, .last = 8, .clipFrames = total});
  const fs::path out = dir / "clip.mp4";
  const JoinSummary summary = joinParts({b, c, a}, out);
  EXPECT_EQ(summary.written, out);
  EXPECT_EQ(summary.frames, total);
  EXPECT_EQ(summary.width, kJoinSize);
  EXPECT_EQ(summary.height, kJoinSize);
  EXPECT_EQ(summary.fpsNum, 10 * summary.fpsDen);
  EXPECT_EQ(joinDirEntries(dir), (std::vector<std::string>{"a.mp4", "b.mp4", "c.mp4", "clip.mp4"}))
      << "no temporary file left";

  std::set<long long> all;
  for (long long k = 0; k < total; ++k) all.insert(k);
  const test::VideoProbe probe = test::probeVideo(out, all);
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_TRUE(probe.indexBeforeData) << "+faststart";
  ASSERT_EQ(probe.ptsSeconds.size(), std::size_t{total});
  ASSERT_EQ(probe.kept.size(), std::size_t{total});
  for (std::size_t k = 0; k < probe.ptsSeconds.size(); ++k) {
    EXPECT_NEAR(probe.ptsSeconds[k], double(k) / 10.0, 1e-6) << "frame " << k << ": one frame every 1/10 s";
    const auto want = joinColour(static_cast<long long>(k));
    const std::uint8_t* got = probe.kept[k].pixel(kJoinSize / 2, kJoinSize / 2);
    for (int ch = 0; ch < 3; ++ch)
      EXPECT_NEAR(int(got[ch]), int(want[ch]), 6) << "frame " << k << " channel " << ch << ": the clip's order";
  }

  // Tagged as the whole render, so that it can be joined or checked again.
  const auto tags = parseContainerTags(readContainerMetadata(out, SourceLoc{out.string()}));
  ASSERT_TRUE(tags.has_value());
  EXPECT_EQ(tags->firstFrame, 0);
  EXPECT_EQ(tags->lastFrame, total - 1);
  EXPECT_EQ(tags->clipFrames, total);
  EXPECT_EQ(tags->version, "9.9.9");
  EXPECT_EQ(tags->sceneSha256, sha256Hex("[ball]\nradius = 1\n"));

  const fs::path again = dir / "again.mp4";
  EXPECT_EQ(joinParts({out}, again).frames, total) << "the joined clip is itself a whole part";
}

// A joined clip must play, and be described by its container, as the whole
// render would be: every frame at its time and in its place; decoding
// timestamps that rise by one frame a packet (a constant-rate stream: each
// sample lasts one frame, so a longer step is a gap that lowers the rate the
// container states) and never come after the packet's presentation; and the
// whole render's frame rate and duration.
void expectPlaysAsTheWholeRender(const fs::path& clip, const test::VideoProbe& whole, long long total) {
  SCOPED_TRACE(clip.filename().string());
  std::set<long long> all;
  for (long long k = 0; k < total; ++k) all.insert(k);
  const test::VideoProbe probe = test::probeVideo(clip, all);
  ASSERT_EQ(probe.ptsSeconds.size(), std::size_t(total));
  ASSERT_EQ(probe.kept.size(), std::size_t(total));
  for (std::size_t k = 0; k < probe.ptsSeconds.size(); ++k) {
    EXPECT_NEAR(probe.ptsSeconds[k], double(k) / 10.0, 1e-6) << "frame " << k;
    const auto want = joinColour(static_cast<long long>(k));
    const std::uint8_t* got = probe.kept[k].pixel(kJoinSize / 2, kJoinSize / 2);
    for (int ch = 0; ch < 3; ++ch) EXPECT_NEAR(int(got[ch]), int(want[ch]), 6) << "frame " << k << " channel " << ch;
  }

  // One frame (1/10 s) in the stream's ticks: MP4's time base holds it whole.
  ASSERT_GT(probe.timeBaseNum, 0);
  const long long frame = probe.timeBaseDen / (10LL * probe.timeBaseNum);
  ASSERT_EQ(frame * 10 * probe.timeBaseNum, probe.timeBaseDen);
  ASSERT_EQ(probe.packetDtsTicks.size(), std::size_t(total));
  ASSERT_EQ(probe.packetPtsTicks.size(), std::size_t(total));
  for (std::size_t k = 0; k < probe.packetDtsTicks.size(); ++k) {
    EXPECT_LE(probe.packetDtsTicks[k], probe.packetPtsTicks[k]) << "packet " << k << " decoded after it is shown";
    if (k > 0) {
      EXPECT_EQ(probe.packetDtsTicks[k] - probe.packetDtsTicks[k - 1], frame)
          << "packet " << k << ": decoding times " << probe.packetDtsTicks[k - 1] << " then "
          << probe.packetDtsTicks[k];
    }
  }
  EXPECT_EQ(probe.frameRateNum, 10 * probe.frameRateDen) << probe.frameRateNum << "/" << probe.frameRateDen;
  EXPECT_EQ(probe.frameRateNum * whole.frameRateDen, whole.frameRateNum * probe.frameRateDen);
  EXPECT_EQ(probe.durationTicks * whole.timeBaseDen * probe.timeBaseNum,
            whole.durationTicks * probe.timeBaseDen * whole.timeBaseNum)
      << "the whole render's duration";
}

// Joins `parts` (given last first), checks the clip against a whole render,
// then joins the clip alone and checks that too.
void expectJoinedTwiceAsTheWholeRender(const std::vector<JoinPart>& parts) {
  const fs::path dir = test::freshTempDir("join_bframes");
  SCOPED_TRACE(fmt::format("first part: frames {}-{}", parts.front().first, parts.front().last));
  const test::VideoProbe whole =
      test::probeVideo(writeJoinPart(dir / "whole.mp4", {.first = 0, .last = kJoinClipFrames - 1}));
  std::vector<fs::path> paths;
  for (const JoinPart& p : parts) paths.push_back(writeJoinPart(dir / fmt::format("p{}.mp4", p.first), p));
  std::reverse(paths.begin(), paths.end());
  const fs::path out = dir / "clip.mp4";
  ASSERT_NO_THROW((void)joinParts(paths, out));
  expectPlaysAsTheWholeRender(out, whole, kJoinClipFrames);

  // "It can itself be joined, or checked, again" (join_parts.hpp).
  const fs::path again = dir / "again.mp4";
  ASSERT_NO_THROW((void)joinParts({out}, again));
  expectPlaysAsTheWholeRender(again, whole, kJoinClipFrames);
}

TEST(JoinParts, PartsWithDifferentBFrameDelaysJoinIntoOneSteadyStream) {
  // x264 (preset medium) gives a 2-frame part no B-frame delay and a 3-frame
  // part some: the short part last, then first.
  expectJoinedTwiceAsTheWholeRender({{.first = 0, .last = 2}, {.first = 3, .last = 5}, {.first = 6, .last = 7}});
  expectJoinedTwiceAsTheWholeRender({{.first = 0, .last = 1}, {.first = 2, .last = 4}, {.first = 5, .last = 7}});
}

TEST(JoinParts, KeepsWhatThePartsRememberButNotAPartsFrameRange) {
  const fs::path dir = test::freshTempDir("join_remembered");
  const OptionList remembered{{"rollspin_scene", "[ball]\nradius = 1\n"},
                              {"rollspin_job", "render: clip\nscene: s\nframes: 0:1\nfigure_layout: false\n"},
                              {"description", "A ball rolls."}};
  const fs::path a = writeJoinPart(dir / "a.mp4", {.first = 0, .last = 1, .clipFrames = 4, .remembered = remembered});
  OptionList second = remembered;
  second[1].second = "render: clip\nscene: s\nframes: 2:3\nfigure_layout: false\n";
  const fs::path b = writeJoinPart(dir / "b.mp4", {.first = 2, .last = 3, .clipFrames = 4, .remembered = second});
  const fs::path out = dir / "clip.mp4";
  (void)joinParts({a, b}, out);
  const auto metadata = readContainerMetadata(out, SourceLoc{out.string()});
  EXPECT_EQ(metadata.at("rollspin_scene"), "[ball]\nradius = 1\n");
  EXPECT_EQ(metadata.at("description"), "A ball rolls.");
  EXPECT_EQ(metadata.at("rollspin_job"), "render: clip\nscene: s\nfigure_layout: false\n")
      << "the clip holds every frame: a part's range would be wrong";
}

TEST(JoinParts, ACaptionCutByAPartBoundaryIsOneCueAgain) {
  const fs::path dir = test::freshTempDir("join_captions");
  // Clip cues: "One" on frames [1, 5) crosses the cut after frame 2; "Two" on [6, 8).
  const fs::path a = writeJoinPart(dir / "a.mp4", {.first = 0, .last = 2, .cues = {{1, 3, "One"}}});
  const fs::path b = writeJoinPart(dir / "b.mp4", {.first = 3, .last = 7, .cues = {{0, 2, "One"}, {3, 5, "Two"}}});
  const JoinSummary summary = joinParts({a, b}, dir / "clip.mp4");
  EXPECT_EQ(summary.cues, (SubtitleCues{{1, 5, "One"}, {6, 8, "Two"}}));
}

// What a refusal must say, and of which file.
struct JoinRefusal {
  const char* name;
  std::vector<JoinPart> parts;  // written as p0.mp4, p1.mp4, …
  int blamed;                   // the part the message names (-1: the output)
  std::string says;
  std::string output = "clip.mp4";
};

TEST(JoinParts, RefusesPartsThatDoNotBelongTogetherNamingThePartAndLeavesNothing) {
  const std::vector<JoinRefusal> refusals{
      {"gap", {{.first = 0, .last = 2}, {.first = 4, .last = 7}}, 1, "frames 3-3 are missing between"},
      {"overlap", {{.first = 0, .last = 3}, {.first = 3, .last = 7}}, 1, "overlaps"},
      {"no start", {{.first = 2, .last = 7}}, 0, "frames 0-1 of the 8-frame clip are missing"},
      {"no end", {{.first = 0, .last = 5}}, 0, "frames 6-7 of the 8-frame clip are missing"},
      {"scene",
       {{.first = 0, .last = 3}, {.first = 4, .last = 7, .scene = "[ball]\nradius = 2\n"}},
       1,
       "comes from a different scene"},
      {"version",
       {{.first = 0, .last = 3}, {.first = 4, .last = 7, .version = "1.0.0"}},
       1,
       "was rendered by rollspin 1.0.0, but"},
      {"clip length",
       {{.first = 0, .last = 3}, {.first = 4, .last = 7, .clipFrames = 9}},
       1,
       "is a part of a 9-frame clip"},
      {"size", {{.first = 0, .last = 3}, {.first = 4, .last = 7, .width = 48}}, 1, "is 48x32, but"},
      {"encoder",
       {{.first = 0, .last = 3}, {.first = 4, .last = 7, .encoder = "libx264 preset=fast crf=18"}},
       1,
       "was encoded with 'libx264 preset=fast crf=18'"},
      {"interrupted",
       {{.first = 0, .last = 3}, {.first = 4, .last = 7, .framesWritten = 2}},
       1,
       "holds 2 frames, but its tags say frames 4-7 (4 frames)"},
      {"untagged", {{.first = 0, .last = 7, .tagged = false}}, 0, "render parts with `rollspin render --shard K/N`"},
      {"container",
       {{.first = 0, .last = 3}, {.first = 4, .last = 7, .extension = ".webm"}},
       1,
       "is a '.webm' file, but"},
      {"captions",
       {{.first = 0, .last = 3}, {.first = 4, .last = 7, .cues = {{0, 1, "Hi"}}}},
       1,
       "has a mov_text subtitle track, but"},
      {"output type",
       {{.first = 0, .last = 7}},
       -1,
       "the parts are '.mp4' files, so the joined clip must be one too",
       "clip.webm"},
  };
  for (const JoinRefusal& r : refusals) {
    SCOPED_TRACE(r.name);
    const fs::path dir = test::freshTempDir("join_refused");
    std::vector<fs::path> parts;
    for (std::size_t k = 0; k < r.parts.size(); ++k)
      parts.push_back(writeJoinPart(dir / fmt::format("p{}{}", k, r.parts[k].extension), r.parts[k]));
    const std::vector<std::string> before = joinDirEntries(dir);
    try {
      (void)joinParts(parts, dir / r.output);
      ADD_FAILURE() << "joined";
    } catch (const Error& e) {
      EXPECT_EQ(e.exitCode(), 2) << e.what();
      const std::string blamed = r.blamed < 0 ? "-o " + (dir / r.output).string() : parts[r.blamed].string();
      EXPECT_EQ(e.where().file, blamed) << e.what();
      EXPECT_NE(e.message().find(r.says), std::string::npos) << e.what();
    }
    EXPECT_EQ(joinDirEntries(dir), before) << "nothing written";
  }
}

TEST(JoinParts, RefusesAPartTwiceAFolderTheOutputAsAPartAndNoParts) {
  const fs::path dir = test::freshTempDir("join_refused_paths");
  const fs::path a = writeJoinPart(dir / "a.mp4", {.first = 0, .last = 3});
  const fs::path b = writeJoinPart(dir / "b.mp4", {.first = 4, .last = 7});
  fs::create_directories(dir / "frames");
  const auto refusal = [&](const std::vector<fs::path>& parts, const fs::path& out) -> Error {
    try {
      (void)joinParts(parts, out);
    } catch (const Error& e) {
      return e;
    }
    ADD_FAILURE() << "joined";
    return Error(ErrorKind::Runtime, {}, "");
  };
  const Error twice = refusal({a, b, dir / "." / "a.mp4"}, dir / "clip.mp4");
  EXPECT_NE(twice.message().find("is given twice"), std::string::npos) << twice.what();
  const Error folder = refusal({a, dir / "frames"}, dir / "clip.mp4");
  EXPECT_EQ(folder.where().file, (dir / "frames").string());
  EXPECT_NE(folder.message().find("is a folder"), std::string::npos) << folder.what();
  const Error self = refusal({a, b}, b);
  EXPECT_EQ(self.where().file, "-o " + b.string());
  EXPECT_NE(self.message().find("is one of the parts"), std::string::npos) << self.what();
  const Error none = refusal({}, dir / "clip.mp4");
  EXPECT_NE(none.message().find("no parts to join"), std::string::npos) << none.what();
  for (const Error& e : {twice, folder, self, none}) EXPECT_EQ(e.exitCode(), 2) << e.what();
  EXPECT_EQ(joinDirEntries(dir), (std::vector<std::string>{"a.mp4", "b.mp4", "frames"}));
}

TEST(JoinParts, AStopWhileReadingOrWritingLeavesNoFile) {
  const fs::path dir = test::freshTempDir("join_stop");
  const fs::path a = writeJoinPart(dir / "a.mp4", {.first = 0, .last = 3});
  const fs::path b = writeJoinPart(dir / "b.mp4", {.first = 4, .last = 7});
  // Polled once per part while reading, then once per packet while writing.
  for (const int stopAt : {1, 5}) {
    SCOPED_TRACE(stopAt);
    int polls = 0;
    const JoinSummary s = joinParts({a, b}, dir / "clip.mp4", [&] { return ++polls >= stopAt; });
    EXPECT_TRUE(s.written.empty());
    EXPECT_EQ(polls, stopAt) << "it ends at the first stop";
    EXPECT_EQ(joinDirEntries(dir), (std::vector<std::string>{"a.mp4", "b.mp4"}));
  }
}

}  // namespace join_parts_test
}  // namespace rollspin::media
