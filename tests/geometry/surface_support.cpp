#include "surface_support.hpp"

#include <numbers>

#include "spin/field.hpp"
#include "support/numbers.hpp"

namespace rollspin::test {

using namespace geometry;

namespace {
std::shared_ptr<const Expression> expr(const std::string& text, std::vector<std::string> vars) {
  return std::make_shared<const Expression>(text, std::move(vars));
}
std::vector<Vec2> loopAround(double cx, double cy, double a, double b) {
  return {{cx + a, cy}, {cx + 0.3 * a, cy + b}, {cx - 0.8 * a, cy + 0.6 * b}, {cx - a, cy - 0.4 * b}, {cx, cy - b}};
}
}  // namespace

std::vector<SurfaceCase> allSurfaceCases() {
  auto plane = std::make_shared<const Plane>(Vec3(1.0, -0.5, 2.0));
  auto sphereOut = std::make_shared<const Sphere>(3.0, Side::Outside);
  auto sphereIn = std::make_shared<const Sphere>(3.0, Side::Inside);
  auto cylOut = std::make_shared<const Cylinder>(2.0, Vec3(0.2, 0.1, 1.0), Side::Outside);
  auto cylIn = std::make_shared<const Cylinder>(2.0, Vec3(0.0, 0.0, 1.0), Side::Inside);
  auto torusOut = std::make_shared<const Torus>(4.0, 1.5, Side::Outside);
  auto torusIn = std::make_shared<const Torus>(4.0, 1.5, Side::Inside);
  std::shared_ptr<const HeightField> bowl = HeightField::quadric(3.0, 3.0, false, true);
  std::shared_ptr<const HeightField> dome = HeightField::quadric(2.0, 2.0, false, false);
  std::shared_ptr<const HeightField> saddle = HeightField::quadric(3.0, 2.0, true, true);
  std::shared_ptr<const HeightField> bumps =
      HeightField::fromExpression(expr("0.3*sin(x)*cos(y)", {"x", "y"}), true);
  const double deg = kPi / 180.0;
  using P = std::unique_ptr<ContactPath>;
  return {
      // plane
      {"plane uv", [=]() -> P { return uvExpressionPath(plane, expr("2*cos(t)+0.5*cos(3*t)", {"t"}), expr("1.5*sin(t)", {"t"}), 0.0, 2 * kPi); }, 1.0},
      {"plane spline closed", [=]() -> P { return pointsPath(plane, loopAround(0, 0, 3, 2), true, PointsInterpolation::CubicSpline, 0); }, 1.0},
      {"plane spline open", [=]() -> P { return pointsPath(plane, {{0, 0}, {1, 1}, {2, 0.5}, {3, 2}}, false, PointsInterpolation::CubicSpline, 0); }, 0.7},
      {"plane polyline rounded", [=]() -> P { return pointsPath(plane, {{0, 0}, {3, 0}, {3, 2}, {0, 2}}, true, PointsInterpolation::Polyline, 0.5); }, 1.0},
      {"plane geodesic", [=]() -> P { return geodesicPath(plane, Vec2(0.5, 0.2), Vec3(1, 1, 0), 5.0); }, 1.0},
      // sphere
      {"sphere parallel (generic)", [=]() -> P { return sphereParallel(sphereOut, 60 * deg, 1.0, true); }, 1.0},
      {"sphere inside parallel", [=]() -> P { return sphereParallel(sphereIn, 50 * deg, 1.0, false); }, 1.0},
      {"sphere meridian", [=]() -> P { return sphereMeridian(sphereOut, 20 * deg, 20 * deg, 150 * deg); }, 1.0},
      {"sphere loxodrome", [=]() -> P { return sphereLoxodrome(sphereOut, 60 * deg, 0.0, 30 * deg, 140 * deg); }, 1.0},
      {"sphere inside loxodrome", [=]() -> P { return sphereLoxodrome(sphereIn, -50 * deg, 1.0, 120 * deg, 40 * deg); }, 0.8},
      {"sphere geodesic", [=]() -> P { return geodesicPath(sphereOut, Vec2(1.0, 0.3), Vec3(0.3, 1.0, 0.5), 9.0); }, 1.0},
      {"sphere uv", [=]() -> P { return uvExpressionPath(sphereOut, expr("1.2+0.4*sin(2*t)", {"t"}), expr("t", {"t"}), 0.0, 2 * kPi); }, 1.0},
      {"sphere points", [=]() -> P { return pointsPath(sphereIn, loopAround(1.5, 0.5, 0.6, 0.8), true, PointsInterpolation::CubicSpline, 0); }, 1.0},
      // cylinder
      {"cylinder parallel", [=]() -> P { return cylinderParallel(cylOut, 0.5, 1.0, true); }, 1.0},
      {"cylinder inside parallel", [=]() -> P { return cylinderParallel(cylIn, 0.0, 1.0, false); }, 1.5},
      {"cylinder meridian", [=]() -> P { return cylinderMeridian(cylOut, 0.3, -1.0, 6.0); }, 1.0},
      {"cylinder helix", [=]() -> P { return cylinderHelix(cylOut, 25 * deg, 0.0, 1.0, true); }, 1.0},
      {"cylinder inside helix", [=]() -> P { return cylinderHelix(cylIn, -40 * deg, 0.0, 1.0, true); }, 1.2},
      {"cylinder geodesic", [=]() -> P { return geodesicPath(cylOut, Vec2(0.0, 0.0), Vec3(0.0, 1.0, 0.4), 10.0); }, 1.0},
      {"cylinder uv", [=]() -> P { return uvExpressionPath(cylIn, expr("t", {"t"}), expr("0.5*sin(2*t)", {"t"}), 0.0, 2 * kPi); }, 1.0},
      {"cylinder points", [=]() -> P { return pointsPath(cylOut, loopAround(0.0, 0.0, 1.0, 1.5), true, PointsInterpolation::CubicSpline, 0); }, 1.0},
      // torus
      {"torus parallel", [=]() -> P { return torusParallel(torusOut, 60 * deg, 0.5, true); }, 1.0},
      {"torus inner-equator parallel", [=]() -> P { return torusParallel(torusOut, kPi, 1.0, false); }, 1.0},
      {"torus inside parallel", [=]() -> P { return torusParallel(torusIn, 30 * deg, 0.4, true); }, 0.6},
      {"torus meridian", [=]() -> P { return torusMeridian(torusOut, 0.4, 0.0, 1.0, true); }, 1.0},
      {"torus inside meridian", [=]() -> P { return torusMeridian(torusIn, 0.4, 0.0, 1.0, false); }, 0.6},
      {"torus geodesic", [=]() -> P { return geodesicPath(torusOut, Vec2(0.0, 0.5), Vec3(0.2, 1.0, 0.6), 12.0); }, 1.0},
      {"torus uv (torus knot)", [=]() -> P { return uvExpressionPath(torusOut, expr("2*t", {"t"}), expr("3*t", {"t"}), 0.0, 0.8 * kPi); }, 0.8},
      {"torus points", [=]() -> P { return pointsPath(torusIn, loopAround(0.5, 1.0, 0.8, 1.2), true, PointsInterpolation::CubicSpline, 0); }, 0.6},
      // quadric height fields
      {"paraboloid parallel", [=]() -> P { return heightFieldParallel(bowl, 2.0, 1.0, true); }, 1.0},
      {"dome parallel", [=]() -> P { return heightFieldParallel(dome, 1.5, 1.0, false); }, 1.0},
      {"paraboloid meridian", [=]() -> P { return heightFieldMeridian(bowl, 0.7, 6.0); }, 1.0},
      {"paraboloid geodesic", [=]() -> P { return geodesicPath(bowl, Vec2(-2.0, -1.0), Vec3(1.0, 0.3, 0.0), 6.0); }, 1.0},
      {"paraboloid uv", [=]() -> P { return uvExpressionPath(bowl, expr("t", {"t"}), expr("0.5*t^2-1", {"t"}), -2.0, 2.0); }, 1.0},
      {"paraboloid points", [=]() -> P { return pointsPath(dome, loopAround(0.3, 0.0, 1.5, 1.0), true, PointsInterpolation::CubicSpline, 0); }, 1.0},
      {"saddle meridian", [=]() -> P { return heightFieldMeridian(saddle, 0.5, 5.0); }, 1.0},
      {"saddle geodesic", [=]() -> P { return geodesicPath(saddle, Vec2(-2.0, 0.5), Vec3(1.0, -0.2, 0.0), 5.0); }, 1.0},
      {"saddle uv", [=]() -> P { return uvExpressionPath(saddle, expr("1.5*cos(t)", {"t"}), expr("1.5*sin(t)", {"t"}), 0.0, 2 * kPi); }, 1.0},
      {"saddle polyline rounded", [=]() -> P { return pointsPath(saddle, {{-2, -1}, {1, -1.5}, {2, 1}, {-1, 1.5}}, true, PointsInterpolation::Polyline, 0.6); }, 1.0},
      // expression height field
      {"height meridian", [=]() -> P { return heightFieldMeridian(bumps, 0.3, 6.0); }, 0.8},
      {"height geodesic", [=]() -> P { return geodesicPath(bumps, Vec2(-2.0, 0.3), Vec3(1.0, 0.4, 0.0), 5.0); }, 0.8},
      {"height uv", [=]() -> P { return uvExpressionPath(bumps, expr("2*cos(t)", {"t"}), expr("1.5*sin(t)", {"t"}), 0.0, 2 * kPi); }, 0.8},
      {"height points", [=]() -> P { return pointsPath(bumps, {{-2, -1}, {0, -1.2}, {1.5, 0}, {1, 1.5}, {-1, 1}}, false, PointsInterpolation::CubicSpline, 0); }, 0.8},
  };
}

double oracleDifferenceStep(double R) { return 2e-3 * std::min(1.0, R); }

double rotationGap(const spin::Su2& u, const Eigen::Matrix3d& q) {
  const Eigen::Matrix3d d = u.rotationMatrix().transpose() * q;
  const Eigen::Vector3d axisTimesSin(d(2, 1) - d(1, 2), d(0, 2) - d(2, 0), d(1, 0) - d(0, 1));
  return std::atan2(0.5 * axisTimesSin.norm(), 0.5 * (d.trace() - 1.0));
}

OracleComparison compareWithKinematics(const ContactPath& path, double R, spin::Method method, long long steps,
                                       long long kinematicSteps, std::size_t samples) {
  const std::vector<double> s = spin::uniformSamples(path.length(), samples);
  const auto q = kinematics::RollingKinematics(path, R, {kinematicSteps, oracleDifferenceStep(R)}).orientations(s);
  return compareWithOrientations(path, R, method, steps, s, q);
}

OracleComparison compareWithOrientations(const ContactPath& path, double R, spin::Method method, long long steps,
                                         const std::vector<double>& s, const std::vector<Eigen::Matrix3d>& q) {
  std::vector<spin::Su2> u(s.size());
  const spin::SolveStats st =
      spin::Propagator(path, R, method, steps).run(s, [&](std::size_t j, double, const spin::Su2& v) { u[j] = v; });
  EXPECT_EQ(st.status, spin::SolveStatus::Ok);
  OracleComparison c;
  c.unitarityError = st.unitarityError;
  for (std::size_t j = 0; j < s.size(); ++j) c.worstGap = std::max(c.worstGap, rotationGap(u[j], q[j]));
  return c;
}

Residuals rollingResiduals(const ContactPath& path, double R, spin::Method method, long long steps,
                           std::size_t samples) {
  const double L = path.length();
  std::vector<double> cuts{0.0};
  for (double b : path.breakpoints()) cuts.push_back(b);
  cuts.push_back(L);
  const std::vector<double> sampleS = spin::uniformSamples(L, samples);
  // Each sample's 9-point stencil stays inside its breakpoint segment.
  std::vector<double> all;
  std::vector<std::size_t> usable;
  for (std::size_t i = 0; i < sampleS.size(); ++i) {
    const double s = sampleS[i];
    std::size_t seg = 0;
    while (seg + 2 < cuts.size() && s >= cuts[seg + 1]) ++seg;
    const double a = cuts[seg], b = cuts[seg + 1];
    const double h = std::min(1e-3 * std::min(1.0, R), (b - a) / 16.0);
    const double first = std::clamp(s - 4 * h, a, b - 8 * h);
    usable.push_back(i);
    for (int k = 0; k < 9; ++k) all.push_back(first + k * h);
    all.push_back(s);
  }
  std::vector<std::size_t> order(all.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](auto x, auto y) { return all[x] < all[y]; });
  std::vector<double> sorted;
  for (auto i : order) sorted.push_back(all[i]);
  std::vector<spin::Su2> qSorted(sorted.size()), q(all.size());
  const auto st = spin::Propagator(path, R, method, steps)
                      .run(sorted, [&](std::size_t j, double, const spin::Su2& u) { qSorted[j] = u; });
  EXPECT_EQ(st.status, spin::SolveStatus::Ok);
  for (std::size_t j = 0; j < order.size(); ++j) q[order[j]] = qSorted[j];

  const kinematics::RollingKinematics kin(path, R, {1000, oracleDifferenceStep(R)});
  Residuals worst;
  for (std::size_t n = 0; n < usable.size(); ++n) {
    const double s = sampleS[usable[n]];
    const std::vector<double> nodes(all.begin() + static_cast<long>(n * 10), all.begin() + static_cast<long>(n * 10 + 9));
    const auto w = kinematics::firstDerivativeWeights(nodes, s);
    spin::Su2 dq{0, 0, 0, 0};
    for (int k = 0; k < 9; ++k) {
      const spin::Su2& u = q[n * 10 + static_cast<std::size_t>(k)];
      dq = {dq.w + w[k] * u.w, dq.x + w[k] * u.x, dq.y + w[k] * u.y, dq.z + w[k] * u.z};
    }
    const spin::Su2 omegaQuat = dq * q[n * 10 + 9].conjugate();
    const Eigen::Vector3d omega = 2.0 * omegaQuat.vec();
    const Eigen::Vector3d normal = path.normal(s);
    // dC/ds from the oracle's own stencil on point/normal (inside the segment).
    const Eigen::Vector3d centreVelocity = kin.centreVelocity(s);
    worst.slip = std::max(worst.slip, (centreVelocity - R * omega.cross(normal)).norm());
    worst.spin = std::max(worst.spin, std::abs(omega.dot(normal)));
  }
  return worst;
}

long long generousSteps(const ContactPath& path, double R) {
  const double rotation = spin::integratedFieldStrength(path, R);
  return std::max<long long>(4000, static_cast<long long>(400.0 * (rotation + path.length())));
}

}  // namespace rollspin::test
