// `rollspin render SCENE` as an animation, the way a user meets it: the MP4
// is decoded with the FFmpeg libraries and checked (codec, pixel format,
// BT.709 tags, frame count, timestamps, one frame against the still of the
// same arc length); --frames against a full PNG render; SIGINT; bad input.
// Small sizes and short clips keep the suite at a few seconds.
#include <gtest/gtest.h>

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fmt/format.h>

#include <chrono>
#include <fstream>
#include <thread>

#include "media/image_compare.hpp"
#include "media/image_io.hpp"
#include "media/video_probe.hpp"
#include "support/cli_runner.hpp"

extern char** environ;

namespace rollspin {
namespace {

namespace fs = std::filesystem;

std::string lollipop() { return (test::sourceDir() / "scenes/lollipop.toml").string(); }

std::vector<std::string> small(std::vector<std::string> args) {
  for (const char* s : {"render.width=96", "render.height=64", "animation.fps=10"}) {
    args.push_back("--set");
    args.push_back(s);
  }
  return args;
}

std::vector<std::string> filesIn(const fs::path& dir) {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path().filename().string());
  std::sort(out.begin(), out.end());
  return out;
}

TEST(VideoCli, Mp4HasH264Bt709TheRightFramesAndMatchesTheStill) {
  const fs::path dir = test::freshTempDir("video_mp4");
  // 1.1 s at 10 fps = 11 motion frames (s = L·j/10), holds of 0.2 s = 2 frames.
  // 192×108: big enough that 4:2:0 edges do not dominate the comparison;
  // without labels, which at this size fill half the view with codec noise.
  const std::vector<std::string> size{"--set", "render.width=192",   "--set", "render.height=108",
                                      "--set", "render.labels=false"};
  auto args = small({"render", lollipop(), "--set", "animation.duration=1.1", "--set", "animation.hold=0.2", "--set",
                     "animation.easing=linear", "-o", (dir / "clip.mp4").string()});
  args.insert(args.end(), size.begin(), size.end());
  const auto r = test::runRollspin(args);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("wrote"), std::string::npos) << "one summary line when not on a terminal: " << r.err;
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"clip.mp4"});

  // Frame 7 = motion frame 5 = s = L·0.5: the still at fraction=0.5.
  const test::VideoProbe probe = test::probeVideo(dir / "clip.mp4", {0, 7});
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_EQ(probe.pixelFormat, "yuv420p");
  EXPECT_EQ(probe.colorSpace, "bt709");
  EXPECT_EQ(probe.colorPrimaries, "bt709");
  EXPECT_EQ(probe.colorTransfer, "bt709");
  EXPECT_EQ(probe.colorRange, "tv");
  EXPECT_EQ(probe.width, 192);
  EXPECT_EQ(probe.height, 108);
  EXPECT_TRUE(probe.indexBeforeData) << "+faststart";
  ASSERT_EQ(probe.ptsSeconds.size(), 15u) << "duration × fps + 2 holds";
  for (std::size_t k = 0; k < probe.ptsSeconds.size(); ++k) {
    EXPECT_NEAR(probe.ptsSeconds[k], double(k) / 10.0, 1e-6) << k;
    if (k > 0) {
      EXPECT_GT(probe.ptsSeconds[k], probe.ptsSeconds[k - 1]);
    }
  }

  auto stillArgs = small({"render", lollipop(), "--still", "--at", "fraction=0.5", "-o", (dir / "still.png").string()});
  stillArgs.insert(stillArgs.end(), size.begin(), size.end());
  const auto still = test::runRollspin(stillArgs);
  ASSERT_EQ(still.exitCode, 0) << still.err;
  const media::Image expected = media::loadImage(dir / "still.png", {});
  ASSERT_EQ(probe.kept.size(), 2u);
  const media::ImageDifference same = media::compareImages(probe.kept[1].view(), expected.view());
  const media::ImageDifference other = media::compareImages(probe.kept[0].view(), expected.view());
  // Tolerance: H.264 at CRF 18 plus 4:2:0 chroma (one chroma sample per 2×2
  // pixels) smears thin coloured lines and text edges by up to ~100 levels,
  // but the image as a whole stays within a few levels (measured ≈ 2.5 here,
  // 1.4 at 640×360). The mean over RGBA must stay ≤ 4; frame 0 (s = 0, the
  // ball elsewhere) against the same still shows what a wrong pose costs.
  EXPECT_LE(same.meanOverall(), 4.0) << "max " << same.maxOverall();
  EXPECT_GT(other.meanOverall(), 2.0 * same.meanOverall()) << "the comparison cannot tell poses apart";
  std::fprintf(stderr, "decoded frame 7 vs still: mean %.3f max %d; frame 0 vs still: mean %.3f\n", same.meanOverall(),
               same.maxOverall(), other.meanOverall());
  if (HasFailure()) media::writePng(dir / "decoded_frame_7.png", probe.kept[1].view());
}

TEST(VideoCli, FramesRangeIsByteIdenticalToTheSameFramesOfAFullRender) {
  const fs::path dir = test::freshTempDir("video_range");
  const std::vector<std::string> clip{"--set", "animation.duration=2.4", "--set", "animation.hold=0"};
  auto full = small({"render", lollipop(), "-o", (dir / "full").string()});
  full.insert(full.end(), clip.begin(), clip.end());
  ASSERT_EQ(test::runRollspin(full).exitCode, 0);
  auto part = small({"render", lollipop(), "--frames", "10:19", "-o", (dir / "part").string()});
  part.insert(part.end(), clip.begin(), clip.end());
  const auto r = test::runRollspin(part);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_EQ(filesIn(dir / "full").size(), 24u);
  ASSERT_EQ(filesIn(dir / "part").size(), 10u);
  for (int k = 10; k <= 19; ++k) {
    const std::string name = "frame_000" + std::to_string(k) + ".png";
    const std::string a = test::readFile(dir / "full" / name), b = test::readFile(dir / "part" / name);
    EXPECT_FALSE(a.empty()) << name;
    EXPECT_TRUE(a == b) << name << " differs between the full and the partial render";
  }
}

TEST(VideoCli, ARerenderIntoAFrameFolderLeavesNoStaleFramesAndNoForeignFileIsTouched) {
  const fs::path dir = test::freshTempDir("video_rerender");
  auto render = [&](const char* duration, std::vector<std::string> more = {}) {
    auto args = small({"render", lollipop(), "--set", std::string("animation.duration=") + duration, "--set",
                       "animation.hold=0", "-o", (dir / "f").string()});
    args.insert(args.end(), more.begin(), more.end());
    const auto r = test::runRollspin(args);
    EXPECT_EQ(r.exitCode, 0) << r.err;
  };
  render("2.4");
  ASSERT_EQ(filesIn(dir / "f").size(), 24u);
  std::ofstream(dir / "f" / "notes.txt") << "mine";
  render("1.2");  // 12 frames: frames 12 … 23 of the first render must go
  std::vector<std::string> expected{"notes.txt"};
  for (int k = 0; k < 12; ++k) expected.push_back(fmt::format("frame_{:05d}.png", k));
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(filesIn(dir / "f"), expected);
  // A part (--frames) replaces its own frames and keeps the others.
  const std::string before = test::readFile(dir / "f" / "frame_00003.png");
  render("2.4", {"--frames", "20:21"});
  expected.push_back("frame_00020.png");
  expected.push_back("frame_00021.png");
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(filesIn(dir / "f"), expected);
  EXPECT_EQ(test::readFile(dir / "f" / "frame_00003.png"), before);
  EXPECT_EQ(filesIn(dir), std::vector<std::string>{"f"}) << "no staging folder left";
}

TEST(VideoCli, VerboseSaysWhichStageSetsThePace) {
  const fs::path dir = test::freshTempDir("video_verbose");
  const auto r = test::runRollspin(small({"render", lollipop(), "--verbose", "--set", "animation.duration=0.5", "--set",
                                          "animation.hold=0", "-o", (dir / "v.mp4").string()}));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("rollspin: pipeline: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("the encoder waited"), std::string::npos) << r.err;
  // A fixed camera: the video writer converts only the blocks that changed.
  const std::size_t at = r.err.find("rollspin: encoder: converted ");
  ASSERT_NE(at, std::string::npos) << r.err;
  const double percent = std::stod(r.err.substr(at + std::string("rollspin: encoder: converted ").size()));
  EXPECT_GT(percent, 0.0) << r.err;
  EXPECT_LT(percent, 90.0) << r.err;
  const auto quiet = test::runRollspin(small({"render", lollipop(), "--set", "animation.duration=0.5", "--set",
                                              "animation.hold=0", "-o", (dir / "q.mp4").string()}));
  EXPECT_EQ(quiet.err.find("pipeline"), std::string::npos) << "only with --verbose: " << quiet.err;
}

// Starts rollspin without waiting for it.
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

TEST(VideoCli, SigintLeavesAShorterPlayableVideoNamedSoAndNothingAtTheFinalName) {
  const fs::path dir = test::freshTempDir("video_sigint");
  const fs::path out = dir / "clip.mp4";
  // 3000 frames: far longer than the test waits.
  const pid_t pid = spawnRollspin({"render", lollipop(), "--set", "render.width=64", "--set", "render.height=48",
                                   "--set", "animation.duration=100", "-o", out.string()},
                                  dir / "stderr");
  ASSERT_GT(pid, 0);
  struct KillOnFailure {
    pid_t pid;
    bool reaped = false;
    ~KillOnFailure() {
      if (!reaped) {
        kill(pid, SIGKILL);
        waitpid(pid, nullptr, 0);
      }
    }
  } child{pid};
  // Wait until encoded packets reach the temporary file, then interrupt.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  bool encoding = false;
  while (!encoding && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().starts_with(".clip.mp4.") && e.file_size() > 4096) encoding = true;
  }
  ASSERT_TRUE(encoding) << "no encoded data appeared: " << test::readFile(dir / "stderr");
  ASSERT_EQ(kill(pid, SIGINT), 0);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  child.reaped = true;
  const std::string err = test::readFile(dir / "stderr");
  ASSERT_TRUE(WIFEXITED(status)) << "killed by the signal instead of stopping cleanly: " << err;
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGINT) << err;
  EXPECT_NE(err.find("interrupted"), std::string::npos) << err;
  EXPECT_NE(err.find("clip.partial.mp4"), std::string::npos) << "says so: " << err;
  EXPECT_FALSE(fs::exists(out)) << "never a file at the final name";
  EXPECT_EQ(filesIn(dir), (std::vector<std::string>{"clip.partial.mp4", "stderr"})) << "no temporary file left";
  const test::VideoProbe probe = test::probeVideo(dir / "clip.partial.mp4");
  EXPECT_EQ(probe.codec, "h264");
  EXPECT_GT(probe.ptsSeconds.size(), 0u);
  EXPECT_LT(probe.ptsSeconds.size(), 3000u + 30u);
}

TEST(VideoCli, SigtermDuringSetUpLeavesAPartialVideoOrNothing) {
  const fs::path dir = test::freshTempDir("video_sigterm");
  const fs::path out = dir / "clip.mp4";
  const pid_t pid = spawnRollspin({"render", lollipop(), "--set", "render.width=64", "--set", "render.height=48",
                                   "--set", "animation.duration=100", "-o", out.string()},
                                  dir / "stderr");
  ASSERT_GT(pid, 0);
  // The temporary file exists once the encoder is open: the GL context and
  // the shaders are usually still being set up.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  bool opened = false;
  while (!opened && std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
    for (const auto& e : fs::directory_iterator(dir))
      if (e.path().filename().string().starts_with(".clip.mp4.")) opened = true;
  }
  kill(pid, SIGTERM);
  int status = 0;
  ASSERT_EQ(waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(opened);
  const std::string err = test::readFile(dir / "stderr");
  ASSERT_TRUE(WIFEXITED(status)) << err;
  EXPECT_EQ(WEXITSTATUS(status), 128 + SIGTERM) << err;
  EXPECT_FALSE(fs::exists(out));
  const auto files = filesIn(dir);
  if (files == std::vector<std::string>{"stderr"}) {
    EXPECT_NE(err.find("nothing written"), std::string::npos) << err;
  } else {
    ASSERT_EQ(files, (std::vector<std::string>{"clip.partial.mp4", "stderr"}));
    EXPECT_GT(test::probeVideo(dir / "clip.partial.mp4").ptsSeconds.size(), 0u);
  }
}

// NTSC rates are exact rationals: 29.97 means 30000/1001, in the stream's
// frame rate, in every timestamp (frame k at exactly k·1001/30000 s) and in
// the frame count (2 s → round(2 · 30000/1001) = round(59.94) = 60 frames).
TEST(VideoCli, NtscFrameRatesAreExactRationals) {
  const fs::path dir = test::freshTempDir("video_ntsc");
  for (const char* fps : {"29.97", "30000/1001"}) {
    const fs::path out = dir / (std::string(fps[2] == '.' ? "decimal" : "rational") + ".mp4");
    const auto r = test::runRollspin({"render", lollipop(), "--set", "render.width=64", "--set", "render.height=48",
                                      "--set", std::string("animation.fps=") + fps, "--set", "animation.duration=2",
                                      "--set", "animation.hold=0.1", "-o", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_NE(r.err.find("30000/1001"), std::string::npos) << r.err;
    const test::VideoProbe probe = test::probeVideo(out);
    EXPECT_EQ(probe.frameRateNum, 30000) << fps;
    EXPECT_EQ(probe.frameRateDen, 1001) << fps;
    // 60 motion frames + 2 holds of round(0.1 · 29.97) = 3.
    ASSERT_EQ(probe.ptsTicks.size(), 66u) << fps;
    ASSERT_GT(probe.timeBaseDen, 0);
    for (std::size_t k = 0; k < probe.ptsTicks.size(); ++k) {
      // pts · tb = k · 1001/30000 exactly: pts · num_tb · 30000 = k · 1001 · den_tb.
      EXPECT_EQ(probe.ptsTicks[k] * probe.timeBaseNum * 30000, (long long)k * 1001 * probe.timeBaseDen)
          << fps << " frame " << k;
      if (k > 0) {
        EXPECT_GT(probe.ptsTicks[k], probe.ptsTicks[k - 1]);
      }
    }
  }
}

TEST(VideoCli, QualityPresetSetsSizeAndFrameRateAndDefaultOutputIsTheSceneName) {
  const fs::path dir = test::freshTempDir("video_default");
  const auto r = test::runRollspin({"render", lollipop(), "--quality", "low", "--quiet", "--set",
                                    "animation.duration=0.2", "--set", "animation.hold=0"},
                                   dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_TRUE(r.err.empty()) << "--quiet: " << r.err;
  const test::VideoProbe probe = test::probeVideo(dir / "output" / "lollipop.mp4");
  EXPECT_EQ(probe.width, 854);
  EXPECT_EQ(probe.height, 480);
  EXPECT_DOUBLE_EQ(probe.frameRate, 15.0);
  EXPECT_EQ(probe.ptsSeconds.size(), 3u);
}

struct BadCase {
  std::vector<std::string> args;
  int exitCode;
  std::string expect;  // substring of stderr
};

TEST(VideoCli, BadInputAndUnwritableOutputsFailClearlyAndLeaveNothing) {
  const fs::path dir = test::freshTempDir("video_bad");
  std::ofstream(dir / "file") << "x";
  const std::string out = (dir / "clip.mp4").string();
  const std::vector<BadCase> cases{
      {{"--set", "render.width=97", "-o", out}, 2, "render.width"},
      {{"--set", "render.transparent=true", "-o", out}, 2, "alpha"},
      {{"--set", "animation.duration=0.05", "-o", out}, 2, "animation.duration"},
      {{"--set", "animation.speed=2", "--set", "animation.duration=3", "-o", out}, 2, "animation.speed"},
      {{"--set", "animation.fps=0", "-o", out}, 2, "animation.fps"},
      {{"--set", "animation.fps=-30", "-o", out}, 2, "animation.fps"},
      {{"--set", "animation.fps=241", "-o", out}, 2, "animation.fps"},
      {{"--set", "animation.fps=12.3456", "-o", out}, 2, "at most 3 places"},
      {{"--set", "animation.fps=30000/0", "-o", out}, 2, "30000/1001"},
      {{"--set", "animation.fps=30/1001/2", "-o", out}, 2, "animation.fps"},
      {{"--set", "animation.easing=bouncy", "-o", out}, 2, "animation.easing"},
      {{"--set", "animation.preset=fastest", "-o", out}, 2, "animation.preset"},
      {{"--set", "animation.crf=60", "-o", out}, 2, "animation.crf"},
      {{"--set", "animation.frames=3", "-o", out}, 2, "unknown key"},
      {{"--set", "render.format=gif", "-o", out}, 2, "render.format"},
      {{"--set", "render.format=png", "-o", out}, 2, "render.format"},
      {{"--frames", "5:2", "-o", out}, 2, "--frames"},
      {{"--frames", "0:100000", "-o", out}, 2, "frames"},
      {{"--quality", "ultra", "-o", out}, 2, "--quality"},
      {{"--at", "s=1", "-o", out}, 2, "--still"},
      {{"-o", (dir / "clip.png").string()}, 2, "--still"},
      {{"-o", (dir / "clip.avi").string()}, 2, ".avi"},
      {{"-o", (dir / "file" / "clip.mp4").string()}, 2, "is a file, not a folder"},
      {{"-o", (dir / "file" / "frames").string()}, 2, "is a file, not a folder"},
      {{"-o", "/dev/full", "--set", "render.format=mp4"}, 1, "No space left on device"},
  };
  for (const auto& c : cases) {
    auto args = small({"render", lollipop(), "--set", "animation.duration=0.5", "--set", "animation.hold=0"});
    args.insert(args.end(), c.args.begin(), c.args.end());
    const auto r = test::runRollspin(args);
    std::string joined;
    for (const auto& a : c.args) joined += a + " ";
    EXPECT_EQ(r.exitCode, c.exitCode) << joined << "\n" << r.err;
    EXPECT_NE(r.err.find(c.expect), std::string::npos) << joined << "\nexpected '" << c.expect << "' in: " << r.err;
    EXPECT_EQ(filesIn(dir), std::vector<std::string>{"file"}) << joined;
  }
}

}  // namespace
}  // namespace rollspin
