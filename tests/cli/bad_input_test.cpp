// Malformed scenes and overrides, through the real CLI: each must exit with
// code 2, name the key and where it came from (file:line:col or the --set
// argument), and leave nothing at the output path.
#include <gtest/gtest.h>

#include <fstream>

#include "support/cli_runner.hpp"

using rollspin::test::freshTempDir;
using rollspin::test::runRollspin;

namespace {

struct BadCase {
  const char* name;
  const char* toml;                    // scene file content
  std::vector<std::string> overrides;  // --set arguments
  const char* key;                     // must appear in the message
  const char* where;                   // ":LINE:" or the --set text
  const char* hint;                    // a word of what was expected
};

const BadCase kCases[] = {
    {"negative ball radius", "[ball]\nradius = -1\n", {}, "ball.radius", ":2:", "> 0"},
    {"zero ball radius", "[ball]\nradius = 0\n", {}, "ball.radius", ":2:", "> 0"},
    {"string ball radius", "[ball]\nradius = \"big\"\n", {}, "ball.radius", ":2:", "number"},
    {"nan ball radius", "[ball]\nradius = nan\n", {}, "ball.radius", ":2:", "finite"},
    {"unknown key", "[ball]\nradius = 1\ncolour = \"red\"\n", {}, "ball.colour", ":3:", "unknown key"},
    {"unknown table", "[bal]\nradius = 1\n", {}, "bal", ":1:", "unknown key"},
    {"unknown surface kind", "[surface]\nkind = \"cube\"\n", {}, "surface.kind", ":2:", "\"plane\""},
    {"zero normal", "[surface]\nnormal = [0, 0, 0]\n", {}, "surface.normal", ":2:", "non-zero"},
    {"short normal", "[surface]\nnormal = [1, 2]\n", {}, "surface.normal", ":2:", "3 finite numbers"},
    {"ball does not fit inside",
     "[ball]\nradius = 3\n[surface]\nkind = \"sphere\"\nradius = 2\nside = \"inside\"\n",
     {},
     "ball.radius",
     ":2:",
     "does not fit"},
    {"ball equal to the sphere inside",
     "[surface]\nkind = \"sphere\"\nradius = 1\nside = \"inside\"\n",
     {},
     "surface.radius",
     ":3:",
     "does not fit"},
    {"colatitude zero",
     "[surface]\nkind = \"sphere\"\n[path]\nkind = \"parallel\"\ncolatitude_deg = 0\n",
     {},
     "path.colatitude_deg",
     ":5:",
     "(0, 180)"},
    {"colatitude 180",
     "[surface]\nkind = \"sphere\"\n[path]\ncolatitude_deg = 180\n",
     {},
     "path.colatitude_deg",
     ":4:",
     "(0, 180)"},
    {"circle on a sphere",
     "[surface]\nkind = \"sphere\"\n[path]\nkind = \"circle\"\n",
     {},
     "path.kind",
     ":4:",
     "leave the surface"},
    {"parallel on a plane", "[path]\nkind = \"parallel\"\n", {}, "path.kind", ":2:", "leave the surface"},
    {"line leaves the plane",
     "[path]\nkind = \"line\"\ndirection_vector = [1, 0, 1]\n",
     {},
     "path.direction_vector",
     ":3:",
     "leaves the surface"},
    {"negative circle radius", "[path]\nradius = -2\n", {}, "path.radius", ":2:", "> 0"},
    {"zero turns", "[path]\nturns = 0\n", {}, "path.turns", ":2:", "> 0"},
    {"bad direction", "[path]\ndirection = \"left\"\n", {}, "path.direction", ":2:", "\"ccw\""},
    {"line with turns", "[path]\nkind = \"line\"\nturns = 2\n", {}, "path.turns", ":3:", "circle or parallel"},
    {"radius on a plane", "[surface]\nradius = 2\n", {}, "surface.radius", ":2:", "sphere"},
    {"unknown method", "[solver]\nmethod = \"euler\"\n", {}, "solver.method", ":2:", "\"magnus4\""},
    {"zero steps", "[solver]\nsteps = 0\n", {}, "solver.steps", ":2:", "[1, 1e11]"},
    {"fractional steps", "[solver]\nsteps = 1.5\n", {}, "solver.steps", ":2:", "integer"},
    {"one sample", "[timeline]\nsamples = 1\n", {}, "timeline.samples", ":2:", "[2, 1e8]"},
    {"plate without radius", "[plate]\n", {}, "plate.radius", ":1:", "missing"},
    {"plate and path radius", "[plate]\nradius = 2\n[path]\nradius = 1\n", {}, "path.radius", ":4:", "conflicts"},
    {"plate on a line", "[plate]\nradius = 2\n[path]\nkind = \"line\"\n", {}, "path.kind", ":4:", "circle"},
    {"TOML syntax", "[ball]\nradius = = 2\n", {}, "TOML syntax error", ":2:", "syntax"},
    {"section is not a table", "ball = 3\n", {}, "ball", ":1:", "table"},
    // --set overrides, validated the same way and named by their argument.
    {"override negative", "", {"ball.radius=-3"}, "ball.radius", "--set ball.radius=-3", "> 0"},
    {"override unknown key", "", {"ball.weight=3"}, "ball.weight", "--set ball.weight=3", "unknown key"},
    {"override without value", "", {"ball.radius"}, "--set", "--set ball.radius", "key.sub=value"},
    {"override wrong type", "", {"path.radius=abc"}, "path.radius", "--set path.radius=abc", "number"},
    {"override kind makes file key invalid",
     "[surface]\nnormal = [0, 1, 0]\n",
     {"surface.kind=sphere"},
     "surface.normal",
     ":2:",
     "plane"},
    {"override into a non-table", "ball = 3\n", {"ball.radius=2"}, "ball", "--set ball.radius=2", "not a table"},
};

}  // namespace

TEST(BadInput, EveryMalformedSceneExitsTwoNamingKeyAndPlaceAndWritesNothing) {
  ASSERT_GE(std::size(kCases), 15u);
  for (const BadCase& c : kCases) {
    const auto dir = freshTempDir("bad_input");
    const auto scene = dir / "scene.toml";
    std::ofstream(scene) << c.toml;
    const auto out = dir / "timeline.csv";
    std::vector<std::string> args{"timeline", scene.string(), "-o", out.string()};
    for (const auto& o : c.overrides) {
      args.push_back("--set");
      args.push_back(o);
    }
    const auto r = runRollspin(args);
    EXPECT_EQ(r.exitCode, 2) << c.name << "\n" << r.err;
    EXPECT_NE(r.err.find(c.key), std::string::npos) << c.name << ": key missing in\n" << r.err;
    EXPECT_NE(r.err.find(c.where), std::string::npos) << c.name << ": location missing in\n" << r.err;
    EXPECT_NE(r.err.find(c.hint), std::string::npos) << c.name << ": expectation missing in\n" << r.err;
    if (std::string(c.where).rfind("--set", 0) != 0) {
      EXPECT_NE(r.err.find(scene.string() + c.where), std::string::npos) << c.name << ": file:line missing\n" << r.err;
    }
    EXPECT_FALSE(std::filesystem::exists(out)) << c.name;
    // Nothing else either: no temporary left behind.
    std::size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) files += e.path() != scene;
    EXPECT_EQ(files, 0u) << c.name;
    std::filesystem::remove_all(dir);
  }
}

TEST(BadInput, MissingSceneFileIsBadInput) {
  const auto r = runRollspin({"solve", "/nonexistent/scene.toml"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("/nonexistent/scene.toml"), std::string::npos);
}

// Refused before the solve: a path that cannot work is the caller's mistake.
TEST(BadInput, OutputInAMissingFolderIsBadInputAndLeavesNothing) {
  const auto r = runRollspin(
      {"timeline", (rollspin::test::sourceDir() / "scenes/lollipop.toml").string(), "-o", "/nonexistent-dir/out.csv"});
  EXPECT_EQ(r.exitCode, 2);
  EXPECT_NE(r.err.find("does not exist"), std::string::npos) << r.err;
}

TEST(BadInput, FullDiskIsReported) {
  if (!std::filesystem::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const auto r =
      runRollspin({"timeline", (rollspin::test::sourceDir() / "scenes/lollipop.toml").string(), "-o", "/dev/full"});
  EXPECT_EQ(r.exitCode, 1);
  EXPECT_NE(r.err.find("write failed"), std::string::npos) << r.err;
}

TEST(BadInput, UnknownCommandLineOptionExitsTwo) {
  const auto r = runRollspin({"solve", "--no-such-flag"});
  EXPECT_EQ(r.exitCode, 2);
}

// Nothing is created before the input is known good: without -o each
// command writes into output/, which must not appear when the command
// refuses its input (exit 2) — a bad --at, a missing texture (a still, a
// figure, a clip), a bad --frames, a timeline or report of a bad scene, an
// MP4 larger than H.264 allows. Each runs in an empty folder of its own.
TEST(BadInput, ARefusedCommandCreatesNoOutputFolder) {
  const std::string lollipop = (rollspin::test::sourceDir() / "scenes/lollipop.toml").string();
  const std::vector<std::vector<std::string>> commands{
      {"render", lollipop, "--still", "--at", "fraction=2"},
      {"render", lollipop, "--still", "--set", "ball.texture=/nonexistent/ball.png"},
      {"render", lollipop, "--still", "--set", "ball.texture=/nonexistent/ball.png", "--set", "render.format=pdf"},
      {"render", lollipop, "--set", "ball.texture=/nonexistent/ball.png", "--width", "64", "--height", "48"},
      {"render", lollipop, "--frames", "5-2", "--width", "64", "--height", "48"},
      {"render", lollipop, "--width", "8192", "--height", "8192"},
      {"timeline", lollipop, "--set", "ball.radius=-1"},
      {"report", "errors", lollipop, "--set", "ball.radius=-1"},
  };
  for (const auto& args : commands) {
    std::string line;
    for (const auto& a : args) line += a + " ";
    const auto dir = freshTempDir("no_output_folder");
    const auto r = runRollspin(args, dir);
    EXPECT_EQ(r.exitCode, 2) << line << "\n" << r.err;
    EXPECT_TRUE(std::filesystem::is_empty(dir))
        << line << ": left " << std::filesystem::directory_iterator(dir)->path();
    std::filesystem::remove_all(dir);
  }
}

// H.264's largest frame is level 6.2's 139,264 macroblocks (8192x4320):
// 8192x8192 as MP4 is refused with the limit and the formats that hold it.
TEST(BadInput, AnMp4BeyondH264sLargestFrameNamesTheLimitAndTheFormatsThatHoldIt) {
  const auto dir = freshTempDir("h264_limit");
  const auto r =
      runRollspin({"render", "lollipop", "--width", "8192", "--height", "8192", "-o", (dir / "big.mp4").string()});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  for (const char* part : {"--height", "8192x8192", "262144 macroblocks", "level 6.2", "139264", "8192x4320",
                           "\"mov\" (ProRes)", "\"webm\"", "PNG frames"})
    EXPECT_NE(r.err.find(part), std::string::npos) << part << " missing from:\n" << r.err;
  EXPECT_TRUE(std::filesystem::is_empty(dir));
  const auto rate = runRollspin({"render", "lollipop", "--width", "8192", "--height", "4320", "--set",
                                 "animation.fps=240", "-o", (dir / "fast.mp4").string()});
  EXPECT_EQ(rate.exitCode, 2) << rate.err;
  EXPECT_NE(rate.err.find("animation.fps"), std::string::npos) << rate.err;
  EXPECT_NE(rate.err.find("16711680 macroblocks a second"), std::string::npos) << rate.err;
}
