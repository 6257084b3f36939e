// A render split across processes as the README's "A render across machines" does it: three
// `render --shard K/3` run by GNU parallel, then `rollspin join`. The joined
// clip is decoded and checked against a full render's PNG frames (every
// frame, PSNR), its timestamps and tags read back, and it is decoded by the
// ffmpeg tool with errors fatal. Parts that do not belong together (another
// scene, a missing part, an overlap, another size, a partial file) are refused
// with exit 2 naming the part, and nothing is written. Tiny clips (160×90,
// 30 frames) keep the suite at a few seconds.
#include <gtest/gtest.h>

extern "C" {
#include <libavformat/avformat.h>
}

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <map>

#include "media/image_io.hpp"
#include "media/video_probe.hpp"
#include "support/cli_runner.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;

constexpr long long kClipFrames = 30;  // 0.6 s × 30 fps + 2 holds of 0.2 s

std::string scene(const char* name) { return (test::sourceDir() / "scenes" / name).string(); }

std::vector<std::string> tiny(std::vector<std::string> args, const char* size = "160x90") {
  const std::string s = size;
  const std::string w = s.substr(0, s.find('x')), h = s.substr(s.find('x') + 1);
  for (const std::string& set : {"render.width=" + w, "render.height=" + h, std::string("animation.fps=30"),
                                 std::string("animation.duration=0.6"), std::string("animation.hold=0.2")}) {
    args.push_back("--set");
    args.push_back(set);
  }
  args.push_back("--quiet");
  return args;
}

std::string shellQuote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

// The container's tags, as ffprobe lists them under [FORMAT].
std::map<std::string, std::string> formatTags(const fs::path& file) {
  std::map<std::string, std::string> tags;
  AVFormatContext* format = nullptr;
  if (avformat_open_input(&format, file.c_str(), nullptr, nullptr) < 0) return tags;
  const AVDictionaryEntry* e = nullptr;
  while ((e = av_dict_get(format->metadata, "", e, AV_DICT_IGNORE_SUFFIX)) != nullptr) tags[e->key] = e->value;
  avformat_close_input(&format);
  return tags;
}

// Peak signal-to-noise ratio over R, G, B (alpha ignored), in dB.
double psnrRgb(const media::ImageView& a, const media::ImageView& b) {
  double sum = 0.0;
  for (int y = 0; y < a.height; ++y) {
    const std::uint8_t* ra = a.rowFromTop(y);
    const std::uint8_t* rb = b.rowFromTop(y);
    for (int x = 0; x < a.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const double d = double(ra[4 * x + c]) - double(rb[4 * x + c]);
        sum += d * d;
      }
  }
  const double mse = sum / (3.0 * a.width * a.height);
  return mse == 0.0 ? 99.0 : 10.0 * std::log10(255.0 * 255.0 / mse);
}

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

class ShardJoin : public ::testing::Test {
 protected:
  // Rendered once for the suite: three shards run by GNU parallel, as the
  // README's "A render across machines" does on one machine.
  static void SetUpTestSuite() {
    dir_ = new fs::path(test::freshTempDir("shard_join"));
    std::string command = "parallel --will-cite -q --halt now,fail=1 -j3 " + shellQuote(test::binaryPath().string());
    for (const std::string& a :
         tiny({"render", scene("lollipop.toml"), "--shard", "{}/3", "-o", (*dir_ / "parts" / "clip.mp4").string()})) {
      command += ' ';  // two appends: GCC 12 warns (-Wrestrict, a false positive) on " " + string here
      command += shellQuote(a);
    }
    command += " ::: 1 2 3 2>" + shellQuote((*dir_ / "parallel.log").string());
    fs::create_directories(*dir_ / "parts");
    const int status = std::system(command.c_str());
    ASSERT_EQ(status, 0) << command << "\n(GNU parallel missing? bash scripts/install-deps.sh)\n"
                         << test::readFile(*dir_ / "parallel.log");
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }
  static fs::path part(int k) { return *dir_ / "parts" / fmt::format("clip.part-{}-of-3.mp4", k); }
  static fs::path dir() { return *dir_; }

  // A join that must be refused: exit 2, the message names `culprit` and says
  // `what`, and nothing appears at -o (no temporary file either).
  static void expectRefused(const std::vector<fs::path>& parts, const fs::path& culprit, const std::string& what) {
    const fs::path outDir = test::freshTempDir("shard_join_refused");
    std::vector<std::string> args{"join"};
    for (const auto& p : parts) args.push_back(p.string());
    args.push_back("-o");
    args.push_back((outDir / "joined.mp4").string());
    const auto r = test::runRollspin(args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find(culprit.string() + ": "), std::string::npos) << "names the part: " << r.err;
    EXPECT_NE(r.err.find(what), std::string::npos) << "says what differs (" << what << "): " << r.err;
    EXPECT_TRUE(filesIn(outDir).empty()) << "nothing written";
    std::fprintf(stderr, "refused as expected: %s", r.err.c_str());
  }

 private:
  static fs::path* dir_;
};
fs::path* ShardJoin::dir_ = nullptr;

TEST_F(ShardJoin, ShardsAreNamedToSortAndTaggedWithTheirRange) {
  EXPECT_EQ(filesIn(dir() / "parts"),
            (std::vector<std::string>{"clip.part-1-of-3.mp4", "clip.part-2-of-3.mp4", "clip.part-3-of-3.mp4"}));
  const char* ranges[] = {"0-9", "10-19", "20-29"};  // 30 frames in three near-equal ranges
  std::string sceneHash;
  for (int k = 1; k <= 3; ++k) {
    const auto tags = formatTags(part(k));
    EXPECT_EQ(tags.count("rollspin_frames") ? tags.at("rollspin_frames") : "", ranges[k - 1]) << k;
    EXPECT_EQ(tags.count("rollspin_clip_frames") ? tags.at("rollspin_clip_frames") : "", "30") << k;
    EXPECT_EQ(tags.count("rollspin_encoder") ? tags.at("rollspin_encoder") : "",
              "mp4 preset=medium crf=default 160x90 30/1 fps");  // the format row, its settings, size, rate
    EXPECT_FALSE(tags.count("rollspin_version") ? tags.at("rollspin_version").empty() : true);
    const std::string hash = tags.count("rollspin_scene_sha256") ? tags.at("rollspin_scene_sha256") : "";
    EXPECT_EQ(hash.size(), 64u);
    if (k == 1) sceneHash = hash;
    EXPECT_EQ(hash, sceneHash) << "one scene, one hash";
  }
  // The hash is of the resolved text, so `scene --print`'s input changes it.
  const fs::path other = test::freshTempDir("shard_join_hash") / "other.mp4";
  auto args =
      tiny({"render", scene("lollipop.toml"), "--frames", "0:1", "--set", "path.radius=2", "-o", other.string()});
  ASSERT_EQ(test::runRollspin(args).exitCode, 0);
  EXPECT_NE(formatTags(other)["rollspin_scene_sha256"], sceneHash);
}

TEST_F(ShardJoin, JoinedClipHasEveryFrameOnOneTimelineAndMatchesTheFullRender) {
  // The reference: the whole clip rendered at once, as PNG frames and as one encode.
  const auto full = test::runRollspin(tiny({"render", scene("lollipop.toml"), "-o", (dir() / "frames").string()}));
  ASSERT_EQ(full.exitCode, 0) << full.err;
  const auto once = test::runRollspin(tiny({"render", scene("lollipop.toml"), "-o", (dir() / "single.mp4").string()}));
  ASSERT_EQ(once.exitCode, 0) << once.err;

  const fs::path out = dir() / "joined.mp4";
  // Given out of order: join sorts by the tagged ranges.
  const auto r = test::runRollspin({"join", part(3).string(), part(1).string(), part(2).string(), "-o", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("30 frames"), std::string::npos) << r.err;

  std::set<long long> all;
  for (long long k = 0; k < kClipFrames; ++k) all.insert(k);
  const test::VideoProbe probe = test::probeVideo(out, all);
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.colorSpace, "bt709");
  EXPECT_TRUE(probe.indexBeforeData) << "+faststart";
  EXPECT_EQ(probe.frameRateNum, 30);
  EXPECT_EQ(probe.frameRateDen, 1);
  ASSERT_EQ(static_cast<long long>(probe.ptsTicks.size()), kClipFrames) << "the full render's frame count";
  // Continuous: frame k exactly k frame durations in, as in a single render.
  const long long tick = probe.ptsTicks.size() > 1 ? probe.ptsTicks[1] - probe.ptsTicks[0] : 0;
  EXPECT_GT(tick, 0);
  for (std::size_t k = 0; k < probe.ptsTicks.size(); ++k)
    EXPECT_EQ(probe.ptsTicks[k], static_cast<long long>(k) * tick) << "frame " << k;
  EXPECT_NEAR(tick * double(probe.timeBaseNum) / probe.timeBaseDen, 1.0 / 30.0, 1e-12);

  const auto tags = formatTags(out);
  EXPECT_EQ(tags.count("rollspin_frames") ? tags.at("rollspin_frames") : "", "0-29") << "tagged as the whole clip";
  EXPECT_EQ(tags.count("rollspin_scene_sha256") ? tags.at("rollspin_scene_sha256") : "",
            formatTags(part(1))["rollspin_scene_sha256"]);

  // Every decoded frame against the same frame of the full render (PNG),
  // beside the same frame of a single encode of the whole clip: joining must
  // cost nothing beyond the encoder's own loss.
  const test::VideoProbe single = test::probeVideo(dir() / "single.mp4", all);
  ASSERT_EQ(static_cast<long long>(probe.kept.size()), kClipFrames);
  ASSERT_EQ(static_cast<long long>(single.kept.size()), kClipFrames);
  double worst = 99.0, best = 0.0, worstSingle = 99.0, worstGap = -99.0;
  for (long long k = 0; k < kClipFrames; ++k) {
    const media::Image png = media::loadImage(dir() / "frames" / fmt::format("frame_{:05d}.png", k), {});
    ASSERT_EQ(png.width, probe.kept[k].width);
    const double p = psnrRgb(probe.kept[k].view(), png.view());
    const double pSingle = psnrRgb(single.kept[k].view(), png.view());
    // Thresholds: H.264 at CRF 18 with 4:2:0 chroma smears the thin red and
    // blue lines and the text of a 160×90 frame, so even a single encode
    // scores only 27.2–32.4 dB here (measured on this machine), and
    // the joined frames 27.2–32.2 dB, 0.4 dB below it at worst (another GOP
    // structure: the parts restart with a keyframe). The floor of 25 dB and
    // the 1 dB allowance leave room for another CPU's llvmpipe and x264.
    EXPECT_GE(p, 25.0) << "frame " << k;
    EXPECT_LE(pSingle - p, 1.0) << "frame " << k << ": joined " << p << " dB, single encode " << pSingle << " dB";
    worst = std::min(worst, p);
    best = std::max(best, p);
    worstSingle = std::min(worstSingle, pSingle);
    worstGap = std::max(worstGap, pSingle - p);
  }
  // A frame against a neighbour 5 frames away (the ball moved) must score
  // clearly lower, or the comparison could not tell frames apart.
  const media::Image png15 = media::loadImage(dir() / "frames" / "frame_00015.png", {});
  const double wrongFrame = psnrRgb(probe.kept[10].view(), png15.view());
  EXPECT_LT(wrongFrame, worst - 3.0) << "the comparison cannot tell frames apart";
  std::fprintf(stderr,
               "joined vs full render's PNG frames: PSNR %.2f … %.2f dB (single encode: worst %.2f dB; largest "
               "shortfall of a joined frame %.2f dB); frame 10 vs PNG 15: %.2f dB\n",
               worst, best, worstSingle, worstGap, wrongFrame);

  // The ffmpeg tool decodes it with any decoding error fatal and silent otherwise.
  const fs::path log = dir() / "ffmpeg.log";
  const std::string decode =
      "ffmpeg -nostdin -v error -xerror -i " + shellQuote(out.string()) + " -f null - 2>" + shellQuote(log.string());
  EXPECT_EQ(std::system(decode.c_str()), 0) << test::readFile(log);
  EXPECT_EQ(test::readFile(log), "") << "decoder messages";
}

// join knows no container by name: parts moved into MOV (stream copy) or
// re-encoded to VP9 in WebM by the ffmpeg tool, their tags kept, join the same
// way (WebM stores tag names in upper case and time in milliseconds: frame k
// lands on round(k·1000/30) ms as in a single WebM).
TEST_F(ShardJoin, MovAndWebmPartsJoinTheSameWay) {
  const fs::path d = test::freshTempDir("shard_join_containers");
  for (const char* ext : {"mov", "webm"}) {
    std::vector<std::string> args{"join"};
    for (int k = 1; k <= 3; ++k) {
      const fs::path p = d / fmt::format("clip.part-{}-of-3.{}", k, ext);
      const std::string codec =
          std::string(ext) == "mov" ? "-c copy -movflags +use_metadata_tags" : "-c:v libvpx-vp9 -crf 40 -b:v 0 -g 1000";
      const std::string convert = "ffmpeg -nostdin -v error -i " + shellQuote(part(k).string()) + " -map_metadata 0 " +
                                  codec + " " + shellQuote(p.string());
      ASSERT_EQ(std::system(convert.c_str()), 0) << convert;
      args.push_back(p.string());
    }
    const fs::path out = d / (std::string("joined.") + ext);
    args.insert(args.end(), {"-o", out.string()});
    const auto r = test::runRollspin(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::VideoProbe probe = test::probeVideo(out);
    ASSERT_EQ(static_cast<long long>(probe.ptsTicks.size()), kClipFrames) << ext;
    for (long long k = 0; k < kClipFrames; ++k) {
      const double expected = double(k) / 30.0;
      EXPECT_NEAR(probe.ptsSeconds[k], expected, 0.5 * probe.timeBaseNum / double(probe.timeBaseDen) + 1e-9)
          << ext << " frame " << k;
    }
    auto tags = formatTags(out);
    const std::string frames = tags.count("rollspin_frames") ? tags["rollspin_frames"] : tags["ROLLSPIN_FRAMES"];
    EXPECT_EQ(frames, "0-29") << ext;
  }
}

// One test for every refusal: each ctest process renders the fixture anew.
TEST_F(ShardJoin, JoinRefusesPartsThatDoNotBelongTogether) {
  SCOPED_TRACE("another scene");
  const fs::path other = test::freshTempDir("shard_join_scene") / "other.part-2-of-3.mp4";
  // The same size, timing and range, so only the scene differs.
  const auto r = test::runRollspin(tiny({"render", scene("wall.toml"), "--frames", "10:19", "-o", other.string()}));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  expectRefused({part(1), other, part(3)}, other, "different scene");

  SCOPED_TRACE("a missing part");
  expectRefused({part(1), part(3)}, part(3), "frames 10-19 are missing");
  expectRefused({part(2), part(3)}, part(2), "frames 0-9 of the 30-frame clip are missing");
  expectRefused({part(1), part(2)}, part(2), "frames 20-29 of the 30-frame clip are missing");

  SCOPED_TRACE("an overlap");
  const fs::path extra = test::freshTempDir("shard_join_overlap") / "clip.frames_5-14.mp4";
  const auto overlapping =
      test::runRollspin(tiny({"render", scene("lollipop.toml"), "--frames", "5:14", "-o", extra.string()}));
  ASSERT_EQ(overlapping.exitCode, 0) << overlapping.err;
  expectRefused({part(1), extra, part(2), part(3)}, extra, "overlaps");
  expectRefused({part(1), part(2), part(2), part(3)}, part(2), "is given twice");

  SCOPED_TRACE("another size");
  const fs::path big = test::freshTempDir("shard_join_size") / "clip.part-2-of-3.mp4";
  const auto bigger = test::runRollspin(
      tiny({"render", scene("lollipop.toml"), "--shard", "2/3", "-o", big.parent_path() / "clip.mp4"}, "192x108"));
  ASSERT_EQ(bigger.exitCode, 0) << bigger.err;
  expectRefused({part(1), big, part(3)}, big, "is 192x108, but");

  SCOPED_TRACE("not a rollspin part; another container");
  const fs::path plain = test::freshTempDir("shard_join_plain") / "plain.mp4";
  const std::string make = "ffmpeg -nostdin -v error -f lavfi -i testsrc=size=160x90:rate=30:duration=1 -c:v libx264 " +
                           shellQuote(plain.string());
  ASSERT_EQ(std::system(make.c_str()), 0);
  expectRefused({part(1), plain}, plain, "has no 'rollspin_scene_sha256' tag");
  // The parts are MP4: -o must be too (streams are copied).
  const fs::path outDir = test::freshTempDir("shard_join_container");
  const auto wrongContainer = test::runRollspin(
      {"join", part(1).string(), part(2).string(), part(3).string(), "-o", (outDir / "j.webm").string()});
  EXPECT_EQ(wrongContainer.exitCode, 2) << wrongContainer.err;
  EXPECT_NE(wrongContainer.err.find("'.mp4' files"), std::string::npos) << wrongContainer.err;
  EXPECT_TRUE(filesIn(outDir).empty());
}

TEST(Shard, BadShardArgumentsAreRefused) {
  const fs::path dir = test::freshTempDir("shard_bad");
  for (const char* bad : {"0/3", "4/3", "3", "a/b", "1/0"}) {
    const auto r =
        test::runRollspin(tiny({"render", scene("lollipop.toml"), "--shard", bad, "-o", (dir / "c.mp4").string()}));
    EXPECT_EQ(r.exitCode, 2) << bad;
    EXPECT_NE(r.err.find(std::string("--shard ") + bad), std::string::npos) << r.err;
  }
  // More shards than frames, and --shard with --frames.
  auto many = tiny({"render", scene("lollipop.toml"), "--shard", "1/31", "-o", (dir / "c.mp4").string()});
  auto r = test::runRollspin(many);
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("30 frames, fewer than the 31 parts"), std::string::npos) << r.err;
  r = test::runRollspin(
      tiny({"render", scene("lollipop.toml"), "--shard", "1/3", "--frames", "0:3", "-o", (dir / "c.mp4").string()}));
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("not both"), std::string::npos) << r.err;
  EXPECT_TRUE(filesIn(dir).empty());
}

TEST(Shard, PngShardsFillTheClipsFolderLikeAFullRender) {
  const fs::path dir = test::freshTempDir("shard_png");
  for (const char* k : {"2/3", "1/3", "3/3"}) {
    const auto r =
        test::runRollspin(tiny({"render", scene("lollipop.toml"), "--shard", k, "-o", (dir / "f").string()}));
    ASSERT_EQ(r.exitCode, 0) << r.err;
  }
  ASSERT_EQ(filesIn(dir / "f").size(), static_cast<std::size_t>(kClipFrames));
  ASSERT_EQ(test::runRollspin(tiny({"render", scene("lollipop.toml"), "-o", (dir / "full").string()})).exitCode, 0);
  for (long long k = 0; k < kClipFrames; ++k) {
    const std::string name = fmt::format("frame_{:05d}.png", k);
    EXPECT_TRUE(test::readFile(dir / "f" / name) == test::readFile(dir / "full" / name)) << name;
  }
}

}  // namespace
}  // namespace rollspin
