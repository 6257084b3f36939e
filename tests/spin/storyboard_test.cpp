// A storyboard's path (geometry::JoinedPath) solved as one: the propagator
// runs piece by piece and composes U = U_k ⋯ U_1, carrying the orientation
// and the spinor's sign across the joins. Judged by (1) the product of the
// pieces solved one by one, each from U = 1, and (2) the independent
// kinematic oracle run over the concatenated path (it sees only point(s)
// and normal(s); the joins are breakpoints, so its stencils stay inside one
// piece), with the sign from the oracle's continuous lift.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geometry/clothoid_path.hpp"
#include "geometry/joined_path.hpp"
#include "geometry/surface_paths.hpp"
#include "oracle_support.hpp"
#include "spin/field.hpp"
#include "support/numbers.hpp"
#include "support/sweep.hpp"
#include "support/test_paths.hpp"

using namespace rollspin;
using namespace rollspin::test;
using Eigen::Vector3d;
using rollspin::test::kPi;
using spin::Method;
using spin::Su2;

namespace {

// Line → circle (r = 1.5, entered tangentially) → clothoid → line, on the
// floor, each piece starting at the previous end along its end heading.
// (Kept near the origin: the oracle's finite differences lose ε|C|/h.)
// Built twice (the joined path owns its pieces; the test solves copies).
std::vector<std::unique_ptr<geometry::ContactPath>> floorPieces() {
  auto plane = std::make_shared<const geometry::Plane>(Vector3d::UnitZ());
  std::vector<std::unique_ptr<geometry::ContactPath>> pieces;
  pieces.push_back(std::make_unique<geometry::PlaneLinePath>(plane, Vector3d::Zero(), Vector3d::UnitX(), 2.0));
  auto end = [&] { return pieces.back()->at(pieces.back()->length()); };
  geometry::DarbouxSample f = end();
  // ccw circle starting at P along h: centre P − r e1 with e1 = h × n.
  const Vector3d e1 = f.tangent.cross(f.normal);
  pieces.push_back(std::make_unique<geometry::PlaneCirclePath>(plane, f.point - 1.5 * e1, e1, 1.5, 1.25, true));
  f = end();
  pieces.push_back(std::make_unique<geometry::PlaneClothoidPath>(plane, f.point, f.tangent, -0.5, 0.4, 3.0));
  f = end();
  pieces.push_back(std::make_unique<geometry::PlaneLinePath>(plane, f.point, f.tangent, 1.5));
  return pieces;
}

// On a sphere with a corner: down a meridian from 30° to 60° colatitude,
// then (turning by 90° on the spot) once round the 60° parallel, then back
// up another meridian from the parallel's end (azimuth 0 again).
std::vector<std::unique_ptr<geometry::ContactPath>> spherePieces() {
  auto sphere = std::make_shared<const geometry::Sphere>(4.0, geometry::Side::Outside);
  std::vector<std::unique_ptr<geometry::ContactPath>> pieces;
  pieces.push_back(geometry::sphereMeridian(sphere, 0.0, kPi / 6, kPi / 3));
  pieces.push_back(geometry::sphereParallel(sphere, kPi / 3, 1.0, true));
  pieces.push_back(geometry::sphereMeridian(sphere, 0.0, kPi / 3, kPi / 4));
  return pieces;
}

long long stepsFor(const geometry::ContactPath& path, double R) {
  return std::max<long long>(4000, std::llround(800.0 * spin::integratedStepBudget(path, R)));
}

Su2 productOfPieces(const std::vector<std::unique_ptr<geometry::ContactPath>>& pieces, double R, Method m) {
  Su2 u = Su2::identity();
  for (const auto& p : pieces) {
    const spin::SolveStats st = spin::Propagator(*p, R, m, stepsFor(*p, R), 1e-12).solveFinal();
    EXPECT_EQ(st.status, spin::SolveStatus::Ok);
    u = st.final * u;
  }
  return u;
}

}  // namespace

TEST(Storyboard, JoinedPathRunsOnThroughItsPieces) {
  const geometry::JoinedPath joined(floorPieces());
  const auto pieces = floorPieces();
  ASSERT_EQ(joined.pieces().size(), 4u);
  double start = 0.0;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    EXPECT_EQ(joined.pieces()[k].start, start);
    // A join belongs to the piece that starts there.
    EXPECT_EQ(joined.pieceAt(start), k);
    EXPECT_LT((joined.point(start) - pieces[k]->point(0.0)).norm(), 1e-12);
    const double mid = start + 0.5 * pieces[k]->length();
    EXPECT_LT((joined.at(mid).tangent - pieces[k]->at(0.5 * pieces[k]->length()).tangent).norm(), 1e-15);
    EXPECT_EQ(joined.at(mid).s, mid);
    start += pieces[k]->length();
  }
  EXPECT_EQ(joined.length(), start);
  EXPECT_EQ(joined.pieceAt(joined.length()), 3u);
  // Tangent-continuous joins on the floor: the end of one is the start of the next.
  for (std::size_t k = 1; k < pieces.size(); ++k) {
    const geometry::DarbouxSample a = pieces[k - 1]->at(pieces[k - 1]->length()), b = pieces[k]->at(0.0);
    EXPECT_LT((a.point - b.point).norm(), 1e-12) << k;
    EXPECT_LT((a.tangent - b.tangent).norm(), 1e-12) << k;
  }
  EXPECT_FALSE(joined.hasConstantCurvatures());  // curvatures jump at the joins
  EXPECT_GE(joined.breakpoints().size(), 3u);
}

// U_total = U_k ⋯ U_1, for every kind of method (exact where every piece has
// constant curvatures).
TEST(Storyboard, SolvingTheWholeEqualsTheProductOfThePieces) {
  const double R = 0.8;
  const geometry::JoinedPath floor(floorPieces());
  for (Method m : {Method::Magnus4, Method::Magnus6, Method::Frame4, Method::Frame6a}) {
    const Su2 whole = spin::Propagator(floor, R, m, stepsFor(floor, R), 1e-12).solveFinal().final;
    EXPECT_LT(spin::spinorDistance(whole, productOfPieces(floorPieces(), R, m)), 1e-11) << spin::methodName(m);
  }
  // Exact needs constant curvatures piece by piece: line, circle, line.
  auto plane = std::make_shared<const geometry::Plane>(Vector3d::UnitZ());
  auto constantPieces = [&] {
    std::vector<std::unique_ptr<geometry::ContactPath>> p;
    p.push_back(std::make_unique<geometry::PlaneLinePath>(plane, Vector3d::Zero(), Vector3d::UnitX(), 4.0));
    p.push_back(
        std::make_unique<geometry::PlaneCirclePath>(plane, Vector3d(4, 3, 0), -Vector3d::UnitY(), 3.0, 1.0, true));
    p.push_back(std::make_unique<geometry::PlaneLinePath>(plane, Vector3d(4, 0, 0), Vector3d::UnitX(), 2.0));
    return p;
  };
  const geometry::JoinedPath lollipopAndLines(constantPieces());
  const spin::SolveStats exact = spin::Propagator(lollipopAndLines, R, Method::Exact, 0).solveFinal();
  ASSERT_EQ(exact.status, spin::SolveStatus::Ok);
  EXPECT_LT(spin::spinorDistance(exact.final, productOfPieces(constantPieces(), R, Method::Exact)), 1e-14);
  const spin::SolveStats magnus = spin::Propagator(lollipopAndLines, R, Method::Magnus4, 20000).solveFinal();
  EXPECT_LT(spin::spinorDistance(exact.final, magnus.final), 1e-12);
}

// The orientation and the spinor's sign carried across the joins, against
// the kinematics of the concatenated path at the end and at samples on
// either side of every join.
TEST(Storyboard, CarriesOrientationAndSignAcrossJoinsLikeTheKinematics) {
  struct Case {
    const char* name;
    std::vector<std::unique_ptr<geometry::ContactPath>> (*pieces)();
    double R;
  };
  // A sweep: the sanitizer pass checks one of the two.
  for (const Case& c :
       test::sweep(std::vector<Case>{{"floor: line, circle, clothoid, line", floorPieces, 0.8},
                                     {"sphere: meridian, corner, parallel, meridian", spherePieces, 1.0}})) {
    const geometry::JoinedPath path(c.pieces());
    std::vector<double> s = spin::uniformSamples(path.length(), 33);
    for (const auto& piece : path.pieces()) {
      if (piece.start <= 0.0) continue;
      for (double d : {-1e-3, 0.0, 1e-3}) s.push_back(piece.start + d);
    }
    std::sort(s.begin(), s.end());
    std::vector<Su2> u(s.size());
    const spin::SolveStats st = spin::Propagator(path, c.R, Method::Magnus6, stepsFor(path, c.R))
                                    .run(s, [&](std::size_t i, double, const Su2& q) { u[i] = q; });
    ASSERT_EQ(st.status, spin::SolveStatus::Ok) << c.name;
    const auto q = kinematics::RollingKinematics(path, c.R, {200000, 0.0}).orientations(s);
    double worst = 0.0;
    for (std::size_t i = 0; i < s.size(); ++i)
      worst = std::max(worst, rotationMatrixDistance(q[i], u[i].rotationMatrix()));
    EXPECT_LT(worst, 1e-10) << c.name;
    RecordProperty(c.R == 1.0 ? "sphere_worst" : "floor_worst", fmt::format("{:.3g}", worst));
    // The sign: the kinematics lifted continuously from U(0) = +1.
    const KinematicRun run = runKinematics(path, c.R, 8001, 200000);
    EXPECT_LT(spin::spinorDistance(run.lifted, st.final), 1e-9) << c.name;
    EXPECT_LT(rotationMatrixDistance(run.final, st.final.rotationMatrix()), 1e-10) << c.name;
  }
}

// A forward-only sample list (an animation's frames, generated on the fly)
// gives bit for bit the values of the same list held in memory.
TEST(Storyboard, ForwardOnlySamplesMatchAnExplicitList) {
  const geometry::JoinedPath path(floorPieces());
  std::vector<double> s = spin::uniformSamples(path.length(), 200);
  for (const auto& piece : path.pieces()) s.push_back(piece.start);  // samples exactly on the joins
  std::sort(s.begin(), s.end());
  for (Method m : {Method::Magnus4, Method::Frame6a}) {
    const spin::Propagator propagator(path, 1.0, m, 3000, 1e-10);
    std::vector<Su2> a(s.size()), b(s.size());
    const Su2 fa = propagator.run(s, [&](std::size_t i, double, const Su2& q) { a[i] = q; }).final;
    std::size_t furthest = 0;
    const auto cursor = spin::SampleArcLengths::generated(s.size(), [&](std::size_t j) {
      EXPECT_GE(j + 1, furthest) << "a forward-only cursor was asked for an earlier sample";
      furthest = std::max(furthest, j + 1);
      return s[j];
    });
    const Su2 fb = propagator.run(cursor, [&](std::size_t i, double, const Su2& q) { b[i] = q; }).final;
    for (std::size_t i = 0; i < s.size(); ++i) {
      EXPECT_EQ(a[i].w, b[i].w) << i;
      EXPECT_EQ(a[i].z, b[i].z) << i;
    }
    EXPECT_EQ(fa.w, fb.w);
    EXPECT_EQ(fa.x, fb.x);
  }
}
