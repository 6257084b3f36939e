#include "geometry/surface_paths.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <numbers>

namespace rollspin::geometry {

namespace {

constexpr double kPi = std::numbers::pi;

std::string deg(double radians) { return describeNumber(radians * 180.0 / kPi) + " deg"; }

std::unique_ptr<SurfaceCurvePath> wrap(std::shared_ptr<const Surface> surface, FunctionUvCurve::Function f,
                                       double start, double end, std::string description,
                                       SurfaceCurveOptions options = {}) {
  auto curve = std::make_shared<FunctionUvCurve>(std::move(f), start, end, std::move(description));
  return std::make_unique<SurfaceCurvePath>(std::move(surface), std::move(curve), options);
}

SurfaceCurveOptions closedCircuit(double turns) {
  SurfaceCurveOptions o;
  o.constantCurvatures = true;
  o.turns = turns;
  return o;
}

}  // namespace

// ---- parallels ---------------------------------------------------------------

namespace {
// The azimuth along a parallel, φ0 + σ t. A zero start adds nothing, so the
// bytes of a scene without start_azimuth_deg stay as they were (0 + −0 would
// turn the cw parallel's first sin(φ) from −0 into +0).
Jet parallelAzimuth(const Jet& t, double sense, double startAzimuth) {
  return startAzimuth == 0.0 ? sense * t : startAzimuth + sense * t;
}
std::string fromAzimuth(double startAzimuth) { return startAzimuth == 0.0 ? "" : " from azimuth " + deg(startAzimuth); }
}  // namespace

std::unique_ptr<SurfaceCurvePath> sphereParallel(std::shared_ptr<const Sphere> sphere, double colatitude, double turns,
                                                 bool ccw, double startAzimuth) {
  const double sense = ccw ? 1.0 : -1.0;
  return wrap(
      sphere,
      [=](const Jet& t) {
        return std::array<Jet, 2>{Jet(colatitude), parallelAzimuth(t, sense, startAzimuth)};
      },
      0.0, 2.0 * kPi * turns, "parallel at colatitude " + deg(colatitude) + fromAzimuth(startAzimuth),
      closedCircuit(turns));
}

std::unique_ptr<SurfaceCurvePath> cylinderParallel(std::shared_ptr<const Cylinder> cylinder, double height,
                                                   double turns, bool ccw, double startAzimuth) {
  const double sense = ccw ? 1.0 : -1.0;
  return wrap(
      cylinder,
      [=](const Jet& t) {
        return std::array<Jet, 2>{parallelAzimuth(t, sense, startAzimuth), Jet(height)};
      },
      0.0, 2.0 * kPi * turns, "parallel at height " + describeNumber(height) + fromAzimuth(startAzimuth),
      closedCircuit(turns));
}

std::unique_ptr<SurfaceCurvePath> torusParallel(std::shared_ptr<const Torus> torus, double tubeAngle, double turns,
                                                bool ccw, double startAzimuth) {
  const double sense = ccw ? 1.0 : -1.0;
  return wrap(
      torus,
      [=](const Jet& t) {
        return std::array<Jet, 2>{parallelAzimuth(t, sense, startAzimuth), Jet(tubeAngle)};
      },
      0.0, 2.0 * kPi * turns, "parallel at tube angle " + deg(tubeAngle) + fromAzimuth(startAzimuth),
      closedCircuit(turns));
}

std::unique_ptr<SurfaceCurvePath> heightFieldParallel(std::shared_ptr<const HeightField> field, double radius,
                                                      double turns, bool ccw, double startAzimuth) {
  const double sense = ccw ? 1.0 : -1.0;
  return wrap(
      field,
      [=](const Jet& t) {
        const Jet phi = parallelAzimuth(t, sense, startAzimuth);
        return std::array<Jet, 2>{radius * cos(phi), radius * sin(phi)};
      },
      0.0, 2.0 * kPi * turns, "parallel of radius " + describeNumber(radius) + fromAzimuth(startAzimuth),
      closedCircuit(turns));
}

// ---- meridians ---------------------------------------------------------------

std::unique_ptr<SurfaceCurvePath> sphereMeridian(std::shared_ptr<const Sphere> sphere, double azimuth,
                                                 double colatitudeStart, double colatitudeEnd) {
  // σ ∈ [0, 1] so that the curve may run either way in θ.
  const double span = colatitudeEnd - colatitudeStart;
  return wrap(
      sphere,
      [=](const Jet& t) {
        return std::array<Jet, 2>{colatitudeStart + span * t, Jet(azimuth)};
      },
      0.0, 1.0,
      "meridian at azimuth " + deg(azimuth) + " from colatitude " + deg(colatitudeStart) + " to " + deg(colatitudeEnd),
      closedCircuit(0.0));  // a great circle: κ_n = ∓1/r, κ_g = τ_g = 0
}

std::unique_ptr<SurfaceCurvePath> torusMeridian(std::shared_ptr<const Torus> torus, double azimuth,
                                                double tubeAngleStart, double turns, bool ccw) {
  const double sense = ccw ? 1.0 : -1.0;
  return wrap(
      torus,
      [=](const Jet& t) {
        return std::array<Jet, 2>{Jet(azimuth), tubeAngleStart + sense * t};
      },
      0.0, 2.0 * kPi * turns, "meridian (round the tube) at azimuth " + deg(azimuth), closedCircuit(turns));
}

std::unique_ptr<SurfaceCurvePath> cylinderMeridian(std::shared_ptr<const Cylinder> cylinder, double azimuth,
                                                   double height, double length) {
  return wrap(
      cylinder,
      [=](const Jet& t) {
        return std::array<Jet, 2>{Jet(azimuth), height + t};
      },
      0.0, length, "generator line at azimuth " + deg(azimuth) + " of length " + describeNumber(length),
      closedCircuit(0.0));
}

std::unique_ptr<SurfaceCurvePath> heightFieldMeridian(std::shared_ptr<const HeightField> field, double azimuth,
                                                      double length) {
  const double c = std::cos(azimuth), s = std::sin(azimuth);
  return wrap(
      field,
      [=](const Jet& t) {
        return std::array<Jet, 2>{c * t, s * t};
      },
      -0.5 * length, 0.5 * length, "vertical section through the z axis at azimuth " + deg(azimuth));
}

// ---- helix and loxodrome ---------------------------------------------------------

std::unique_ptr<SurfaceCurvePath> cylinderHelix(std::shared_ptr<const Cylinder> cylinder, double pitchAngle,
                                                double height, double turns, bool ccw) {
  const double sense = ccw ? 1.0 : -1.0, rise = cylinder->radius() * std::tan(pitchAngle);
  return wrap(
      cylinder,
      [=](const Jet& t) {
        return std::array<Jet, 2>{sense * t, height + rise * t};
      },
      0.0, 2.0 * kPi * turns, "helix with pitch angle " + deg(pitchAngle), closedCircuit(turns));
}

std::unique_ptr<SurfaceCurvePath> sphereLoxodrome(std::shared_ptr<const Sphere> sphere, double heading, double azimuth,
                                                  double colatitudeStart, double colatitudeEnd) {
  const double span = colatitudeEnd - colatitudeStart, k = std::tan(heading);
  const double logStart = std::log(std::tan(0.5 * colatitudeStart));
  return wrap(
      sphere,
      [=](const Jet& t) {
        const Jet theta = colatitudeStart + span * t;
        return std::array<Jet, 2>{theta, azimuth + k * (log(tan(0.5 * theta)) - logStart)};
      },
      0.0, 1.0,
      "loxodrome at heading " + deg(heading) + " from colatitude " + deg(colatitudeStart) + " to " +
          deg(colatitudeEnd));
}

// ---- geodesics -----------------------------------------------------------------

namespace {
using State = Eigen::Vector4d;  // (u, v, u', v') in arc length

// Geodesic equation: α'' ⊥ surface ⇒ (u'', v'') = −I⁻¹ (x_u·Q, x_v·Q),
// Q = x_uu u'² + 2 x_uv u'v' + x_vv v'².
State geodesicRate(const Surface& surface, const State& y) {
  const SurfaceJet j = surface.jet(Vec2(y[0], y[1]));
  const double a = y[2], b = y[3];
  const Vec3 q = j.xuu * (a * a) + j.xuv * (2.0 * a * b) + j.xvv * (b * b);
  Eigen::Matrix2d metric;
  metric << j.xu.dot(j.xu), j.xu.dot(j.xv), j.xu.dot(j.xv), j.xv.dot(j.xv);
  const Vec2 acc = -metric.inverse() * Vec2(j.xu.dot(q), j.xv.dot(q));
  return {a, b, acc.x(), acc.y()};
}

State rk4Increment(const Surface& surface, const State& y, double h) {
  const State k1 = geodesicRate(surface, y);
  const State k2 = geodesicRate(surface, y + 0.5 * h * k1);
  const State k3 = geodesicRate(surface, y + 0.5 * h * k2);
  const State k4 = geodesicRate(surface, y + h * k3);
  return (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

State rk4(const Surface& surface, const State& y, double h) { return y + rk4Increment(surface, y, h); }

// A geodesic as its own march, in arc length: between nodes (σ_k, σ_k + h)
// the quintic Hermite interpolant of (u, v) with the march's rates and the
// geodesic equation's accelerations at both nodes (error O(h⁶) in place,
// O(h⁵) in the rate), and d2 the geodesic equation's at that place and
// rate: its derivatives are the ODE's own, not those of a fit (whose d2
// the frame methods integrate as κ_g), for one surface evaluation a point.
class MarchedGeodesicCurve final : public UvCurve {
 public:
  MarchedGeodesicCurve(std::shared_ptr<const Surface> surface, const std::vector<State>& nodes, double h, double length)
      : surface_(std::move(surface)), h_(h), length_(length) {
    for (const State& y : nodes) {
      const State rate = geodesicRate(*surface_, y);
      nodes_.push_back({Vec2(y[0], y[1]), Vec2(y[2], y[3]), Vec2(rate[2], rate[3])});
    }
  }
  [[nodiscard]] UvJet at(double sigma) const override {
    const auto last = static_cast<long long>(nodes_.size()) - 2;
    const auto k = static_cast<std::size_t>(std::clamp<long long>(static_cast<long long>(sigma / h_), 0, last));
    const double t = sigma / h_ - static_cast<double>(k);
    const UvJet& a = nodes_[k];
    const UvJet& b = nodes_[k + 1];
    // p(t) = Σ c_i t^i on [0, 1], matching value, h·d1 and h²·d2 at both ends.
    const Vec2 jump = b.uv - a.uv, v0 = h_ * a.d1, v1 = h_ * b.d1, a0 = h_ * h_ * a.d2, a1 = h_ * h_ * b.d2;
    const Vec2 c2 = 0.5 * a0;
    const Vec2 c3 = 10.0 * jump - 6.0 * v0 - 4.0 * v1 - 1.5 * a0 + 0.5 * a1;
    const Vec2 c4 = -15.0 * jump + 8.0 * v0 + 7.0 * v1 + 1.5 * a0 - a1;
    const Vec2 c5 = 6.0 * jump - 3.0 * (v0 + v1) - 0.5 * (a0 - a1);
    UvJet j;
    j.uv = a.uv + t * (v0 + t * (c2 + t * (c3 + t * (c4 + t * c5))));
    j.d1 = (v0 + t * (2.0 * c2 + t * (3.0 * c3 + t * (4.0 * c4 + t * 5.0 * c5)))) / h_;
    const State rate = geodesicRate(*surface_, State(j.uv.x(), j.uv.y(), j.d1.x(), j.d1.y()));
    j.d2 = Vec2(rate[2], rate[3]);
    return j;
  }
  [[nodiscard]] double start() const override { return 0.0; }
  [[nodiscard]] double end() const override { return length_; }
  [[nodiscard]] std::string describe() const override {
    return "geodesic of length " + describeNumber(length_) + " (RK4 march, finer)";
  }

 private:
  std::shared_ptr<const Surface> surface_;
  std::vector<UvJet> nodes_;  // (u, v), their rate and acceleration at each node
  double h_, length_;
};

// The same geodesic marched at half the step, its sums compensated (Kahan),
// used as it is (no fit, no arc-length map): RK4's error falls 16-fold and
// the rounding that a long march of equal increments piles up (7.5e-13 in
// (u, v) over 6,000 steps on a cylinder) is carried, so this path's error
// is far below the fitted one's and the two differ by the fitted one's own.
std::unique_ptr<ContactPath> finerGeodesic(std::shared_ptr<const Surface> surface, const State& start, double length,
                                           long long steps) {
  const double h = length / static_cast<double>(steps);
  std::vector<State> nodes{start};
  nodes.reserve(static_cast<std::size_t>(steps) + 1);
  State carry = State::Zero();
  for (long long k = 0; k < steps; ++k) {
    const State& y = nodes.back();
    const State increment = rk4Increment(*surface, y, h) - carry;
    const State sum = y + increment;
    carry = (sum - y) - increment;
    nodes.push_back(sum);
  }
  SurfaceCurveOptions options;
  options.arcLengthParameter = true;
  auto curve = std::make_shared<MarchedGeodesicCurve>(surface, nodes, h, length);
  return std::make_unique<SurfaceCurvePath>(std::move(surface), std::move(curve), options);
}
}  // namespace

namespace {
// A geodesic on a sphere is a great circle, in closed form: with a the unit
// start point and b the unit start tangent, p(σ)/r = cos t a + sin t b,
// t = σ/r, so θ = acos(p_z/r) and, writing p_xy = A cos t + B sin t = P e^{it}
// + Q e^{−it} (complex, P = (A − iB)/2, Q = (A + iB)/2), the azimuth is
// arg P + t + atan(k sin(γ − 2t)/(1 + k cos(γ − 2t))), k e^{iγ} = Q/P, when
// |P| > |Q| (else the same with P, Q and t, −t swapped): continuous, no
// unwrapping. Its curvatures are constant (κ_g = 0, κ_n = ∓1/r, τ_g = 0), so
// `exact` applies. |P| = |Q| is a circle through a pole, where the azimuth
// is undefined: it leaves the parameter domain.
std::unique_ptr<SurfaceCurvePath> greatCircle(std::shared_ptr<const Sphere> sphere, const Vec2& startUv,
                                              const Vec3& unitDirection, double length) {
  const double r = sphere->radius();
  const Vec3 a = sphere->jet(startUv).x / r, b = unitDirection;
  const std::complex<double> A(a.x(), a.y()), B(b.x(), b.y()), I(0.0, 1.0);
  const std::complex<double> P = 0.5 * (A - I * B), Q = 0.5 * (A + I * B);
  if (!(std::abs(std::abs(P) - std::abs(Q)) > 1e-9))
    throw GeometryError(
        "the geodesic (a great circle) passes through a pole of the sphere, where the azimuth "
        "is undefined");
  const bool forward = std::abs(P) > std::abs(Q);
  const std::complex<double> lead = forward ? P : Q, ratio = forward ? Q / P : P / Q;
  const double k = std::abs(ratio), gamma = std::arg(ratio), base = std::arg(lead), sense = forward ? 1.0 : -1.0;
  auto azimuth = [=](const Jet& t) {
    const Jet phase = gamma - 2.0 * sense * t;
    return base + sense * t + atan(k * sin(phase) / (1.0 + k * cos(phase)));
  };
  // Start on the caller's sheet of the azimuth (it may lie outside [−π, π]).
  const double turnsOff = std::round((startUv.y() - azimuth(Jet(0.0)).v) / (2.0 * kPi));
  const double offset = 2.0 * kPi * turnsOff;
  SurfaceCurveOptions options;
  options.constantCurvatures = true;
  return wrap(
      sphere,
      [=](const Jet& sigma) {
        const Jet t = sigma / r;
        return std::array<Jet, 2>{acos(a.z() * cos(t) + b.z() * sin(t)), azimuth(t) + offset};
      },
      0.0, length, "geodesic (great circle) of length " + describeNumber(length), options);
}
}  // namespace

std::unique_ptr<SurfaceCurvePath> geodesicPath(std::shared_ptr<const Surface> surface, const Vec2& startUv,
                                               const Vec3& direction, double length) {
  const SurfaceJet j0 = surface->jet(startUv);
  if (!j0.allFinite())
    throw SurfaceUndefinedError("the surface is undefined at the geodesic's start (surface parameters (" +
                                    describeNumber(startUv.x()) + ", " + describeNumber(startUv.y()) + ") " +
                                    surface->parameterNames() + ")",
                                startUv, 0.0);
  const Vec3 n0 = j0.xu.cross(j0.xv).normalized();
  const Vec3 w = direction - direction.dot(n0) * n0;
  if (!(w.norm() > 1e-9 * direction.norm()))
    throw GeometryError("the geodesic's direction is perpendicular to the surface at its start point");
  Eigen::Matrix2d metric;
  metric << j0.xu.dot(j0.xu), j0.xu.dot(j0.xv), j0.xu.dot(j0.xv), j0.xv.dot(j0.xv);
  const Vec3 unit = w.normalized();
  if (auto sphere = std::dynamic_pointer_cast<const Sphere>(surface)) return greatCircle(sphere, startUv, unit, length);
  const Vec2 rate = metric.inverse() * Vec2(j0.xu.dot(unit), j0.xv.dot(unit));

  // Integrate on a fine uniform grid, keeping every node (dense output by one
  // partial RK4 step from the node below).
  const auto steps = static_cast<long long>(std::max(2000.0, std::ceil(500.0 * length)));
  const double h = length / static_cast<double>(steps);
  std::vector<State> nodes{State(startUv.x(), startUv.y(), rate.x(), rate.y())};
  const ParameterDomain domain = surface->domain();
  for (long long k = 0; k < steps; ++k) {
    const State next = rk4(*surface, nodes.back(), h);
    // A step that comes out not finite because the surface is not, at one of
    // RK4's stage points (a half and a whole step ahead): its formula is to blame.
    for (const double t : {0.5, 1.0}) {
      if (next.allFinite()) break;
      const State& last = nodes.back();
      const Vec2 probe(last[0] + t * h * last[2], last[1] + t * h * last[3]);
      if (!surface->jet(probe).allFinite())
        throw SurfaceUndefinedError("the surface is undefined where the geodesic reaches at arc length ≈ " +
                                        describeNumber((static_cast<double>(k) + t) * h) + " (surface parameters (" +
                                        describeNumber(probe.x()) + ", " + describeNumber(probe.y()) + ") " +
                                        surface->parameterNames() + ")",
                                    probe, (static_cast<double>(k) + t) * h);
    }
    if (!next.allFinite() || !domain.contains(Vec2(next[0], next[1])))
      throw GeometryError("the geodesic leaves the surface's domain at arc length ≈ " +
                          describeNumber(static_cast<double>(k + 1) * h) + " (surface parameters (" +
                          describeNumber(next[0]) + ", " + describeNumber(next[1]) + ") " + surface->parameterNames() +
                          ")");
    nodes.push_back(next);
  }
  auto dense = [&](double s) {
    const auto k = std::clamp<long long>(static_cast<long long>(s / h), 0, steps - 1);
    const double ds = s - static_cast<double>(k) * h;
    const State y =
        ds == 0.0 ? nodes[static_cast<std::size_t>(k)] : rk4(*surface, nodes[static_cast<std::size_t>(k)], ds);
    return Vec2(y[0], y[1]);
  };
  // Chebyshev panels of length ≤ 1/2 (halved until the fit matches the
  // integration to 1e-12 relative between nodes).
  constexpr int kDegree = 24;
  double panelLength = std::min(0.5, length);
  for (int attempt = 0;; ++attempt) {
    const auto panels = static_cast<long long>(std::ceil(length / panelLength));
    std::vector<double> cuts;
    for (long long p = 0; p <= panels; ++p)
      cuts.push_back(length * static_cast<double>(p) / static_cast<double>(panels));
    auto curve = std::make_shared<PiecewiseChebyshevUvCurve>(
        dense, cuts, kDegree, "geodesic of length " + describeNumber(length) + " (integrated, RK4 + Chebyshev panels)");
    double worst = 0.0, scale = 1.0;
    for (long long p = 0; p < panels; ++p)
      for (int q = 0; q < 8; ++q) {
        const double s = cuts[static_cast<std::size_t>(p)] +
                         (cuts[static_cast<std::size_t>(p + 1)] - cuts[static_cast<std::size_t>(p)]) * (q + 0.37) / 8.0;
        const Vec2 exact = dense(s);
        worst = std::max(worst, (curve->at(s).uv - exact).norm());
        scale = std::max(scale, exact.norm());
      }
    // Relative to the size of the parameters: far out on a surface (a long
    // geodesic up a saddle) round-off alone exceeds an absolute 1e-12, and
    // halving on regardless made 64x the panels for nothing (43 s).
    if (worst <= 1e-12 * scale || attempt >= 6) {
      SurfaceCurveOptions options;
      const State start = nodes.front();
      options.finer = [surface, start, length, steps] { return finerGeodesic(surface, start, length, 2 * steps); };
      return std::make_unique<SurfaceCurvePath>(surface, curve, options);
    }
    panelLength *= 0.5;
  }
}

// ---- expressions and control points ------------------------------------------------

std::unique_ptr<SurfaceCurvePath> uvExpressionPath(std::shared_ptr<const Surface> surface,
                                                   std::shared_ptr<const Expression> u,
                                                   std::shared_ptr<const Expression> v, double tStart, double tEnd) {
  const std::string description = "curve u = " + u->text() + ", v = " + v->text() + " for t in [" +
                                  describeNumber(tStart) + ", " + describeNumber(tEnd) + "]";
  return wrap(
      surface,
      [u, v](const Jet& t) {
        return std::array<Jet, 2>{u->jet(t), v->jet(t)};
      },
      tStart, tEnd, description);
}

std::unique_ptr<SurfaceCurvePath> pointsPath(std::shared_ptr<const Surface> surface, const std::vector<Vec2>& pointsUv,
                                             bool closed, PointsInterpolation interpolation, double cornerRadius) {
  std::shared_ptr<const UvCurve> curve =
      interpolation == PointsInterpolation::CubicSpline
          ? std::static_pointer_cast<const UvCurve>(SplineUvCurve::cubic(pointsUv, closed))
          : SplineUvCurve::roundedPolyline(pointsUv, closed, cornerRadius);
  SurfaceCurveOptions options;
  options.turns = closed ? 1.0 : 0.0;
  return std::make_unique<SurfaceCurvePath>(std::move(surface), std::move(curve), options);
}

}  // namespace rollspin::geometry
