// Bad curved-surface scenes through the real CLI: an expression that does not
// parse (the column points into the string), a curve that leaves the
// surface's domain, a ball that does not fit (with the first failing s), a
// corner without a radius, keys of another kind. Each exits 2, names the key
// and file:line:col, and writes nothing. Also: every new scene in scenes/
// solves.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "support/cli_runner.hpp"

using rollspin::test::freshTempDir;
using rollspin::test::runRollspin;
using rollspin::test::sourceDir;

namespace {

const rollspin::test::BadScene kSurfaceCases[] = {
    {"height expression does not parse", "[surface]\nkind = \"height\"\nz = \"0.3*sin(x)**cos(y)\"\n", "surface.z",
     ":3:17:", "at character 12"},
    {"unknown variable in a height", "[surface]\nkind = \"height\"\nz = \"x + w\"\n", "surface.z",
     ":3:10:", "cannot parse"},
    {"uv expression does not parse", "[surface]\nkind = \"plane\"\n[path]\nkind = \"uv\"\nu = \"cos(t\"\n", "path.u",
     ":5:", "cannot parse"},
    {"uv curve leaves the sphere's domain",
     "[surface]\nkind = \"sphere\"\n[path]\nkind = \"uv\"\nu = \"t\"\nv = \"0\"\nt_start = 0.5\nt_end = 4\n", "path.u",
     ":5:", "leaves the surface's domain"},
    // A formula with no value where the path goes is the formula's fault:
    // surface.z at its line:col, with the point (x, y), whatever the path kind.
    {"height field undefined along a geodesic",
     "[surface]\nkind = \"height\"\nz = \"sqrt(4-x^2-y^2)\"\n[path]\nkind = \"geodesic\"\nlength = 5\n"
     "direction_vector = [1, 0, 0]\n",
     "surface.z", ":3:5:", "is undefined (not finite, or its slope is not) at (x, y) = ("},
    {"height field undefined everywhere", "[surface]\nkind = \"height\"\nz = \"sqrt(-1-x*x)\"\n", "surface.z",
     ":3:5:", "\"sqrt(-1-x*x)\" is undefined (not finite, or its slope is not) at (x, y) = ("},
    {"height field undefined on a uv path",
     "[surface]\nkind = \"height\"\nz = \"sqrt(-1-x*x)\"\n[path]\nkind = \"uv\"\nu = \"t\"\nv = \"0\"\n", "surface.z",
     ":3:5:", "at (x, y) = (0, 0), where the path goes (arc length ≈ 0)"},
    {"ball too big inside a cylinder",
     "[ball]\nradius = 2.5\n[surface]\nkind = \"cylinder\"\nradius = 2\nside = \"inside\"\n", "ball.radius",
     ":2:", "does not fit"},
    {"ball too big inside the torus tube",
     "[ball]\nradius = 1.2\n[surface]\nkind = \"torus\"\nmajor_radius = 4\nminor_radius = 1\nside = \"inside\"\n",
     "ball.radius", ":2:", "does not fit"},
    {"ball stops touching at one point on a saddle",
     "[ball]\nradius = 1.5\n[surface]\nkind = \"saddle\"\na = 1\nb = 2\n[path]\nkind = \"meridian\"\n"
     "azimuth_deg = 90\nlength = 6\n",
     "ball.radius", ":2:", "arc length s = "},
    {"corner without a radius",
     "[path]\nkind = \"points\"\npoints = [[0, 0], [2, 0], [2, 2]]\ninterpolation = \"polyline\"\n", "path.points",
     ":3:", "corner at point 2"},
    {"kink in a uv curve", "[path]\nkind = \"uv\"\nu = \"t\"\nv = \"abs(t - 0.5)\"\n", "path.u",
     ":3:", "corner at curve parameter 0.5"},
    {"torus key on a sphere", "[surface]\nkind = \"sphere\"\nmajor_radius = 3\n", "surface.major_radius",
     ":3:", "torus"},
    {"helix on a sphere", "[surface]\nkind = \"sphere\"\n[path]\nkind = \"helix\"\n", "path.kind", ":4:", "cylinder"},
    {"parallel on an elliptic paraboloid", "[surface]\nkind = \"paraboloid\"\na = 2\nb = 3\n", "surface.a",
     ":3:", "surface of revolution"},
    {"pitch angle of 90", "[surface]\nkind = \"cylinder\"\n[path]\nkind = \"helix\"\npitch_angle_deg = 90\n",
     "path.pitch_angle_deg", ":5:", "(-90, 90)"},
    {"points of mixed sizes", "[path]\nkind = \"points\"\npoints = [[0, 0], [1, 2, 3]]\n", "path.points",
     ":3:", "same number"},
};

TEST(SurfaceCli, BadCurvedScenesExitTwoAndWriteNothing) {
  for (const auto& c : kSurfaceCases) rollspin::test::expectBadScene(c);
}

TEST(SurfaceCli, CurvedScenesSolve) {
  for (const char* name :
       {"torus", "cylinder-helix", "plane-spline", "saddle-geodesic", "height-bumps", "sphere-loxodrome"}) {
    const auto r = runRollspin({"solve", (sourceDir() / "scenes" / (std::string(name) + ".toml")).string(), "--json"});
    EXPECT_EQ(r.exitCode, 0) << name << "\n" << r.err;
    EXPECT_NE(r.out.find("\"spinor_angle\""), std::string::npos) << name;
  }
}

// Control points may be given as points in space: they are mapped to the
// surface's parameters (here a sphere's (θ, φ)), and the path goes through them.
TEST(SurfaceCli, PointsInSpaceAreMappedOntoTheSurface) {
  const auto dir = freshTempDir("surface_points3d");
  const auto scene = dir / "scene.toml";
  std::ofstream(scene) << "[surface]\nkind = \"sphere\"\nradius = 2\n[path]\nkind = \"points\"\nclosed = true\n"
                          "points = [[2, 0, 0.5], [0, 2, 0.5], [-2, 0, 0.5], [0, -2, 1]]\n";
  const auto out = dir / "timeline.csv";
  const auto r = runRollspin({"timeline", scene.string(), "-o", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  std::ifstream in(out);
  std::string header, row;
  std::getline(in, header);  // the CSV starts with its header row
  std::getline(in, row);
  // First sample: on the sphere, in the direction of the first point.
  double s, px, py, pz;
  ASSERT_EQ(std::sscanf(row.c_str(), "%lf,%lf,%lf,%lf", &s, &px, &py, &pz), 4);
  const double norm = std::sqrt(px * px + py * py + pz * pz);
  EXPECT_NEAR(norm, 2.0, 1e-12);
  EXPECT_NEAR(px / norm, 2.0 / std::sqrt(4.25), 1e-12);
  EXPECT_NEAR(py, 0.0, 1e-12);
  std::filesystem::remove_all(dir);
}

}  // namespace
