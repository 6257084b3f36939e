// path.start_azimuth_deg through the real CLI: a torus parallel's timeline
// starts at azimuth 90°, scene --print writes the key, and a value that is
// not a number or a key on a path without it exits 2 naming the key.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <numbers>
#include <sstream>

#include "support/cli_runner.hpp"

using rollspin::test::freshTempDir;
using rollspin::test::readFile;
using rollspin::test::runRollspin;
using rollspin::test::shippedScenePath;

TEST(StartAzimuthCli, ATorusParallelsTimelineStartsAtTheGivenAzimuth) {
  const auto dir = freshTempDir("start_azimuth_cli");
  const auto csv = dir / "torus.csv";
  const auto r = runRollspin({"timeline", shippedScenePath("torus"), "--set", "path.start_azimuth_deg=90", "--set",
                              "timeline.samples=5", "-o", csv.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::istringstream rows(readFile(csv));
  std::string header, first;
  std::getline(rows, header);
  std::getline(rows, first);
  ASSERT_EQ(header.rfind("s,px,py,pz,", 0), 0u) << header;
  double s = 0, px = 0, py = 0;
  char comma = 0;
  std::istringstream(first) >> s >> comma >> px >> comma >> py;
  EXPECT_EQ(s, 0.0);
  EXPECT_NEAR(std::atan2(py, px), std::numbers::pi / 2, 1e-12) << first;

  const auto printed =
      runRollspin({"scene", shippedScenePath("torus"), "--print", "--set", "path.start_azimuth_deg=90"});
  ASSERT_EQ(printed.exitCode, 0) << printed.err;
  EXPECT_NE(printed.out.find("start_azimuth_deg = 90"), std::string::npos) << printed.out;
}

TEST(StartAzimuthCli, BadValuesAndOtherPathsExitTwoNamingTheKey) {
  const auto notNumber = runRollspin({"solve", shippedScenePath("torus"), "--set", "path.start_azimuth_deg=east"});
  EXPECT_EQ(notNumber.exitCode, 2);
  EXPECT_NE(notNumber.err.find("path.start_azimuth_deg"), std::string::npos) << notNumber.err;
  // The loxodrome scene's path is not a parallel: the key does not apply.
  const auto other = runRollspin({"solve", shippedScenePath("sphere-loxodrome"), "--set", "path.start_azimuth_deg=90"});
  EXPECT_EQ(other.exitCode, 2);
  EXPECT_NE(other.err.find("path.start_azimuth_deg"), std::string::npos) << other.err;
  EXPECT_NE(other.err.find("parallel"), std::string::npos) << other.err;
}
