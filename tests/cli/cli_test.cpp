// The CLI end to end on the real scenes: solve (text and JSON) and timeline.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "support/cli_runner.hpp"
#include "support/sweep.hpp"

using rollspin::test::freshTempDir;
using rollspin::test::runRollspin;
using rollspin::test::sourceDir;

namespace {
std::string scenePath(const char* name) { return (sourceDir() / "scenes" / name).string(); }

std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::vector<std::vector<std::string>> rows;
  std::string line;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream ss(line);
    std::string cell;
    while (std::getline(ss, cell, ',')) cells.push_back(cell);
    rows.push_back(cells);
  }
  return rows;
}

double jsonNumber(const std::string& json, const std::string& key) {
  const auto at = json.find("\"" + key + "\":");
  EXPECT_NE(at, std::string::npos) << key;
  return std::stod(json.substr(at + key.size() + 3));
}
}  // namespace

TEST(Cli, SolveJsonHasEveryKeyAndTheLollipopAngle) {
  const auto r = runRollspin({"solve", scenePath("lollipop.toml"), "--json"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  for (const char* key :
       {"length", "method", "steps", "quaternion", "angle", "axis", "spinor_angle", "unitarity_error", "solve_seconds"})
    EXPECT_NE(r.out.find(std::string("\"") + key + "\""), std::string::npos) << key;
  // δ = 2π√10 reduced to [0, π].
  const double delta = 2 * std::numbers::pi * std::sqrt(10.0);
  EXPECT_NEAR(jsonNumber(r.out, "angle"), std::abs(std::remainder(delta, 2 * std::numbers::pi)), 1e-11);
  EXPECT_NEAR(jsonNumber(r.out, "length"), 6 * std::numbers::pi, 1e-12);
  EXPECT_LT(jsonNumber(r.out, "unitarity_error"), 1e-13);
}

TEST(Cli, SetOverridesTheScene) {
  const auto r = runRollspin(
      {"solve", scenePath("lollipop.toml"), "--json", "--set", "path.radius=1", "--set", "solver.method=exact"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NEAR(jsonNumber(r.out, "length"), 2 * std::numbers::pi, 1e-12);
  EXPECT_NE(r.out.find("\"exact\""), std::string::npos);
}

TEST(Cli, TimelineHasTheNamedColumnsAndShowsTheSpinorSign) {
  const auto dir = freshTempDir("timeline");
  const auto out = dir / "t.csv";
  // r/R = √3: δ = 4π per circuit. Over two circuits the SO(3) rotation is the
  // identity after each, but q runs from +1 through −1 back to +1.
  const auto r =
      runRollspin({"timeline", scenePath("lollipop.toml"), "-o", out.string(), "--set",
                   "path.radius=1.7320508075688772", "--set", "path.turns=2", "--set", "timeline.samples=241"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto rows = readCsv(out);
  ASSERT_EQ(rows.size(), 242u);
  const std::vector<std::string> named{"s",  "px", "py", "pz", "nx", "ny", "nz", "cx", "cy",
                                       "cz", "qw", "qx", "qy", "qz", "Bx", "By", "Bz"};
  for (std::size_t i = 0; i < named.size(); ++i) EXPECT_EQ(rows[0][i], named[i]);
  auto qw = [&](std::size_t row) { return std::stod(rows[row][10]); };
  EXPECT_NEAR(qw(1), 1.0, 1e-15);
  EXPECT_NEAR(qw(121), -1.0, 1e-11);  // after one circuit: −1
  EXPECT_NEAR(qw(241), 1.0, 1e-11);   // after two: +1
  // Full precision: 17 significant digits.
  EXPECT_GE(rows[50][0].size(), 15u);
  // C = P + R n on every row.
  for (std::size_t i = 1; i < rows.size(); i += 40)
    EXPECT_NEAR(std::stod(rows[i][9]), std::stod(rows[i][3]) + std::stod(rows[i][6]), 1e-15);
}

TEST(Cli, EveryFoundationSceneSolves) {
  for (const char* name :
       {"lollipop.toml", "wall.toml", "tennis-ball.toml", "sphere-outside.toml", "sphere-inside.toml", "penny.toml"}) {
    const auto r = runRollspin({"solve", scenePath(name), "--json"});
    EXPECT_EQ(r.exitCode, 0) << name << "\n" << r.err;
  }
}

// ---- scene --print ---------------------------------------------------------

namespace {
std::string withoutHeader(const std::string& printed) {
  // The first three lines name the file and the path; the rest is the scene.
  std::size_t at = 0;
  for (int i = 0; i < 3 && at != std::string::npos; ++i) at = printed.find('\n', at) + 1;
  return printed.substr(at);
}
}  // namespace

TEST(ScenePrint, EverySceneRoundTripsThroughItsPrintedForm) {
  const auto dir = freshTempDir("print");
  int checked = 0;
  for (const std::filesystem::path& scene : rollspin::test::sweep(rollspin::test::bundledSceneFiles())) {
    const std::filesystem::directory_entry entry(scene);
    const auto first = runRollspin({"scene", entry.path().string(), "--print"});
    ASSERT_EQ(first.exitCode, 0) << entry.path() << "\n" << first.err;
    const auto printed = dir / entry.path().filename();
    std::ofstream(printed) << first.out;
    const auto second = runRollspin({"scene", printed.string(), "--print"});
    ASSERT_EQ(second.exitCode, 0) << printed << "\n" << second.err << "\n" << first.out;
    EXPECT_EQ(withoutHeader(first.out), withoutHeader(second.out)) << entry.path();
    // The engine does the same thing from either file.
    const auto a = runRollspin({"solve", entry.path().string(), "--json"});
    const auto b = runRollspin({"solve", printed.string(), "--json"});
    auto result = [](const std::string& json) {  // everything but the timing
      const auto from = json.find("\"length\""), to = json.find("\"solve_seconds\"");
      return json.substr(from, to - from);
    };
    EXPECT_EQ(result(a.out), result(b.out)) << entry.path();
    ++checked;
  }
  EXPECT_GE(checked, rollspin::test::sweepSampled() ? 3 : 10);
}

TEST(ScenePrint, ShowsDefaultsOverridesAndDerivedValues) {
  const auto r = runRollspin({"scene", scenePath("tennis-ball.toml"), "--print", "--set", "ball.radius=0.5"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.out.find("radius = 0.5"), std::string::npos);                // the override
  EXPECT_NE(r.out.find("direction = \"ccw\""), std::string::npos);         // a default
  EXPECT_NE(r.out.find("derived: R1/2 = 1"), std::string::npos) << r.out;  // Brockett's circle
  EXPECT_NE(r.out.find("# steps = automatic: "), std::string::npos);       // the automatic step count
  EXPECT_EQ(r.out.find("colatitude_deg"), std::string::npos);              // keys of other kinds are not shown
}

// render.backend and render.device (the GL context): printed when set, a
// comment saying who decides when not, and the printed form reads back.
TEST(ScenePrint, GlContextKeysRoundTrip) {
  const auto dir = freshTempDir("print_gl");
  const auto unset = runRollspin({"scene", scenePath("lollipop.toml"), "--print"});
  ASSERT_EQ(unset.exitCode, 0) << unset.err;
  EXPECT_NE(unset.out.find("# backend = ROLLSPIN_GL, else \"auto\""), std::string::npos) << unset.out;
  EXPECT_NE(unset.out.find("# device = ROLLSPIN_EGL_DEVICE, else the first GPU"), std::string::npos) << unset.out;
  for (const std::vector<std::string>& set : {std::vector<std::string>{"render.backend=\"egl\"", "render.device=1"},
                                              {"render.backend=\"auto\"", "render.device=\"/dev/dri/renderD128\""}}) {
    const auto first = runRollspin({"scene", scenePath("lollipop.toml"), "--print", "--set", set[0], "--set", set[1]});
    ASSERT_EQ(first.exitCode, 0) << first.err;
    const std::string device = set[1].substr(set[1].find('=') + 1);
    EXPECT_NE(first.out.find("backend = " + set[0].substr(set[0].find('=') + 1)), std::string::npos) << first.out;
    EXPECT_NE(first.out.find("device = " + device + "\n"), std::string::npos) << first.out;
    std::ofstream(dir / "p.toml") << first.out;
    const auto second = runRollspin({"scene", (dir / "p.toml").string(), "--print"});
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_EQ(withoutHeader(first.out), withoutHeader(second.out));
  }
  // A device for a backend that takes none stays rejected, at the key.
  const auto bad = runRollspin({"scene", scenePath("lollipop.toml"), "--print", "--set", "render.backend=\"osmesa\"",
                                "--set", "render.device=0"});
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("render.device"), std::string::npos) << bad.err;
}

// solver.error_estimate = false skips the second solve: JSON says so (null,
// skipped), the text and the timeline's header comment say "skipped"; the
// solve itself is unchanged, bit for bit.
TEST(Cli, ErrorEstimateCanBeSkippedByItsKey) {
  const auto with = runRollspin({"solve", scenePath("lollipop.toml"), "--json"});
  const auto without =
      runRollspin({"solve", scenePath("lollipop.toml"), "--json", "--set", "solver.error_estimate=false"});
  ASSERT_EQ(with.exitCode, 0) << with.err;
  ASSERT_EQ(without.exitCode, 0) << without.err;
  EXPECT_NE(with.out.find("\"error_estimate_skipped\": false"), std::string::npos) << with.out;
  EXPECT_GT(jsonNumber(with.out, "error_estimate"), 0.0);
  EXPECT_NE(without.out.find("\"error_estimate\": null"), std::string::npos) << without.out;
  EXPECT_NE(without.out.find("\"error_estimate_skipped\": true"), std::string::npos) << without.out;
  EXPECT_EQ(jsonNumber(without.out, "error_estimate_seconds"), 0.0);
  auto quaternion = [](const std::string& json) { return json.substr(json.find("\"quaternion\"")).substr(0, 120); };
  EXPECT_EQ(quaternion(with.out), quaternion(without.out));
  const auto text = runRollspin({"solve", scenePath("lollipop.toml"), "--set", "solver.error_estimate=false"});
  EXPECT_NE(text.out.find("error estimate   skipped (solver.error_estimate = false)"), std::string::npos) << text.out;
  const auto dir = freshTempDir("no-estimate");
  const auto out = dir / "t.csv";
  const auto tl =
      runRollspin({"timeline", scenePath("lollipop.toml"), "-o", out.string(), "--set", "solver.error_estimate=false"});
  ASSERT_EQ(tl.exitCode, 0) << tl.err;
  // The CSV starts with its header row; the estimate is in the sidecar, and
  // in the '#' line above the header row with --comment-header.
  std::ifstream in(out);
  std::string header;
  std::getline(in, header);
  EXPECT_TRUE(header.starts_with("s,px,py,pz,")) << header;
  const std::string sidecar = rollspin::test::readFile(out.string() + ".json");
  EXPECT_NE(sidecar.find("\"error_estimate\": null"), std::string::npos) << sidecar;
  EXPECT_NE(sidecar.find("\"error_estimate_basis\": \"skipped"), std::string::npos) << sidecar;
  const auto commented = runRollspin({"timeline", scenePath("lollipop.toml"), "-o", out.string(), "--set",
                                      "solver.error_estimate=false", "--comment-header"});
  ASSERT_EQ(commented.exitCode, 0) << commented.err;
  std::ifstream again(out);
  std::getline(again, header);
  EXPECT_NE(header.find("# rollspin timeline:"), std::string::npos) << header;
  EXPECT_NE(header.find("error estimate of U(L) skipped"), std::string::npos) << header;
  const auto bad = runRollspin({"solve", scenePath("lollipop.toml"), "--set", "solver.error_estimate=1"});
  EXPECT_EQ(bad.exitCode, 2);
  EXPECT_NE(bad.err.find("solver.error_estimate"), std::string::npos) << bad.err;
}
