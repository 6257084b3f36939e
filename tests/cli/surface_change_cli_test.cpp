// A storyboard across surfaces through the real CLI (issue 53): surface keys
// that make no sense exit 2 at their file:line:col; the torus-to-floor
// timeline has a `surface` column, its q continuous with its sign kept and
// its position jumping at the cut; `scene --print` names each segment's
// surface and reads back; scenes of one surface keep their columns.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "support/cli_runner.hpp"

using rollspin::test::freshTempDir;
using rollspin::test::runRollspin;
using rollspin::test::sourceDir;

namespace {

const rollspin::test::BadScene kBad[] = {
    {"hold with a surface",
     "[[segment]]\npath = { kind = \"line\" }\n[[segment]]\nhold = 1\nsurface = { kind = \"sphere\" }\n",
     "segment[2].surface", ":5:11:", "a hold rests where the previous motion ended"},
    {"transition without a surface change",
     "[[segment]]\npath = { kind = \"line\" }\n[[segment]]\npath = { kind = \"line\" }\ntransition = \"fade\"\n",
     "segment[2].transition", ":5:14:", "applies where the surface changes"},
    {"unknown transition",
     "[[segment]]\npath = { kind = \"line\" }\n[[segment]]\npath = { kind = \"parallel\" }\nsurface = { kind = "
     "\"sphere\" }\ntransition = \"wipe\"\n",
     "segment[2].transition", ":6:14:", "\"cut\""},
    {"path off the segment's surface",
     "[[segment]]\npath = { kind = \"line\" }\n[[segment]]\npath = { kind = \"line\" }\nsurface = { kind = \"sphere\" "
     "}\n",
     "segment[2].path.kind", ":4:17:", "segment[2].surface.kind is \"sphere\""},
    {"a surface key of another kind",
     "[[segment]]\npath = { kind = \"line\" }\n[[segment]]\npath = { kind = \"parallel\" }\nsurface = { kind = "
     "\"sphere\", major_radius = 3 }\n",
     "segment[2].surface.major_radius", ":5:45:", "applies to kind = \"torus\" only"},
};

std::vector<std::string> fields(const std::string& line) {
  std::vector<std::string> out;
  std::stringstream in(line);
  for (std::string f; std::getline(in, f, ',');) out.push_back(f);
  return out;
}

std::string torusToFloor() { return (sourceDir() / "scenes/torus-to-floor.toml").string(); }

}  // namespace

TEST(SurfaceChangeCli, SurfaceKeysThatMakeNoSenseExitTwoAtTheirPlace) {
  for (const auto& c : kBad) rollspin::test::expectBadScene(c);
}

TEST(SurfaceChangeCli, TimelineHasASurfaceColumnAndQRunsOnAcrossTheCut) {
  const auto dir = freshTempDir("surface_change_timeline");
  const auto out = dir / "t.csv";
  const auto r = runRollspin({"timeline", torusToFloor(), "-o", out.string(), "--set", "timeline.samples=4001"});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::istringstream csv(rollspin::test::readFile(out));
  std::string line;
  std::getline(csv, line);  // the header row (the method is in t.csv.json)
  EXPECT_TRUE(line.ends_with("tau_g,segment,surface")) << line;
  const std::vector<std::string> names = fields(line);
  auto column = [&](const std::string& name) {
    return std::size_t(std::find(names.begin(), names.end(), name) - names.begin());
  };
  std::vector<std::vector<double>> rows;
  while (std::getline(csv, line)) {
    std::vector<double> row;
    for (const std::string& f : fields(line)) row.push_back(std::stod(f));
    rows.push_back(row);
  }
  ASSERT_EQ(rows.size(), 4001u);
  int cuts = 0;
  const double R = 0.8, tube = 1.5;
  for (std::size_t i = 1; i < rows.size(); ++i) {
    const auto &a = rows[i - 1], &b = rows[i];
    EXPECT_GE(b[column("surface")], a[column("surface")]);
    // q moves by at most |ω| ds / 2 between rows, |ω| ≤ 1/R + 1/a here; the sign is kept.
    double dq = 0.0, dot = 0.0, dp = 0.0;
    for (const char* q : {"qw", "qx", "qy", "qz"}) {
      dq += std::pow(b[column(q)] - a[column(q)], 2);
      dot += a[column(q)] * b[column(q)];
    }
    for (const char* p : {"px", "py", "pz"}) dp += std::pow(b[column(p)] - a[column(p)], 2);
    const double ds = b[column("s")] - a[column("s")];
    EXPECT_LE(std::sqrt(dq), 0.5 * (1.0 / R + 1.0 / tube) * ds * 1.01) << "row " << i;
    EXPECT_GT(dot, 0.0) << "row " << i;
    if (b[column("surface")] != a[column("surface")]) {
      ++cuts;
      EXPECT_EQ(a[column("surface")], 0.0);
      EXPECT_EQ(b[column("surface")], 1.0);
      EXPECT_EQ(b[column("segment")], 3.0);  // the hold (2) has no rows
      EXPECT_GT(std::sqrt(dp), 2.0) << "the position jumps from the torus to the floor";
      EXPECT_NEAR(b[column("pz")], 0.0, 1e-12);
    }
  }
  EXPECT_EQ(cuts, 1);
  // One surface: no surface column (the storyboard keeps its header).
  const auto one =
      runRollspin({"timeline", (sourceDir() / "scenes/storyboard.toml").string(), "-o", (dir / "one.csv").string()});
  ASSERT_EQ(one.exitCode, 0) << one.err;
  EXPECT_NE(rollspin::test::readFile(dir / "one.csv").find("tau_g,segment\n"), std::string::npos);
}

TEST(SurfaceChangeCli, PrintNamesEachSegmentsSurfaceAndReadsBack) {
  const auto dir = freshTempDir("surface_change_print");
  const auto first = runRollspin({"scene", torusToFloor(), "--print"});
  ASSERT_EQ(first.exitCode, 0) << first.err;
  for (const char* text :
       {"[segment.surface]\nkind = \"plane\"", "on surface 0 (a torus)", "on surface 1 (a plane)",
        "transition = \"fade\"", "fade_seconds = 0.5", "# surface = surface 1 (a plane), as segment[3].surface"})
    EXPECT_NE(first.out.find(text), std::string::npos) << text << "\n" << first.out;
  const auto printed = dir / "printed.toml";
  std::ofstream(printed) << first.out;
  const auto second = runRollspin({"scene", printed.string(), "--print"});
  ASSERT_EQ(second.exitCode, 0) << second.err;
  EXPECT_EQ(first.out.substr(first.out.find("\n\n")), second.out.substr(second.out.find("\n\n")));
  const auto solved = runRollspin({"solve", torusToFloor(), "--json"});
  ASSERT_EQ(solved.exitCode, 0) << solved.err;
}
