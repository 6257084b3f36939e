// The bad-input matrix: every command fed broken input. Each case checks the
// exit code (2 bad input, 1 runtime failure), that the message names the
// problem, that nothing is left at the output path (nor a temporary beside
// it), and — in the sanitizer build — that nothing crashed.
#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <random>

#include "support/cli_runner.hpp"

using rollspin::test::freshTempDir;
using rollspin::test::runRollspin;
using rollspin::test::sourceDir;
namespace fs = std::filesystem;

namespace {

struct Case {
  const char* name;
  std::vector<std::string> args;  // {DIR} → a fresh directory, {SCENE} → scenes/lollipop.toml
  int exitCode;
  const char* message;           // must appear on stderr
  const char* output = nullptr;  // relative to {DIR}: must not exist afterwards
  std::function<void(const fs::path&)> prepare = {};
};

void write(const fs::path& p, const std::string& text) { std::ofstream(p, std::ios::binary) << text; }

void writeRandom(const fs::path& p, std::size_t n) {
  std::mt19937 rng(42);
  std::string bytes(n, '\0');
  for (auto& c : bytes) c = static_cast<char>(rng());
  write(p, bytes);
}

void writeScene(const fs::path& dir, const std::string& text) { write(dir / "s.toml", text); }

std::vector<Case> cases() {
  const std::string out = "{DIR}/out";
  std::vector<Case> c = {
      // ---- command line ------------------------------------------------
      {"no command", {}, 2, "subcommand"},
      {"unknown command", {"explode"}, 2, "explode"},
      {"unknown option", {"solve", "{SCENE}", "--frobnicate"}, 2, "frobnicate"},
      {"solve without scene", {"solve"}, 2, "scene"},
      // ---- scene files ------------------------------------------------
      {"missing scene", {"solve", "{DIR}/nope.toml"}, 2, "cannot read the scene file"},
      {"scene is a directory", {"solve", "{DIR}"}, 2, "cannot read the scene file"},
      {"binary garbage scene",
       {"timeline", "{DIR}/s.toml", "-o", out + ".csv"},
       2,
       "TOML syntax error",
       "out.csv",
       [](const fs::path& d) { writeRandom(d / "s.toml", 600); }},
      {"empty key", {"solve", "{DIR}/s.toml"}, 2, "syntax", nullptr, [](const fs::path& d) { writeScene(d, "= 3\n"); }},
      {"nan radius", {"timeline", "{SCENE}", "--set", "ball.radius=nan", "-o", out + ".csv"}, 2, "finite", "out.csv"},
      {"inf radius", {"timeline", "{SCENE}", "--set", "ball.radius=inf", "-o", out + ".csv"}, 2, "finite", "out.csv"},
      {"negative radius", {"solve", "{SCENE}", "--set", "ball.radius=-1"}, 2, "ball.radius"},
      {"zero radius", {"solve", "{SCENE}", "--set", "path.radius=0"}, 2, "path.radius"},
      {"huge turns",
       {"timeline", "{SCENE}", "--set", "path.turns=1e300", "-o", out + ".csv"},
       2,
       "above the limit",
       "out.csv"},
      {"huge steps", {"solve", "{SCENE}", "--set", "solver.steps=1000000000000"}, 2, "solver.steps"},
      {"negative steps", {"solve", "{SCENE}", "--set", "solver.steps=-5"}, 2, "solver.steps"},
      {"too many samples",
       {"timeline", "{SCENE}", "--set", "timeline.samples=1000000000", "-o", out + ".csv"},
       2,
       "timeline.samples",
       "out.csv"},
      {"wrong type", {"solve", "{SCENE}", "--set", "path.turns=[1,2]"}, 2, "path.turns"},
      {"unknown key", {"solve", "{SCENE}", "--set", "path.color=red"}, 2, "unknown key"},
      {"unknown section", {"solve", "{SCENE}", "--set", "physics.g=9.8"}, 2, "unknown key"},
      {"ball does not fit",
       {"solve", "{DIR}/s.toml"},
       2,
       "does not fit",
       nullptr,
       [](const fs::path& d) {
         writeScene(d, "[ball]\nradius = 5\n[surface]\nkind = \"sphere\"\nside = \"inside\"\n");
       }},
      {"impossible colatitude",
       {"solve", "{DIR}/s.toml", "--set", "path.colatitude_deg=-10"},
       2,
       "colatitude",
       nullptr,
       [](const fs::path& d) { writeScene(d, "[surface]\nkind = \"sphere\"\n"); }},
      {"path leaves the surface",
       {"solve", "{DIR}/s.toml", "--set", "path.direction_vector=[0,0,1]"},
       2,
       "leaves the surface",
       nullptr,
       [](const fs::path& d) { writeScene(d, "[path]\nkind = \"line\"\n"); }},
      {"extends cycle",
       {"timeline", "{DIR}/s.toml", "-o", out + ".csv"},
       2,
       "cycle",
       "out.csv",
       [](const fs::path& d) {
         writeScene(d, "extends = \"t.toml\"\n");
         write(d / "t.toml", "extends = \"s.toml\"\n");
       }},
      {"extends a missing file",
       {"solve", "{DIR}/s.toml"},
       2,
       "cannot read the scene file",
       nullptr,
       [](const fs::path& d) { writeScene(d, "extends = \"gone.toml\"\n"); }},
      // ---- outputs -------------------------------------------------------
      {"timeline into a missing directory", {"timeline", "{SCENE}", "-o", "{DIR}/missing/t.csv"}, 2, "does not exist"},
      {"timeline onto a directory", {"timeline", "{SCENE}", "-o", "{DIR}"}, 2, "is a directory"},
      {"timeline to a full disk", {"timeline", "{SCENE}", "-o", "/dev/full"}, 1, "write failed"},
      {"timeline into /proc", {"timeline", "{SCENE}", "-o", "/proc/rollspin.csv"}, 2, "cannot write"},
      // ---- render --------------------------------------------------------
      {"zero width", {"render", "{SCENE}", "--still", "--width", "0", "-o", out + ".png"}, 2, "--width", "out.png"},
      {"width above the limit",
       {"render", "{SCENE}", "--still", "--width", "9000", "-o", out + ".png"},
       2,
       "8192",
       "out.png"},
      {"negative height",
       {"render", "{SCENE}", "--still", "--height", "-5", "-o", out + ".png"},
       2,
       "--height",
       "out.png"},
      {"scene width zero",
       {"render", "{SCENE}", "--still", "--set", "render.width=0", "-o", out + ".png"},
       2,
       "render.width",
       "out.png"},
      {"unknown layout",
       {"render", "{SCENE}", "--still", "--set", "render.layout=grid", "-o", out + ".png"},
       2,
       "render.layout",
       "out.png"},
      {"missing texture",
       {"render", "{SCENE}", "--still", "--set", "ball.texture={DIR}/none.png", "-o", out + ".png"},
       2,
       "cannot read the image",
       "out.png"},
      {"corrupt texture",
       {"render", "{SCENE}", "--still", "--set", "ball.texture={DIR}/bad.png", "-o", out + ".png"},
       2,
       "not a readable PNG",
       "out.png",
       [](const fs::path& d) { writeRandom(d / "bad.png", 2000); }},
      {"truncated PNG texture",
       {"render", "{SCENE}", "--still", "--set", "ball.texture={DIR}/cut.png", "-o", out + ".png"},
       2,
       "cut.png",
       "out.png",
       [](const fs::path& d) { write(d / "cut.png", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16)); }},
      {"texture is a directory",
       {"render", "{SCENE}", "--still", "--set", "ball.texture={DIR}", "-o", out + ".png"},
       2,
       "cannot read the image",
       "out.png"},
      {"fraction outside [0,1]",
       {"render", "{SCENE}", "--still", "--at", "fraction=1.5", "-o", out + ".png"},
       2,
       "fraction",
       "out.png"},
      {"negative arc length",
       {"render", "{SCENE}", "--still", "--at", "s=-2", "-o", out + ".png"},
       2,
       "arc length",
       "out.png"},
      {"garbage --at", {"render", "{SCENE}", "--still", "--at", "middle", "-o", out + ".png"}, 2, "--at", "out.png"},
      {"bad msaa",
       {"render", "{SCENE}", "--still", "--set", "render.msaa=3", "-o", out + ".png"},
       2,
       "render.msaa",
       "out.png"},
      {"bad strobe",
       {"render", "{SCENE}", "--still", "--set", "render.strobe=-4", "-o", out + ".png"},
       2,
       "render.strobe",
       "out.png"},
      {"missing shader dir",
       {"render", "{SCENE}", "--still", "--shader-dir", "{DIR}/none", "-o", out + ".png"},
       2,
       "shader",
       "out.png"},
      {"still into a missing directory",
       {"render", "{SCENE}", "--still", "-o", "{DIR}/missing/x.png"},
       2,
       "does not exist"},
      {"still to a full disk",
       {"render", "{SCENE}", "--still", "--width", "64", "--height", "64", "-o", "/dev/full"},
       1,
       "write failed"},
      // ---- animations ----------------------------------------------------
      {"zero-length clip",
       {"render", "{SCENE}", "--set", "animation.duration=0", "-o", out + ".mp4"},
       2,
       "animation.duration",
       "out.mp4"},
      {"zero frames per second",
       {"render", "{SCENE}", "--set", "animation.fps=0", "-o", out + ".mp4"},
       2,
       "animation.fps",
       "out.mp4"},
      {"reversed frame range", {"render", "{SCENE}", "--frames", "5:2", "-o", out + ".mp4"}, 2, "--frames", "out.mp4"},
      {"frames past the end",
       {"render", "{SCENE}", "--frames", "100000:100001", "-o", out + ".mp4"},
       2,
       "frames",
       "out.mp4"},
      {"unknown quality", {"render", "{SCENE}", "--quality", "ultra", "-o", out + ".mp4"}, 2, "--quality", "out.mp4"},
      {"odd size for H.264",
       {"render", "{SCENE}", "--width", "101", "--height", "100", "-o", out + ".mp4"},
       2,
       "even",
       "out.mp4"},
      {"unknown container", {"render", "{SCENE}", "-o", out + ".avi"}, 2, ".avi", "out.avi"},
      {"format not in the table",
       {"solve", "{DIR}/s.toml"},
       2,
       "s.toml:2:10: render.format",
       nullptr,
       [](const fs::path& d) { writeScene(d, "[render]\nformat = \"avi\"\n"); }},
      {"still to a video extension",
       {"render", "{SCENE}", "--still", "-o", out + ".mp4"},
       2,
       "jpg (.jpg, .jpeg)",
       "out.mp4"},
      {"clip to a JPEG", {"render", "{SCENE}", "-o", out + ".jpg"}, 2, "still format", "out.jpg"},
      {"transparent JPEG",
       {"render", "{SCENE}", "--still", "--transparent", "-o", out + ".jpg"},
       2,
       "JPEG has none",
       "out.jpg"},
      {"JPEG quality out of range",
       {"render", "{SCENE}", "--still", "--set", "render.jpeg_quality=101", "-o", out + ".jpg"},
       2,
       "render.jpeg_quality",
       "out.jpg"},
      {"loop not a boolean",
       {"render", "{SCENE}", "--set", "animation.loop=2", "-o", out + ".gif"},
       2,
       "animation.loop",
       "out.gif"},
      {"unknown x264 preset",
       {"render", "{SCENE}", "--set", "animation.preset=warp", "-o", out + ".mp4"},
       2,
       "animation.preset",
       "out.mp4"},
      {"crf out of range",
       {"render", "{SCENE}", "--set", "animation.crf=99", "-o", out + ".mp4"},
       2,
       "animation.crf",
       "out.mp4"},
      {"absurd frame count",
       {"render", "{SCENE}", "--set", "animation.speed=1e-300", "-o", out + ".mp4"},
       2,
       "the limit is",
       "out.mp4"},
      {"video to a full disk",
       {"render", "{SCENE}", "--set", "render.format=mp4", "--set", "animation.duration=0.2", "--width", "128",
        "--height", "72", "-o", "/dev/full"},
       1,
       "No space left"},
      {"video into a missing directory", {"render", "{SCENE}", "-o", "{DIR}/missing/v.mp4"}, 2, "missing"},
      // ---- compare -------------------------------------------------------
      {"compare missing file", {"compare", "{DIR}/a.png", "{DIR}/b.png"}, 2, "cannot read the image"},
      {"compare corrupt file",
       {"compare", "{DIR}/bad.png", "{DIR}/bad.png"},
       2,
       "not a readable PNG",
       nullptr,
       [](const fs::path& d) { writeRandom(d / "bad.png", 300); }},
      {"compare negative tolerance",
       {"compare", "{DIR}/bad.png", "{DIR}/bad.png", "--max-delta", "-1"},
       2,
       "max-delta"},
      {"compare nan tolerance", {"compare", "{DIR}/bad.png", "{DIR}/bad.png", "--mean-delta", "nan"}, 2, "mean-delta"},
  };
  return c;
}

std::string substitute(std::string arg, const fs::path& dir) {
  for (const auto& [key, value] :
       {std::pair{std::string("{DIR}"), dir.string()},
        std::pair{std::string("{SCENE}"), (sourceDir() / "scenes" / "lollipop.toml").string()}}) {
    for (auto at = arg.find(key); at != std::string::npos; at = arg.find(key)) arg.replace(at, key.size(), value);
  }
  return arg;
}

}  // namespace

TEST(BadInputMatrix, EveryCaseFailsCleanly) {
  const auto all = cases();
  ASSERT_GE(all.size(), 40u);
  for (const Case& c : all) {
    const fs::path dir = freshTempDir("matrix");
    if (c.prepare) c.prepare(dir);
    std::vector<std::string> args;
    for (const auto& a : c.args) args.push_back(substitute(a, dir));
    const auto r = runRollspin(args);
    EXPECT_EQ(r.exitCode, c.exitCode) << c.name << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << c.name << ": '" << c.message << "' not in\n" << r.err;
    EXPECT_EQ(r.err.find("AddressSanitizer"), std::string::npos) << c.name;
    EXPECT_EQ(r.err.find("runtime error"), std::string::npos) << c.name;  // UBSan
    if (c.output != nullptr) {
      EXPECT_FALSE(fs::exists(dir / c.output)) << c.name;
      for (const auto& e : fs::directory_iterator(dir))
        EXPECT_EQ(e.path().extension(), e.path().extension() == ".tmp" ? ".none" : e.path().extension())
            << c.name << ": temporary left behind: " << e.path();
    }
    fs::remove_all(dir);
  }
}

TEST(BadInputMatrix, FrameBuffersLargerThanMemoryAreRefusedUpFront) {
#if defined(ROLLSPIN_ADDRESS_SANITIZER)
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of address space: RLIMIT_AS cannot be set";
#else
  // 8192² with 4× MSAA needs ~3.1 GiB; allow the process 2 GiB of address space.
  const fs::path dir = freshTempDir("memory");
  const auto r = runRollspin({"render", (sourceDir() / "scenes" / "lollipop.toml").string(), "--still", "--width",
                              "8192", "--height", "8192", "-o", (dir / "big.png").string()},
                             {}, 2ULL << 30);
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find("MiB"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("available"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "big.png"));
  fs::remove_all(dir);
#endif
}

// ---- only what a job needs: the GL library ---------------------------------

TEST(WithoutOsMesa, SolveAndTimelineRunAndDrawingFailsClearly) {
  // A broken libOSMesa.so.8 and libEGL.so.1 first on the library path, and
  // the loaders told to use nothing else: the binary must still start and
  // solve (it links no GL library; it loads one only to draw), and a render
  // (auto: every backend broken) must fail with exit code 1 and a message
  // naming the libraries.
  const fs::path dir = freshTempDir("no-osmesa");
  writeRandom(dir / "libOSMesa.so.8", 4096);
  writeRandom(dir / "libEGL.so.1", 4096);
  const std::vector<std::string> env{"LD_LIBRARY_PATH=" + dir.string(), "ROLLSPIN_GL=auto",
                                     "ROLLSPIN_OSMESA_LIBRARY=" + (dir / "libOSMesa.so.8").string(),
                                     "ROLLSPIN_EGL_LIBRARY=" + (dir / "libEGL.so.1").string()};
  const std::string scene = (sourceDir() / "scenes" / "lollipop.toml").string();
  const auto solve = runRollspin({"solve", scene, "--json"}, {}, 0, env);
  EXPECT_EQ(solve.exitCode, 0) << solve.err;
  EXPECT_NE(solve.out.find("\"angle\""), std::string::npos);
  const auto timeline = runRollspin({"timeline", scene, "-o", (dir / "t.csv").string()}, {}, 0, env);
  EXPECT_EQ(timeline.exitCode, 0) << timeline.err;
  EXPECT_TRUE(fs::exists(dir / "t.csv"));
  const auto report = runRollspin({"report", "paper"}, dir, 0, env);
  EXPECT_EQ(report.exitCode, 0) << report.err;
  EXPECT_TRUE(fs::exists(dir / "output" / "report" / "paper.md"));
  const auto still = runRollspin({"render", scene, "--still", "-o", (dir / "x.png").string()}, {}, 0, env);
  EXPECT_EQ(still.exitCode, 1) << still.err;
  EXPECT_NE(still.err.find("OSMesa"), std::string::npos) << still.err;
  EXPECT_NE(still.err.find("EGL library"), std::string::npos) << still.err;
  EXPECT_FALSE(fs::exists(dir / "x.png"));
  fs::remove_all(dir);
}

// ---- only what a job needs: FFmpeg's libraries ------------------------------

namespace {
// The files the dynamic loader opened for a command (glibc's LD_DEBUG=files).
std::string loadedLibraries(const std::vector<std::string>& args, const std::vector<std::string>& env = {}) {
  std::vector<std::string> withDebug = env;
  withDebug.emplace_back("LD_DEBUG=files");
  const auto r = runRollspin(args, {}, 0, withDebug);
  EXPECT_EQ(r.exitCode, 0) << r.err.substr(r.err.size() > 4000 ? r.err.size() - 4000 : 0);
  return r.err;
}

// `args` for a clip of two 64×48 frames.
std::vector<std::string> withTiny(std::vector<std::string> args) {
  for (const char* setting : {"render.width=64", "render.height=48", "animation.fps=5", "animation.duration=0.4"}) {
    args.emplace_back("--set");
    args.emplace_back(setting);
  }
  return args;
}
}  // namespace

TEST(WithoutFfmpeg, OnlyVideoLoadsTheCodecLibraries) {
  // libavcodec and libavfilter bring in about 140 libraries: loading them
  // took 0.1 s of every start. They are opened only to write or join video.
  const fs::path dir = freshTempDir("lazy-libav");
  const std::string scene = (sourceDir() / "scenes" / "lollipop.toml").string();
  const std::string solve = loadedLibraries({"solve", scene, "--json"});
  EXPECT_EQ(solve.find("libavcodec"), std::string::npos);
  EXPECT_EQ(solve.find("libavutil"), std::string::npos);
  const std::string still = loadedLibraries(withTiny({"render", scene, "--still", "-o", (dir / "s.png").string()}));
  EXPECT_EQ(still.find("libavcodec"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "s.png"));
  // The control: a video does load them (so the checks above can fail).
  const std::string video = loadedLibraries(withTiny({"render", scene, "-o", (dir / "v.mp4").string(), "--quiet"}));
  EXPECT_NE(video.find("libavcodec.so"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "v.mp4"));
  fs::remove_all(dir);
}

TEST(WithoutFfmpeg, StillsRunAndVideoFailsClearly) {
  // The loader pointed at a folder whose libavutil is garbage: solve and a
  // still work; a video and a join exit 1 naming the library and the
  // variable, and leave nothing behind.
  const fs::path dir = freshTempDir("no-libav");
  const fs::path libs = dir / "libs";
  fs::create_directories(libs);
  for (const char* name : {"libavutil.so.57", "libavcodec.so.59"}) writeRandom(libs / name, 4096);
  const std::vector<std::string> env{"ROLLSPIN_LIBAV_DIR=" + libs.string()};
  const std::string scene = (sourceDir() / "scenes" / "lollipop.toml").string();
  const auto solve = runRollspin({"solve", scene, "--json"}, {}, 0, env);
  EXPECT_EQ(solve.exitCode, 0) << solve.err;
  const auto still = runRollspin(withTiny({"render", scene, "--still", "-o", (dir / "s.png").string()}), {}, 0, env);
  EXPECT_EQ(still.exitCode, 0) << still.err;
  EXPECT_TRUE(fs::exists(dir / "s.png"));
  for (const char* name : {"v.mp4", "v.webm", "v.gif"}) {
    const auto video = runRollspin(withTiny({"render", scene, "-o", (dir / name).string()}), {}, 0, env);
    EXPECT_EQ(video.exitCode, 1) << name << ": " << video.err;
    EXPECT_NE(video.err.find("libavutil.so."), std::string::npos) << video.err;
    EXPECT_NE(video.err.find("ROLLSPIN_LIBAV_DIR"), std::string::npos) << video.err;
  }
  // `info` says why, and still exits 0 (it is about what this machine can do).
  const auto info = runRollspin({"info"}, {}, 0, env);
  EXPECT_EQ(info.exitCode, 0) << info.err;
  EXPECT_NE(info.out.find("video (MP4, WebM, MOV, GIF, join): not available: "), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("libavutil.so."), std::string::npos) << info.out;
  const auto infoWithFfmpeg = runRollspin({"info"});
  EXPECT_EQ(infoWithFfmpeg.exitCode, 0) << infoWithFfmpeg.err;
  EXPECT_NE(infoWithFfmpeg.out.find(", libavcodec "), std::string::npos) << infoWithFfmpeg.out;
  EXPECT_EQ(infoWithFfmpeg.out.find("not available"), std::string::npos) << infoWithFfmpeg.out;
  // Parts made with FFmpeg, joined without it.
  for (const char* shard : {"1/2", "2/2"}) {
    const auto part =
        runRollspin(withTiny({"render", scene, "--shard", shard, "-o", (dir / "p.mp4").string(), "--quiet"}));
    ASSERT_EQ(part.exitCode, 0) << part.err;
  }
  const auto join = runRollspin({"join", (dir / "p.part-1-of-2.mp4").string(), (dir / "p.part-2-of-2.mp4").string(),
                                 "-o", (dir / "j.mp4").string()},
                                {}, 0, env);
  EXPECT_EQ(join.exitCode, 1) << join.err;
  EXPECT_NE(join.err.find("libavutil.so."), std::string::npos) << join.err;
  // Nothing but the fake libraries, the still and the parts is left.
  std::vector<std::string> left;
  for (const auto& e : fs::recursive_directory_iterator(dir)) left.push_back(fs::relative(e.path(), dir).string());
  std::sort(left.begin(), left.end());
  EXPECT_EQ(left, (std::vector<std::string>{"libs", "libs/libavcodec.so.59", "libs/libavutil.so.57",
                                            "p.part-1-of-2.mp4", "p.part-2-of-2.mp4", "s.png"}));
  fs::remove_all(dir);
}
