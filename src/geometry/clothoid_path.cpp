#include "geometry/clothoid_path.hpp"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace rollspin::geometry {

namespace {
constexpr int kDegree = 16;
// 20-point Gauss–Legendre on [−1, 1] (half the nodes; symmetric).
constexpr std::array<double, 10> kGlX{0.0765265211334973, 0.2277858511416451, 0.3737060887154195, 0.5108670019508271,
                                      0.6360536807265150, 0.7463319064601508, 0.8391169718222188, 0.9122344282513259,
                                      0.9639719272779138, 0.9931285991850949};
constexpr std::array<double, 10> kGlW{0.1527533871307258, 0.1491729864726037, 0.1420961093183820, 0.1316886384491766,
                                      0.1181945319615184, 0.1019301198172404, 0.0832767415767048, 0.0626720483341091,
                                      0.0406014298003869, 0.0176140071391521};
}  // namespace

PlaneClothoidPath::PlaneClothoidPath(std::shared_ptr<const Plane> plane, const Vec3& start, const Vec3& e1,
                                     double curvature0, double curvatureRate, double length)
    : plane_(std::move(plane)),
      start_(start),
      e1_(e1.normalized()),
      kappa0_(curvature0),
      curvatureRate_(curvatureRate),
      length_(length) {
  assert(std::abs(e1_.dot(plane_->normal())) < 1e-12);
  e2_ = plane_->normal().cross(e1_);
  // Panels: the tangent turns by ≤ 0.25 rad across each, and none is longer
  // than 1, so the offset is an entire function that a degree-16 Chebyshev
  // series resolves to round-off.
  auto kappaAbs = [&](double s) { return std::abs(kappa0_ + curvatureRate_ * s); };
  panelStarts_.push_back(0.0);
  double s = 0.0;
  while (s < length_) {
    double w = std::min(1.0, length_ - s);
    while (w * std::max(kappaAbs(s), kappaAbs(s + w)) > 0.25) w *= 0.5;
    s = (length_ - (s + w) < 1e-12 * std::max(1.0, length_)) ? length_ : s + w;
    panelStarts_.push_back(s);
  }
  // cos(π j k / n), shared by every panel's transform.
  std::array<std::array<double, kDegree + 1>, kDegree + 1> cosTable{};
  for (int j = 0; j <= kDegree; ++j)
    for (int k = 0; k <= kDegree; ++k) cosTable[j][k] = std::cos(std::numbers::pi * j * k / kDegree);

  double x = 0.0, y = 0.0;
  for (std::size_t p = 0; p + 1 < panelStarts_.size(); ++p) {
    const double a = panelStarts_[p], b = panelStarts_[p + 1];
    x0_.push_back(x);
    y0_.push_back(y);
    // ∫ₐᵗ (cos φ, sin φ) ds by Gauss–Legendre, at the Chebyshev–Lobatto nodes.
    auto offset = [&](double t) {
      const double mid = 0.5 * (a + t), half = 0.5 * (t - a);
      double ox = 0.0, oy = 0.0;
      for (std::size_t i = 0; i < kGlX.size(); ++i)
        for (double sign : {-1.0, 1.0}) {
          const double phi = turningAngle(mid + sign * half * kGlX[i]);
          ox += kGlW[i] * std::cos(phi);
          oy += kGlW[i] * std::sin(phi);
        }
      return std::array<double, 2>{half * ox, half * oy};
    };
    std::array<double, kDegree + 1> vx{}, vy{};
    for (int j = 0; j <= kDegree; ++j) {
      const double t = 0.5 * (a + b) + 0.5 * (b - a) * cosTable[j][1];  // node cos(π j / n)
      const auto o = offset(t);
      vx[j] = o[0];
      vy[j] = o[1];
    }
    std::vector<double> cx(kDegree + 1), cy(kDegree + 1);
    for (int k = 0; k <= kDegree; ++k) {
      double sx = 0.0, sy = 0.0;
      for (int j = 0; j <= kDegree; ++j) {
        const double w = (j == 0 || j == kDegree) ? 0.5 : 1.0;
        sx += w * vx[j] * cosTable[j][k];
        sy += w * vy[j] * cosTable[j][k];
      }
      const double scale = (2.0 / kDegree) * ((k == 0 || k == kDegree) ? 0.5 : 1.0);
      cx[k] = scale * sx;
      cy[k] = scale * sy;
    }
    const auto whole = offset(b);
    x += whole[0];
    y += whole[1];
    cx_.push_back(std::move(cx));
    cy_.push_back(std::move(cy));
  }
}

std::unique_ptr<PlaneClothoidPath> PlaneClothoidPath::symmetricSweep(double curvatureRate, double length) {
  auto plane = std::make_shared<const Plane>(Vec3::UnitZ());
  return std::make_unique<PlaneClothoidPath>(plane, Vec3::Zero(), defaultTangentFor(plane->normal()),
                                             -0.5 * curvatureRate * length, curvatureRate, length);
}

Vec3 PlaneClothoidPath::point(double s) const {
  s = std::clamp(s, 0.0, length_);
  const auto it = std::upper_bound(panelStarts_.begin(), panelStarts_.end(), s);
  const std::size_t p = std::min<std::size_t>(
      cx_.size() - 1, static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, it - panelStarts_.begin() - 1)));
  const double a = panelStarts_[p], b = panelStarts_[p + 1];
  const double xi = std::clamp((2.0 * s - a - b) / (b - a), -1.0, 1.0);
  auto clenshaw = [xi](const std::vector<double>& c) {
    double b1 = 0.0, b2 = 0.0;
    for (std::size_t k = c.size() - 1; k >= 1; --k) {
      const double b0 = 2.0 * xi * b1 - b2 + c[k];
      b2 = b1;
      b1 = b0;
    }
    return xi * b1 - b2 + c[0];
  };
  return start_ + (x0_[p] + clenshaw(cx_[p])) * e1_ + (y0_[p] + clenshaw(cy_[p])) * e2_;
}

Vec3 PlaneClothoidPath::normal(double s) const { return plane_->normalAt(point(s)); }

DarbouxSample PlaneClothoidPath::at(double s) const {
  const double phi = turningAngle(s);
  const double c = std::cos(phi), sn = std::sin(phi);
  DarbouxSample f;
  f.s = s;
  f.point = point(s);
  f.tangent = c * e1_ + sn * e2_;
  f.normal = plane_->normal();
  f.tangentNormal = -sn * e1_ + c * e2_;  // n × t
  f.geodesicCurvature = kappa0_ + curvatureRate_ * s;
  return f;
}

std::string PlaneClothoidPath::describe() const {
  char buf[160];
  std::snprintf(buf, sizeof buf, "clothoid kappa_g = %g + %g s, length %g, on a ", kappa0_, curvatureRate_, length_);
  return buf + plane_->describe();
}

}  // namespace rollspin::geometry
