// Subtitle cues (media/subtitle_track): frame times in milliseconds from the
// exact rational frame rate, cues cut into parts and made whole again, the
// WebVTT and SubRip documents, the --subtitles values, mov_text's packet
// text, and sidecar files that appear only on commit.
#include <gtest/gtest.h>

#include <random>

#include "core/error.hpp"
#include "media/subtitle_track.hpp"
#include "support/test_files.hpp"

namespace rollspin::media {
namespace {

namespace fs = std::filesystem;

TEST(SubtitleTrack, FrameMillisecondsRoundExactRationalsToNearest) {
  for (const auto& [num, den] : {std::pair{30, 1}, {30000, 1001}, {24000, 1001}, {15, 1}, {60, 1}}) {
    for (long long k : {0LL, 1LL, 2LL, 3LL, 29LL, 1799LL, 107892LL, 9'999'999LL}) {
      // The same time in long double: k · 1000 · den / num.
      const long double exact = static_cast<long double>(k) * 1000.0L * den / num;
      const long long ms = frameMilliseconds(k, num, den);
      EXPECT_LE(std::abs(static_cast<long double>(ms) - exact), 0.5L) << k << " at " << num << "/" << den;
    }
  }
  EXPECT_EQ(frameMilliseconds(1, 30000, 1001), 33);  // 33.367 ms
  EXPECT_EQ(frameMilliseconds(2, 30000, 1001), 67);  // 66.733 ms
}

TEST(SubtitleTrack, AppendCueMergesOnlyACueThatContinuesTheLast) {
  SubtitleCues cues;
  appendCue(cues, {0, 10, "a"});
  appendCue(cues, {10, 14, "a"});  // continues: merged
  appendCue(cues, {14, 20, "b"});  // another text
  appendCue(cues, {22, 30, "b"});  // a gap: a cue of its own
  appendCue(cues, {30, 30, "c"});  // empty: dropped
  appendCue(cues, {30, 31, ""});   // no text: dropped
  ASSERT_EQ(cues.size(), 3u);
  EXPECT_EQ(cues[0], (SubtitleCue{0, 14, "a"}));
  EXPECT_EQ(cues[1], (SubtitleCue{14, 20, "b"}));
  EXPECT_EQ(cues[2], (SubtitleCue{22, 30, "b"}));
}

// What render --shard and join do: each part keeps its frames' cues, moved to
// its own frame 0; joined back in order they are the clip's cues again.
TEST(SubtitleTrack, PartsCutAndAppendedBackAreTheWholeTrack) {
  const SubtitleCues whole{{0, 14, "title\nfirst"}, {14, 42, "title\nsecond"}, {42, 52, "third"}, {55, 62, "last"}};
  std::mt19937 random(7);
  for (int trial = 0; trial < 200; ++trial) {
    // Random cut points in [1, 61] split frames 0 … 61 into parts.
    std::vector<long long> cuts{0, 62};
    for (int c = 0; c < trial % 6; ++c) cuts.push_back(1 + static_cast<long long>(random() % 61));
    std::sort(cuts.begin(), cuts.end());
    cuts.erase(std::unique(cuts.begin(), cuts.end()), cuts.end());
    SubtitleCues joined;
    for (std::size_t p = 0; p + 1 < cuts.size(); ++p) {
      const SubtitleCues part = cuesOfPart(whole, cuts[p], cuts[p + 1] - 1);
      for (const SubtitleCue& c : part) {
        EXPECT_GE(c.firstFrame, 0);
        EXPECT_LE(c.endFrame, cuts[p + 1] - cuts[p]);
        appendCue(joined, {c.firstFrame + cuts[p], c.endFrame + cuts[p], c.text});
      }
    }
    EXPECT_EQ(joined, whole) << "trial " << trial;
  }
  EXPECT_EQ(cuesOfPart(whole, 52, 54), SubtitleCues{});  // between cues
}

TEST(SubtitleTrack, WebvttDocumentHasTheCuesTimesAndEscapedText) {
  // 4 fps: frame 14 is 3.5 s, frame 14406 is 1 h 0 min 1.5 s.
  const SubtitleCues cues{{0, 14, "A <b> & c\n\nsecond line"}, {14, 14406, "δ ≈ 19.87 rad -->"}};
  EXPECT_EQ(webvttDocument(cues, 4, 1),
            "WEBVTT\n\n"
            "00:00:00.000 --> 00:00:03.500\nA &lt;b&gt; &amp; c\nsecond line\n\n"
            "00:00:03.500 --> 01:00:01.500\nδ ≈ 19.87 rad --&gt;\n\n");
  EXPECT_EQ(webvttDocument({}, 30, 1), "WEBVTT\n\n");
}

TEST(SubtitleTrack, SrtDocumentNumbersItsCuesWithCommaMilliseconds) {
  const SubtitleCues cues{{0, 1, "one"}, {2, 3, "two\nlines"}};
  EXPECT_EQ(srtDocument(cues, 30000, 1001),
            "1\n00:00:00,000 --> 00:00:00,033\none\n\n"
            "2\n00:00:00,067 --> 00:00:00,100\ntwo\nlines\n\n");
}

TEST(SubtitleTrack, SidecarFormatsAreVttSrtOrNone) {
  EXPECT_EQ(parseSidecarFormats("vtt", "--subtitles"), SidecarFormats::Vtt);
  EXPECT_EQ(parseSidecarFormats("srt", "--subtitles"), SidecarFormats::VttAndSrt);
  EXPECT_EQ(parseSidecarFormats("none", "--subtitles"), SidecarFormats::None);
  try {
    (void)parseSidecarFormats("ass", "--subtitles");
    FAIL() << "accepted 'ass'";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
    EXPECT_NE(e.where().file.find("--subtitles ass"), std::string::npos) << e.where().file;
    EXPECT_NE(e.message().find("vtt"), std::string::npos) << e.message();
  }
}

TEST(SubtitleTrack, MovTextPacketTextIsItsLengthPrefixedText) {
  const std::string text = "once around: δ";
  std::string payload;
  payload += static_cast<char>(text.size() >> 8);
  payload += static_cast<char>(text.size() & 0xff);
  payload += text + std::string("\0\0\0\x0cstyl", 8);  // a style box after the text is not text
  EXPECT_EQ(cueTextOfPacket(payload, true), text);
  EXPECT_EQ(cueTextOfPacket(std::string("\0\0", 2), true), "");  // MP4's filler between cues
  EXPECT_EQ(cueTextOfPacket("", true), "");
  EXPECT_EQ(cueTextOfPacket(text, false), text);  // WebVTT in WebM: the text itself
}

std::vector<std::string> namesIn(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(SubtitleTrack, SidecarsAppearOnlyOnCommitAndLeaveNothingOtherwise) {
  const fs::path dir = test::freshTempDir("subtitle_sidecars");
  const SubtitleCues cues{{0, 30, "hello"}};
  {
    SubtitleSidecars files(dir / "clip.mp4", SidecarFormats::VttAndSrt, cues, 30, 1);
    EXPECT_EQ(namesIn(dir).size(), 2u);  // two temporaries, hidden
    for (const std::string& name : namesIn(dir)) EXPECT_EQ(name.front(), '.') << name;
  }  // not committed
  EXPECT_TRUE(namesIn(dir).empty());
  {
    SubtitleSidecars files(dir / "clip.mp4", SidecarFormats::VttAndSrt, cues, 30, 1);
    files.commit();
    EXPECT_EQ(files.paths(), (std::vector<fs::path>{dir / "clip.vtt", dir / "clip.srt"}));
  }
  EXPECT_EQ(namesIn(dir), (std::vector<std::string>{"clip.srt", "clip.vtt"}));
  EXPECT_EQ(test::readFile(dir / "clip.vtt"), webvttDocument(cues, 30, 1));
  EXPECT_EQ(test::readFile(dir / "clip.srt"), srtDocument(cues, 30, 1));
  SubtitleSidecars none(dir / "other.webm", SidecarFormats::None, cues, 30, 1);
  none.commit();
  SubtitleSidecars noCues(dir / "plain.mp4", SidecarFormats::VttAndSrt, {}, 30, 1);  // no title, no caption
  noCues.commit();
  EXPECT_TRUE(noCues.paths().empty());
  SubtitleSidecars device("/dev/null", SidecarFormats::Vtt, cues, 30, 1);  // a device gets none
  device.commit();
  EXPECT_TRUE(device.paths().empty());
  EXPECT_EQ(namesIn(dir).size(), 2u);
}

}  // namespace
}  // namespace rollspin::media
