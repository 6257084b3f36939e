#include "geometry/surface_curve.hpp"

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <optional>

namespace rollspin::geometry {

namespace {

constexpr int kGaussPoints = 20;
constexpr int kChebyshevDegree = 24;
// A segment starts as 4 panels, each halved until its arc length converges,
// at most 14 times: panels down to 1/65536 of a segment; beyond that the
// tolerance is round-off, not truncation.
constexpr int kInitialPanels = 4;
constexpr int kMaxPanelDepth = 14;

// Gauss–Legendre nodes and weights on [−1, 1], by Newton on P_n (computed once).
struct GaussLegendre {
  std::array<double, kGaussPoints> x{}, w{};
  GaussLegendre() {
    const int n = kGaussPoints;
    for (int i = 0; i < n; ++i) {
      double z = std::cos(std::numbers::pi * (i + 0.75) / (n + 0.5)), dp = 1.0;
      for (int it = 0; it < 100; ++it) {
        double p0 = 1.0, p1 = z;
        for (int k = 2; k <= n; ++k) {
          const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
          p0 = p1;
          p1 = p2;
        }
        dp = n * (z * p1 - p0) / (z * z - 1.0);
        const double dz = p1 / dp;
        z -= dz;
        if (std::abs(dz) < 1e-17) break;
      }
      x[static_cast<std::size_t>(i)] = z;
      w[static_cast<std::size_t>(i)] = 2.0 / ((1.0 - z * z) * dp * dp);
    }
  }
};
const GaussLegendre& gauss() {
  static const GaussLegendre g;
  return g;
}

// x = cos(π (j + ½)/n): points halfway between Lobatto nodes, for checking.
std::vector<double> checkNodes(int n) {
  std::vector<double> x(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) x[static_cast<std::size_t>(j)] = std::cos(std::numbers::pi * (j + 0.5) / n);
  return x;
}

// Tangent, normal and their rates at curve parameter σ, for the smoothness
// check: |dt/ds| = |k| (curvature vector), |dn/ds| = √(κ_n² + τ_g²).
struct LocalFrame {
  Vec3 tangent, normal;
  double speed = 0.0, tangentRate = 0.0, normalRate = 0.0;
};
LocalFrame localFrame(const Surface& surface, const UvCurve& curve, double sigma) {
  const UvJet c = curve.at(sigma);
  const SurfaceJet j = surface.jet(c.uv);
  const double du = c.d1.x(), dv = c.d1.y();
  const Vec3 d1 = j.xu * du + j.xv * dv;
  const Vec3 d2 = j.xuu * (du * du) + j.xuv * (2.0 * du * dv) + j.xvv * (dv * dv) + j.xu * c.d2.x() + j.xv * c.d2.y();
  LocalFrame f;
  f.speed = d1.norm();
  f.tangent = d1 / f.speed;
  f.normal = j.xu.cross(j.xv).normalized();
  f.tangentRate = (d2 - d2.dot(f.tangent) * f.tangent).norm() / (f.speed * f.speed);
  const double E = j.xu.dot(j.xu), F = j.xu.dot(j.xv), G = j.xv.dot(j.xv);
  const double L = j.xuu.dot(f.normal), M = j.xuv.dot(f.normal), N = j.xvv.dot(f.normal);
  const double det = E * G - F * F;
  const Vec3 nu = ((F * M - G * L) * j.xu + (F * L - E * M) * j.xv) / det;
  const Vec3 nv = ((F * N - G * M) * j.xu + (F * M - E * N) * j.xv) / det;
  f.normalRate = (nu * du + nv * dv).norm() / f.speed;
  return f;
}

// A unit vector cannot move further than the integral of its rate: a jump
// beyond 1.5× Simpson's estimate of ∫ rate ds (plus round-off) over a probe
// interval is a kink of the curve (t) or of the surface under it (n).
bool jumps(const Vec3& a, const Vec3& b, double rateA, double rateMid, double rateB, double ds) {
  const double travel = ds * (rateA + 4.0 * rateMid + rateB) / 6.0;
  return (b - a).norm() > 1.5 * travel + 1e-7;
}

}  // namespace

SurfaceCurvePath::SurfaceCurvePath(std::shared_ptr<const Surface> surface, std::shared_ptr<const UvCurve> curve,
                                   SurfaceCurveOptions options)
    : surface_(std::move(surface)), curve_(std::move(curve)), options_(options) {
  static std::atomic<std::uint64_t> nextId{1};
  id_ = nextId++;
  std::vector<double> cuts{curve_->start()};
  for (double b : curve_->breakpoints())
    if (b > curve_->start() && b < curve_->end()) cuts.push_back(b);
  cuts.push_back(curve_->end());
  if (!(cuts.back() > cuts.front())) throw GeometryError("the curve has an empty parameter range");
  if (options_.arcLengthParameter) {
    length_ = cuts.back() - cuts.front();
    for (std::size_t i = 1; i + 1 < cuts.size(); ++i) breakpoints_.push_back(cuts[i] - cuts.front());
    return;
  }
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    buildSegment(cuts[i], cuts[i + 1]);
    if (i + 2 < cuts.size()) breakpoints_.push_back(length_);
  }
  for (const Panel& p : panels_) panelStarts_.push_back(p.sStart);
}

double SurfaceCurvePath::speed(double sigma) const {
  const UvJet c = curve_->at(sigma);
  const SurfaceJet j = surface_->jet(c.uv);
  return (j.xu * c.d1.x() + j.xv * c.d1.y()).norm();
}

double SurfaceCurvePath::panelArcLength(double sigmaStart, double sigma) const {
  const GaussLegendre& g = gauss();
  const double mid = 0.5 * (sigmaStart + sigma), half = 0.5 * (sigma - sigmaStart);
  double sum = 0.0;
  for (int i = 0; i < kGaussPoints; ++i)
    sum += g.w[static_cast<std::size_t>(i)] * speed(mid + half * g.x[static_cast<std::size_t>(i)]);
  return half * sum;
}

void SurfaceCurvePath::buildSegment(double sigmaStart, double sigmaEnd) {
  // Walk the segment first: stay in the domain, finite, with non-zero speed.
  const ParameterDomain domain = surface_->domain();
  constexpr int kProbe = 512;
  double approxS = length_, typicalSpeed = 0.0;
  std::vector<double> speeds(kProbe + 1);
  for (int k = 0; k <= kProbe; ++k) {
    const double sigma = sigmaStart + (sigmaEnd - sigmaStart) * k / kProbe;
    const UvJet c = curve_->at(sigma);
    const bool finite = c.uv.allFinite() && c.d1.allFinite() && c.d2.allFinite();
    if (!finite || !domain.contains(c.uv)) {
      throw GeometryError("the path leaves the surface's domain at arc length ≈ " + describeNumber(approxS) +
                          " (curve parameter " + describeNumber(sigma) + ", surface parameters (" +
                          describeNumber(c.uv.x()) + ", " + describeNumber(c.uv.y()) + ") " +
                          surface_->parameterNames() + ")");
    }
    const SurfaceJet j = surface_->jet(c.uv);
    const double sp = (j.xu * c.d1.x() + j.xv * c.d1.y()).norm();
    const double area = j.xu.cross(j.xv).norm();
    // Not finite: the surface's own formula fails there (its key is to blame).
    if (!j.allFinite())
      throw SurfaceUndefinedError("the surface is undefined at arc length ≈ " + describeNumber(approxS) +
                                      " (surface parameters (" + describeNumber(c.uv.x()) + ", " +
                                      describeNumber(c.uv.y()) + ") " + surface_->parameterNames() +
                                      "): a value or derivative is not finite",
                                  c.uv, approxS);
    if (!std::isfinite(sp) || !(area > 0.0)) {
      throw GeometryError("the surface is undefined or singular at arc length ≈ " + describeNumber(approxS) +
                          " (surface parameters (" + describeNumber(c.uv.x()) + ", " + describeNumber(c.uv.y()) +
                          "): a value or derivative is not finite, or x_u × x_v = 0)");
    }
    speeds[static_cast<std::size_t>(k)] = sp;
    typicalSpeed = std::max(typicalSpeed, sp);
    if (k > 0) approxS += 0.5 * (sp + speeds[static_cast<std::size_t>(k - 1)]) * (sigmaEnd - sigmaStart) / kProbe;
  }
  for (int k = 0; k <= kProbe; ++k) {
    if (!(speeds[static_cast<std::size_t>(k)] > 1e-9 * typicalSpeed) || typicalSpeed == 0.0) {
      const double sigma = sigmaStart + (sigmaEnd - sigmaStart) * k / kProbe;
      throw GeometryError("the curve stops (zero speed: a cusp or corner) at curve parameter " + describeNumber(sigma));
    }
  }
  // Kinks: the tangent or the normal jumping between neighbouring probes.
  // Bisect a suspicious interval; a jump that survives to a width of 1e-12 is
  // a corner.
  auto kinkBetween = [&](double a, double b) {
    for (int it = 0; it < 60; ++it) {
      const double m = 0.5 * (a + b);
      const LocalFrame fa = localFrame(*surface_, *curve_, a), fm = localFrame(*surface_, *curve_, m),
                       fb = localFrame(*surface_, *curve_, b);
      auto bad = [&](const LocalFrame& p, const LocalFrame& q, double x, double y) {
        const LocalFrame mid = localFrame(*surface_, *curve_, 0.5 * (x + y));
        const double ds = (y - x) * (p.speed + 4.0 * mid.speed + q.speed) / 6.0;
        return jumps(p.tangent, q.tangent, p.tangentRate, mid.tangentRate, q.tangentRate, ds) ||
               jumps(p.normal, q.normal, p.normalRate, mid.normalRate, q.normalRate, ds);
      };
      if (bad(fa, fm, a, m)) b = m;
      else if (bad(fm, fb, m, b)) a = m;
      else return std::optional<double>();  // smooth after all: fast but continuous turning
      if (b - a < 1e-12 * (1.0 + std::abs(a))) return std::optional<double>(0.5 * (a + b));
    }
    return std::optional<double>(0.5 * (a + b));
  };
  for (int k = 0; k < kProbe; ++k) {
    const double a = sigmaStart + (sigmaEnd - sigmaStart) * k / kProbe;
    const double b = sigmaStart + (sigmaEnd - sigmaStart) * (k + 1) / kProbe;
    const LocalFrame fa = localFrame(*surface_, *curve_, a), fb = localFrame(*surface_, *curve_, b),
                     fm = localFrame(*surface_, *curve_, 0.5 * (a + b));
    const double ds = (b - a) * (fa.speed + 4.0 * fm.speed + fb.speed) / 6.0;
    if (!jumps(fa.tangent, fb.tangent, fa.tangentRate, fm.tangentRate, fb.tangentRate, ds) &&
        !jumps(fa.normal, fb.normal, fa.normalRate, fm.normalRate, fb.normalRate, ds))
      continue;
    if (const auto at = kinkBetween(a, b)) {
      const LocalFrame before = localFrame(*surface_, *curve_, *at - 1e-9 * (1.0 + std::abs(*at)));
      const LocalFrame after = localFrame(*surface_, *curve_, *at + 1e-9 * (1.0 + std::abs(*at)));
      const double turn =
          std::acos(std::clamp(before.tangent.dot(after.tangent), -1.0, 1.0)) * 180.0 / std::numbers::pi;
      const double fold = std::acos(std::clamp(before.normal.dot(after.normal), -1.0, 1.0)) * 180.0 / std::numbers::pi;
      throw GeometryError("the path has a corner at curve parameter " + describeNumber(*at) +
                          " (the tangent turns by " + describeNumber(turn) + " deg, the surface normal by " +
                          describeNumber(fold) +
                          " deg): round it (points with interpolation = \"polyline\" and a corner_radius) or "
                          "end the curve there");
    }
  }
  for (int p = 0; p < kInitialPanels; ++p) {
    const double a = sigmaStart + (sigmaEnd - sigmaStart) * p / kInitialPanels;
    const double b =
        p + 1 == kInitialPanels ? sigmaEnd : sigmaStart + (sigmaEnd - sigmaStart) * (p + 1) / kInitialPanels;
    fitPanel(a, b, length_, 0);
    length_ = panels_.back().sEnd;
  }
}

void SurfaceCurvePath::fitPanel(double sigmaStart, double sigmaEnd, double sStart, int depth) {
  const double total = panelArcLength(sigmaStart, sigmaEnd);
  const double sigmaMid = 0.5 * (sigmaStart + sigmaEnd);
  auto split = [&] {
    fitPanel(sigmaStart, sigmaMid, sStart, depth + 1);
    fitPanel(sigmaMid, sigmaEnd, panels_.back().sEnd, depth + 1);
  };
  // The quadrature must be converged on the panel: compare with its halves.
  const double halves = panelArcLength(sigmaStart, sigmaMid) + panelArcLength(sigmaMid, sigmaEnd);
  // Round-off: a 20-term sum of speeds carries a few ε·total, and σ itself is
  // only known to ε|σ|, i.e. s to ε|σ|·speed. Ask for a small multiple of both.
  constexpr double eps = std::numeric_limits<double>::epsilon();
  const double speedScale = std::max({speed(sigmaStart), speed(sigmaMid), speed(sigmaEnd)});
  const double sigmaScale = std::max(std::abs(sigmaStart), std::abs(sigmaEnd));
  const double tolerance = 8.0 * eps * (1.0 + total) + 4.0 * eps * sigmaScale * speedScale;
  // Still not converged on a panel 2^-14 of a quarter segment wide: the
  // curve (or the surface under it) is not smooth there — a kink that the
  // scene must round, or a cusp — or the segment turns so often (an ellipse
  // as a uv curve with t_end = 1e5 winds 16 000 times) that each of 2^16
  // panels is still too wide for the quadrature. The message names both, and
  // the panel's width, as the code cannot tell them apart cheaply.
  auto notSmooth = [&] {
    throw GeometryError("the path's arc length does not converge near curve parameter " + describeNumber(sigmaMid) +
                        " (arc length ≈ " + describeNumber(sStart) + ") even over a parameter step of " +
                        describeNumber(sigmaEnd - sigmaStart) + " (1/" +
                        std::to_string(kInitialPanels << kMaxPanelDepth) +
                        " of its segment): either the curve has a kink or cusp there (round corners with a "
                        "polyline's corner_radius, or split the curve there), or it turns too often over the segment "
                        "for steps that size (shorten its parameter range)");
  };
  if (std::abs(total - halves) > tolerance) {
    if (depth < kMaxPanelDepth) return split();
    notSmooth();
  }
  PanelBudget::spend(sigmaStart);

  // σ at Chebyshev–Lobatto nodes in s, by Newton on the quadrature.
  auto solveSigma = [&](double ds) {
    double sigma = sigmaStart + (sigmaEnd - sigmaStart) * ds / total;
    for (int it = 0; it < 40; ++it) {
      const double f = panelArcLength(sigmaStart, sigma) - ds;
      const double step = f / speed(sigma);
      sigma -= step;
      if (std::abs(step) <= 1e-16 * (std::abs(sigma) + std::abs(sigmaEnd - sigmaStart))) break;
    }
    return sigma;
  };
  const std::vector<double> x = chebyshevLobattoNodes(kChebyshevDegree);
  std::vector<double> values(x.size());
  for (std::size_t j = 0; j < x.size(); ++j) {
    if (j == 0) values[j] = sigmaEnd - sigmaStart;
    else if (j + 1 == x.size()) values[j] = 0.0;
    else values[j] = solveSigma(0.5 * total * (x[j] + 1.0)) - sigmaStart;
  }
  Panel panel{sigmaStart, sigmaEnd, sStart, sStart + total, chebyshevCoefficients(values)};
  // Between the nodes, the interpolant must still invert the quadrature.
  for (double xc : checkNodes(kChebyshevDegree)) {
    const double ds = 0.5 * total * (xc + 1.0);
    const double sigma = sigmaStart + chebyshevValue(panel.coefficients, xc);
    if (std::abs(panelArcLength(sigmaStart, sigma) - ds) > tolerance) {
      if (depth < kMaxPanelDepth) return split();
      notSmooth();
    }
  }
  panels_.push_back(std::move(panel));
}

double SurfaceCurvePath::parameterAt(double s) const {
  s = std::clamp(s, 0.0, length_);
  if (options_.arcLengthParameter) return curve_->start() + s;
  const auto it = std::upper_bound(panelStarts_.begin() + 1, panelStarts_.end(), s);
  const Panel& p = panels_[static_cast<std::size_t>(it - panelStarts_.begin()) - 1];
  const double x = 2.0 * (s - p.sStart) / (p.sEnd - p.sStart) - 1.0;
  return p.sigmaStart + chebyshevValue(p.coefficients, std::clamp(x, -1.0, 1.0));
}

double SurfaceCurvePath::arcLengthAt(double sigma) const {
  if (options_.arcLengthParameter) return sigma - curve_->start();
  for (const Panel& p : panels_)
    if (sigma <= p.sigmaEnd || &p == &panels_.back()) return p.sStart + panelArcLength(p.sigmaStart, sigma);
  return length_;
}

// The oracle asks for point(s) and then normal(s) at the same s; a
// one-entry per-thread cache of (u, v)(s) halves its cost.
namespace {
struct UvCache {
  std::uint64_t owner = 0;  // SurfaceCurvePath::id_ (addresses get reused)
  double s = 0.0;
  Vec2 uv = Vec2::Zero();
};
thread_local UvCache uvCache;
}  // namespace

Vec2 SurfaceCurvePath::cachedUvAt(double s) const {
  if (uvCache.owner != id_ || uvCache.s != s) uvCache = {id_, s, uvAt(s)};
  return uvCache.uv;
}

Vec3 SurfaceCurvePath::point(double s) const { return surface_->position(cachedUvAt(s)); }

Vec3 SurfaceCurvePath::normal(double s) const { return surface_->normal(cachedUvAt(s)); }

DarbouxSample SurfaceCurvePath::at(double s) const {
  const UvJet c = curve_->at(parameterAt(s));
  const SurfaceJet j = surface_->jet(c.uv);
  const double du = c.d1.x(), dv = c.d1.y();
  const Vec3 d1 = j.xu * du + j.xv * dv;
  const Vec3 d2 = j.xuu * (du * du) + j.xuv * (2.0 * du * dv) + j.xvv * (dv * dv) + j.xu * c.d2.x() + j.xv * c.d2.y();
  const double speed = d1.norm();
  DarbouxSample f;
  f.s = s;
  f.point = j.x;
  f.tangent = d1 / speed;
  f.normal = surface_->orientation() * j.xu.cross(j.xv).normalized();
  f.tangentNormal = f.normal.cross(f.tangent);
  const Vec3 curvature = (d2 - d2.dot(f.tangent) * f.tangent) / (speed * speed);
  f.normalCurvature = curvature.dot(f.normal);
  f.geodesicCurvature = curvature.dot(f.tangentNormal);
  // Weingarten: the normal's derivatives from the fundamental forms.
  const double E = j.xu.dot(j.xu), F = j.xu.dot(j.xv), G = j.xv.dot(j.xv);
  const double L = j.xuu.dot(f.normal), M = j.xuv.dot(f.normal), N = j.xvv.dot(f.normal);
  const double det = E * G - F * F;
  const Vec3 nu = ((F * M - G * L) * j.xu + (F * L - E * M) * j.xv) / det;
  const Vec3 nv = ((F * N - G * M) * j.xu + (F * M - E * N) * j.xv) / det;
  const Vec3 dnds = (nu * du + nv * dv) / speed;
  f.geodesicTorsion = -dnds.dot(f.tangentNormal);
  return f;
}

std::string SurfaceCurvePath::describe() const { return curve_->describe() + " on a " + surface_->describe(); }

// ---- physical validity -------------------------------------------------------

ContactCheck checkSingleContact(const SurfaceCurvePath& path, double ballRadius, int samples) {
  auto k1At = [&](double s) { return shapeAt(path.surface(), path.uvAt(s)).maxCurvature; };
  auto fails = [&](double s) { return !(ballRadius * k1At(s) < 1.0); };
  std::vector<double> grid;
  const double length = path.length();
  for (int k = 0; k <= samples; ++k) grid.push_back(length * k / samples);
  for (double b : path.breakpoints()) grid.push_back(b);
  const std::vector<double>& starts = path.panelStarts();
  for (std::size_t p = 0; p < starts.size(); ++p) {
    const double end = p + 1 < starts.size() ? starts[p + 1] : length;
    for (int k = 0; k < 16; ++k) grid.push_back(starts[p] + (end - starts[p]) * k / 16.0);
  }
  std::sort(grid.begin(), grid.end());
  ContactCheck check;
  for (std::size_t k = 0; k < grid.size(); ++k) {
    if (!fails(grid[k])) continue;
    double lo = k == 0 ? grid[0] : grid[k - 1], hi = grid[k];
    if (k > 0) {
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (fails(mid) ? hi : lo) = mid;
      }
    }
    check.ok = false;
    check.s = hi;
    check.point = path.point(hi);
    check.curvature = k1At(hi);
    check.reason = "at arc length s = " + describeNumber(hi) + " (point (" + describeNumber(check.point.x()) + ", " +
                   describeNumber(check.point.y()) + ", " + describeNumber(check.point.z()) +
                   ")) the surface curves towards the ball with principal curvature " +
                   describeNumber(check.curvature) + " (radius of curvature " + describeNumber(1.0 / check.curvature) +
                   "), but the ball's radius is " + describeNumber(ballRadius) +
                   ": the ball no longer touches at one point (needs ball.radius < " +
                   describeNumber(1.0 / check.curvature) + ")";
    return check;
  }
  return check;
}

}  // namespace rollspin::geometry
