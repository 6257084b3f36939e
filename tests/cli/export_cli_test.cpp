// `rollspin export` as a user meets it: the default name, .glb and
// .gltf + .bin, --set and --no-metadata; bad input (an unknown extension, a
// folder that cannot be written, a surface that cannot be meshed) is exit 2
// with the reason and nothing written; Ctrl-C leaves nothing.
#include <gtest/gtest.h>
#include <signal.h>

#include <algorithm>
#include <fstream>

#include "support/cli_runner.hpp"

namespace fs = std::filesystem;
namespace test = rollspin::test;

namespace {

std::vector<std::string> entries(const fs::path& dir) {
  std::vector<std::string> names;
  for (const auto& e : fs::recursive_directory_iterator(dir)) names.push_back(fs::relative(e.path(), dir).string());
  std::sort(names.begin(), names.end());
  return names;
}

using rollspin::test::has;

TEST(ExportCli, WritesTheDefaultGlbAndAGltfWithItsBin) {
  const fs::path dir = test::freshTempDir("export_cli_default");
  const auto glb = test::runRollspin({"export", test::shippedScenePath("penny")}, dir);
  ASSERT_EQ(glb.exitCode, 0) << glb.err;
  EXPECT_TRUE(test::readFile(dir / "output/penny.glb").starts_with("glTF")) << "a GLB header";
  const auto gltf = test::runRollspin(
      {"export", test::shippedScenePath("penny"), "--set", "ball.radius=0.625", "-o", (dir / "p.gltf").string()});
  ASSERT_EQ(gltf.exitCode, 0) << gltf.err;
  const std::string json = test::readFile(dir / "p.gltf");
  EXPECT_TRUE(has(json, "\"uri\": \"p.bin\"")) << json.substr(0, 400);
  EXPECT_TRUE(has(json, "radius = 0.625")) << "the resolved scene, --set included, in the ball's extras";
  EXPECT_GT(fs::file_size(dir / "p.bin"), 1000u);
  const auto bare =
      test::runRollspin({"export", test::shippedScenePath("penny"), "--no-metadata", "-o", (dir / "q.gltf").string()});
  ASSERT_EQ(bare.exitCode, 0) << bare.err;
  EXPECT_FALSE(has(test::readFile(dir / "q.gltf"), "radius =")) << "--no-metadata leaves the scene out";
  EXPECT_EQ(entries(dir),
            (std::vector<std::string>{"output", "output/penny.glb", "p.bin", "p.gltf", "q.bin", "q.gltf"}));
}

TEST(ExportCli, BadInputIsExitTwoWithTheReasonAndNothingWritten) {
  const fs::path dir = test::freshTempDir("export_cli_bad");
  std::ofstream(dir / "dome.toml")
      << "[ball]\nradius = 0.5\n[surface]\nkind = \"height\"\nz = \"sqrt(9 - x^2 - y^2)\"\n"
         "[path]\nkind = \"uv\"\nu = \"2*cos(t)\"\nv = \"2*sin(t)\"\nt_start = 0\n"
         "t_end = 6.283185307179586\n";
  const std::string lollipop = test::shippedScenePath("lollipop");
  const struct {
    std::vector<std::string> args;
    std::string reason;
  } cases[] = {
      {{"export", lollipop, "-o", (dir / "x.obj").string()}, "expected a .glb or .gltf file name (got '.obj')"},
      {{"export", lollipop, "-o", (dir / "x").string()}, "(got no extension)"},
      {{"export", lollipop, "-o", (dir / "missing/x.glb").string()}, "missing"},
      {{"export", lollipop, "-o", "/proc/x.glb"}, "cannot write in the folder '/proc'"},
      {{"export", lollipop, "-o", "/proc/x.gltf"}, "cannot write in the folder '/proc'"},
      {{"export", (dir / "dome.toml").string(), "-o", (dir / "d.glb").string()},
       "dome.toml:4:8: surface.kind: the height surface cannot be meshed where the path runs"},
      {{"export", lollipop, "--set", "ball.radius=-1", "-o", (dir / "r.glb").string()}, "ball.radius"},
  };
  for (const auto& c : cases) {
    const auto r = test::runRollspin(c.args);
    EXPECT_EQ(r.exitCode, 2) << c.args.back() << ": " << r.err;
    EXPECT_TRUE(has(r.err, c.reason)) << r.err;
  }
  EXPECT_EQ(entries(dir), std::vector<std::string>{"dome.toml"}) << "nothing written, no temporary left";
}

TEST(ExportCli, InterruptLeavesNothing) {
  const fs::path dir = test::freshTempDir("export_cli_interrupt");
  // A clip of 5.5 hours: 600 000 frames, seconds of work, long enough to stop.
  for (const char* name : {"long.glb", "long.gltf"}) {
    test::SpawnedRollspin child({"export", test::shippedScenePath("lollipop"), "--set", "animation.duration=20000",
                                 "-v", "-o", (dir / name).string()},
                                dir.parent_path() / "export_cli_interrupt.stderr");
    const fs::path err = dir.parent_path() / "export_cli_interrupt.stderr";
    EXPECT_TRUE(child.waitUntil([&] { return has(test::readFile(err), "stage: gltf-keys"); })) << test::readFile(err);
    test::sleepMilliseconds(100);
    EXPECT_EQ(kill(child.pid(), SIGINT), 0);
    bool signalled = false;
    EXPECT_EQ(child.wait(&signalled), 128 + SIGINT) << test::readFile(err);
    EXPECT_FALSE(signalled) << "killed instead of cleaning up";
    EXPECT_EQ(entries(dir), std::vector<std::string>{}) << name;
  }
}

}  // namespace
