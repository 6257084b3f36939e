// `rollspin render` to every output format, the way a user meets it: each
// file decoded with libavcodec and one frame checked against the PNG still
// of the same arc length (colours, and alpha with --transparent); JPEG
// stills; the GIF's own defaults (size, frame rate, loop); --frames; and the
// exit-2 cases of a format that does not fit. Label gl.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <thread>

#include "media/image_io.hpp"
#include "media/video_probe.hpp"
#include "support/cli_runner.hpp"

extern char** environ;

namespace rollspin {
namespace {

namespace fs = std::filesystem;

std::string lollipop() { return (test::sourceDir() / "scenes/lollipop.toml").string(); }

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

// 192×108, 1.1 s at 10 fps (linear) + holds of 0.2 s: 15 frames; frame 7 is
// s = L/2, the still at fraction=0.5. Without labels: at this size text
// fills half the view, and its codec noise (and the lines it gives up to
// make room) hid the pose the comparison is about.
std::vector<std::string> clip(std::vector<std::string> args) {
  for (const char* s : {"render.width=192", "render.height=108", "animation.fps=10", "animation.duration=1.1",
                        "animation.hold=0.2", "animation.easing=linear", "render.labels=false"}) {
    args.push_back("--set");
    args.push_back(s);
  }
  return args;
}

struct Difference {
  double colour = 0.0;  // mean |ΔRGB| of 2×2 block averages, blocks opaque in both
  double alpha = 0.0;   // mean |ΔA| over all pixels
};

// Colour on 2×2 block averages: 4:2:0 and 4:2:2 keep one chroma sample per
// block, so a pixel-wise comparison mostly measures that smear on thin lines
// and text; block averages measure whether the colours are right. Alpha per
// pixel; `binaryAlpha`: the still's alpha thresholded at 128 first (GIF).
Difference compare(const media::Image& decoded, const media::Image& still, bool binaryAlpha = false) {
  Difference d;
  long long blocks = 0;
  for (int y = 0; y < still.height; ++y)
    for (int x = 0; x < still.width; ++x) {
      const int want = binaryAlpha ? (still.pixel(x, y)[3] < 128 ? 0 : 255) : still.pixel(x, y)[3];
      d.alpha += std::abs(int(decoded.pixel(x, y)[3]) - want);
    }
  for (int y = 0; y + 1 < still.height; y += 2)
    for (int x = 0; x + 1 < still.width; x += 2) {
      int sum[2][3] = {};
      bool opaque = true;
      for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 2; ++i) {
          const std::uint8_t* a = decoded.pixel(x + i, y + j);
          const std::uint8_t* b = still.pixel(x + i, y + j);
          opaque = opaque && a[3] == 255 && b[3] == 255;
          for (int c = 0; c < 3; ++c) {
            sum[0][c] += a[c];
            sum[1][c] += b[c];
          }
        }
      if (!opaque) continue;
      for (int c = 0; c < 3; ++c) d.colour += std::abs(sum[0][c] - sum[1][c]) / 4.0;
      blocks += 3;
    }
  d.colour /= double(std::max<long long>(blocks, 1));
  d.alpha /= double(still.width) * still.height;
  return d;
}

struct FormatCase {
  std::string file;
  bool transparent;
  std::string codec, decodedPixelFormat;
  double colourTolerance, alphaTolerance;
};

TEST(FormatCli, EachFormatHasItsCodecFramesAndTheStillsColoursAndAlpha) {
  const fs::path dir = test::freshTempDir("format_cli");
  // Tolerances: lossy 4:2:0 codecs smear thin lines and text (see
  // video_cli_test: H.264 ≈ 2.5 here); ProRes is near-lossless; the GIF's
  // 256 colours and Bayer dither add a few levels on the gradients. Alpha:
  // antialiased edges; GIF's is 1-bit (compared with the still's alpha
  // thresholded at 128, its rule). Measured (192×108): WebM 3.2 / 3.4, MOV 2.3
  // / 0.06, GIF 0.9 / 1.1; frame 0 against the same still 7.7 … 13.
  const std::vector<FormatCase> cases{
      {"clip.webm", false, "vp9", "yuv420p", 4.5, 0.0},
      {"alpha.webm", true, "vp9", "yuva420p", 4.5, 1.5},
      // ProRes 422 HQ: libswscale's yuv422p10le → RGB lands ≈ 2 levels low even
      // on a flat colour (measured with the ffmpeg tool alone: 200,30,30 →
      // 198,28,28; 4444 round-trips exactly), hence its own tolerance.
      {"clip.mov", false, "prores", "yuv422p10le", 3.0, 0.0},
      {"alpha.mov", true, "prores", "yuva444p12le", 1.0, 0.5},
      {"clip.gif", false, "gif", "bgra", 3.0, 0.0},
      {"alpha.gif", true, "gif", "bgra", 3.0, 1.0},
  };
  for (const bool transparent : {false, true}) {
    auto args = clip({"render", lollipop(), "--still", "--at", "fraction=0.5", "-o",
                      (dir / (transparent ? "still_alpha.png" : "still.png")).string()});
    if (transparent) args.push_back("--transparent");
    ASSERT_EQ(test::runRollspin(args).exitCode, 0);
  }
  const media::Image still = media::loadImage(dir / "still.png", {});
  const media::Image stillAlpha = media::loadImage(dir / "still_alpha.png", {});
  for (const FormatCase& c : cases) {
    SCOPED_TRACE(c.file);
    auto args = clip({"render", lollipop(), "-o", (dir / c.file).string()});
    if (c.transparent) args.push_back("--transparent");
    const auto r = test::runRollspin(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const test::VideoProbe probe = test::probeVideo(dir / c.file, {0, 7});
    EXPECT_EQ(probe.codec, c.codec);
    EXPECT_EQ(probe.decodedPixelFormat, c.decodedPixelFormat);
    EXPECT_EQ(probe.width, 192);
    EXPECT_EQ(probe.height, 108);
    ASSERT_EQ(probe.ptsSeconds.size(), 15u);
    for (std::size_t k = 0; k < 15; ++k) EXPECT_NEAR(probe.ptsSeconds[k], double(k) / 10.0, 1e-6) << k;
    ASSERT_EQ(probe.kept.size(), 2u);
    const media::Image& expected = c.transparent ? stillAlpha : still;
    const bool binary = c.codec == "gif";
    const Difference same = compare(probe.kept[1], expected, binary), other = compare(probe.kept[0], expected, binary);
    std::fprintf(stderr, "%s: frame 7 vs still: mean |dRGB| %.2f, mean |dA| %.2f; frame 0: %.2f\n", c.file.c_str(),
                 same.colour, same.alpha, other.colour);
    EXPECT_LE(same.colour, c.colourTolerance);
    EXPECT_LE(same.alpha, c.alphaTolerance);
    EXPECT_GT(other.colour + other.alpha, 2.0 * (same.colour + same.alpha)) << "the comparison cannot tell poses apart";
    if (c.transparent) {
      // Alpha really there: the backdrop is transparent, the ball is not.
      long long clear = 0;
      for (std::size_t i = 3; i < probe.kept[1].rgba.size(); i += 4) clear += probe.kept[1].rgba[i] < 16;
      EXPECT_GT(clear, 192 * 108 / 4) << "most of the backdrop should be transparent";
    }
    if (HasFailure()) media::writePng(dir / (c.file + ".frame7.png"), probe.kept[1].view(), media::PngChannels::Rgba);
  }
}

TEST(FormatCli, JpegStillsAndFormatsThatDoNotFitAreExitTwo) {
  const fs::path dir = test::freshTempDir("format_cli_jpeg");
  const std::vector<std::string> size{"--width", "160", "--height", "90"};
  auto png = std::vector<std::string>{"render", lollipop(), "--still", "-o", (dir / "still.png").string()};
  auto jpg = std::vector<std::string>{"render", lollipop(), "--still", "-o", (dir / "still.jpg").string()};
  png.insert(png.end(), size.begin(), size.end());
  jpg.insert(jpg.end(), size.begin(), size.end());
  ASSERT_EQ(test::runRollspin(png).exitCode, 0);
  const auto r = test::runRollspin(jpg);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string bytes = test::readFile(dir / "still.jpg");
  ASSERT_GT(bytes.size(), 4u);
  EXPECT_EQ(bytes.substr(0, 3), std::string("\xFF\xD8\xFF")) << "a JPEG, not a PNG under a .jpg name";
  const media::Image a = media::loadImage(dir / "still.jpg", {}), b = media::loadImage(dir / "still.png", {});
  const Difference d = compare(a, b);
  EXPECT_LE(d.colour, 3.0) << "quality 92";
  auto low = std::vector<std::string>{
      "render", lollipop(), "--still", "--set", "render.jpeg_quality=30", "-o", (dir / "low.jpg").string()};
  low.insert(low.end(), size.begin(), size.end());
  ASSERT_EQ(test::runRollspin(low).exitCode, 0);
  EXPECT_LT(fs::file_size(dir / "low.jpg"), bytes.size());

  const std::vector<std::pair<std::vector<std::string>, std::string>> bad{
      {{"--still", "--transparent", "-o", (dir / "t.jpg").string()}, "JPEG has none"},
      {{"--still", "-o", (dir / "x.mp4").string()}, "jpg (.jpg, .jpeg)"},
      {{"-o", (dir / "x.jpg").string()}, "webm (.webm)"},
      {{"--set", "render.format=jpg", "-o", (dir / "x.webm").string()}, "still format"},
      {{"--set", "render.format=avi"}, "render.format"},
      {{"--transparent", "-o", (dir / "x.mp4").string()}, "alpha"},
      {{"--set", "render.jpeg_quality=0", "--still", "-o", (dir / "q.jpg").string()}, "render.jpeg_quality"},
  };
  const auto before = filesIn(dir);
  for (const auto& [args, expect] : bad) {
    std::vector<std::string> full{"render", lollipop(), "--set", "animation.duration=0.2"};
    full.insert(full.end(), size.begin(), size.end());
    full.insert(full.end(), args.begin(), args.end());
    const auto e = test::runRollspin(full, dir);
    EXPECT_EQ(e.exitCode, 2) << args.back() << "\n" << e.err;
    EXPECT_NE(e.err.find(expect), std::string::npos) << "expected '" << expect << "' in: " << e.err;
  }
  EXPECT_EQ(filesIn(dir), before) << "nothing written";
}

TEST(FormatCli, GifDefaultsToA480PixelWide25FpsLoopAndFramesWork) {
  const fs::path dir = test::freshTempDir("format_cli_gif");
  // No size, 30 fps: 480×270 at 25 fps (frames of exactly 4/100 s); 0.4 s → 10 frames.
  const auto r = test::runRollspin({"render", lollipop(), "--set", "animation.duration=0.4", "--set",
                                    "animation.hold=0", "-o", (dir / "clip.gif").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const test::VideoProbe probe = test::probeVideo(dir / "clip.gif");
  EXPECT_EQ(probe.width, 480);
  EXPECT_EQ(probe.height, 270);
  ASSERT_EQ(probe.ptsSeconds.size(), 10u);
  for (std::size_t k = 0; k < 10; ++k) EXPECT_NEAR(probe.ptsSeconds[k], double(k) * 0.04, 1e-9) << k;
  EXPECT_NE(test::readFile(dir / "clip.gif").find("NETSCAPE2.0"), std::string::npos) << "loops";

  // --frames: a part of a WebM and of a GIF, each with just its frames.
  for (const char* ext : {"webm", "gif"}) {
    const auto p = test::runRollspin(
        clip({"render", lollipop(), "--frames", "3:8", "-o", (dir / fmt::format("part.{}", ext)).string()}));
    ASSERT_EQ(p.exitCode, 0) << p.err;
    EXPECT_EQ(test::probeVideo(dir / fmt::format("part.{}", ext)).ptsSeconds.size(), 6u) << ext;
  }
}

// Starts rollspin without waiting for it (stderr to a file).
pid_t spawnRollspin(const std::vector<std::string>& args, const fs::path& errFile) {
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 2, errFile.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  std::vector<std::string> store{test::binaryPath().string()};
  store.insert(store.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (auto& a : store) argv.push_back(a.data());
  argv.push_back(nullptr);
  pid_t pid = 0;
  posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return pid;
}

// SIGINT once frames reach the file: a shorter, playable NAME.partial.EXT
// and nothing else. The GIF is interrupted after its palette pass.
TEST(FormatCli, SigintLeavesAPlayablePartialFileForEveryVideoFormat) {
  for (const char* ext : {"webm", "gif", "mov"}) {
    SCOPED_TRACE(ext);
    const fs::path dir = test::freshTempDir(fmt::format("format_sigint_{}", ext));
    const std::string name = fmt::format("clip.{}", ext);
    const pid_t pid = spawnRollspin({"render", lollipop(), "--set", "render.width=64", "--set", "render.height=48",
                                     "--set", "animation.duration=100", "-o", (dir / name).string()},
                                    dir / "stderr");
    ASSERT_GT(pid, 0);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    bool encoding = false;
    while (!encoding && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().starts_with("." + name + ".") && e.file_size() > 16384) encoding = true;
    }
    kill(pid, SIGINT);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    const std::string err = test::readFile(dir / "stderr");
    ASSERT_TRUE(encoding) << "no encoded data appeared: " << err;
    ASSERT_TRUE(WIFEXITED(status)) << err;
    EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT) << err;
    const std::string partial = fmt::format("clip.partial.{}", ext);
    EXPECT_NE(err.find(partial), std::string::npos) << err;
    EXPECT_EQ(filesIn(dir), (std::vector<std::string>{partial, "stderr"})) << "nothing else left";
    const test::VideoProbe probe = test::probeVideo(dir / partial);
    EXPECT_GT(probe.ptsSeconds.size(), 0u);
    EXPECT_LT(probe.ptsSeconds.size(), 3000u);
  }
}

}  // namespace
}  // namespace rollspin
