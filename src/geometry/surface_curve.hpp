// SurfaceCurvePath — the contact path P(s) = x(u(σ(s)), v(σ(s))) of a
// parameter curve on a parametrised surface, stepped in arc length s.
//
// Arc length: s(σ) = ∫ |x_u u' + x_v v'| dσ by 20-point Gauss–Legendre on
// panels refined until the quadrature is converged; the inverse σ(s) is a
// degree-24 Chebyshev–Lobatto interpolant per panel, its nodes solved by
// Newton on the quadrature and checked between nodes:
// |s(σ(s)) − s| ≤ 8ε (1 + panel length) + 4ε |σ| |α′| (σ is only known to ε|σ|).
//
// Frame and curvatures from the fundamental forms (n on the ball's side):
//   α' = x_u u' + x_v v',  α'' = x_uu u'² + 2 x_uv u'v' + x_vv v'² + x_u u'' + x_v v'',
//   t = α'/|α'|,  u = n × t,  k = (α'' − (α''·t) t)/|α'|²  (curvature vector),
//   κ_n = k·n,  κ_g = k·u,
//   dn/ds = (n_u u' + n_v v')/|α'| with Weingarten's equations
//   n_u = ((FM − GL) x_u + (FL − EM) x_v)/(EG − F²),
//   n_v = ((FN − GM) x_u + (FM − EN) x_v)/(EG − F²),   τ_g = −(dn/ds)·u.
// point(s) and normal(s) use only the surface's x(u, v) and unit normal.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/contact_path.hpp"
#include "geometry/surface.hpp"
#include "geometry/uv_curve.hpp"

namespace rollspin::geometry {

struct SurfaceCurveOptions {
  bool constantCurvatures = false;  // the caller knows κ_n, κ_g, τ_g are constant (parallels, helices)
  double turns = 0.0;               // closed circuits, for default sampling
  // The curve runs at unit speed already, σ = start + s (a geodesic's own
  // march): no arc-length map is fitted and no kink is looked for.
  bool arcLengthParameter = false;
  // Builds a second, finer approximation of the same curve (ContactPath::finerApproximation).
  std::function<std::unique_ptr<ContactPath>()> finer = nullptr;
};

class SurfaceCurvePath final : public ContactPath {
 public:
  // Throws GeometryError when the curve leaves the surface's parameter
  // domain, hits a non-finite value, or stops (zero speed: a cusp).
  SurfaceCurvePath(std::shared_ptr<const Surface> surface, std::shared_ptr<const UvCurve> curve,
                   SurfaceCurveOptions options = {});

  [[nodiscard]] double length() const override { return length_; }
  [[nodiscard]] DarbouxSample at(double s) const override;
  [[nodiscard]] Vec3 point(double s) const override;
  [[nodiscard]] Vec3 normal(double s) const override;
  [[nodiscard]] bool hasConstantCurvatures() const override { return options_.constantCurvatures; }
  [[nodiscard]] std::vector<double> breakpoints() const override { return breakpoints_; }
  [[nodiscard]] double turns() const override { return options_.turns; }
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] std::unique_ptr<ContactPath> finerApproximation() const override {
    return options_.finer ? options_.finer() : nullptr;
  }

  // σ(s) and (u, v)(s).
  [[nodiscard]] double parameterAt(double s) const;
  [[nodiscard]] Vec2 uvAt(double s) const { return curve_->at(parameterAt(s)).uv; }
  // s(σ) by quadrature (for tests of the inverse).
  [[nodiscard]] double arcLengthAt(double sigma) const;
  [[nodiscard]] const Surface& surface() const { return *surface_; }
  [[nodiscard]] std::size_t panelCount() const { return panels_.size(); }
  // Arc lengths where the arc-length panels start (finer where the curve's
  // speed varies faster): a scale for sampling the path.
  [[nodiscard]] const std::vector<double>& panelStarts() const { return panelStarts_; }
  [[nodiscard]] const UvCurve& curve() const { return *curve_; }

 private:
  struct Panel {
    double sigmaStart, sigmaEnd;       // σ range
    double sStart, sEnd;               // s range
    std::vector<double> coefficients;  // σ − sigmaStart as a Chebyshev series in s
  };
  [[nodiscard]] double speed(double sigma) const;
  [[nodiscard]] Vec2 cachedUvAt(double s) const;
  [[nodiscard]] double panelArcLength(double sigmaStart, double sigma) const;
  void buildSegment(double sigmaStart, double sigmaEnd);
  void fitPanel(double sigmaStart, double sigmaEnd, double sStart, int depth);

  std::shared_ptr<const Surface> surface_;
  std::shared_ptr<const UvCurve> curve_;
  SurfaceCurveOptions options_;
  std::vector<Panel> panels_;
  std::vector<double> panelStarts_;  // panels_[i].sStart, for lookup
  std::vector<double> breakpoints_;  // s of the curve's σ breakpoints
  double length_ = 0.0;
  std::uint64_t id_ = 0;  // identifies this path in the per-thread (u, v) cache
};

// Where the ball stops touching the surface at a single point along a path.
struct ContactCheck {
  bool ok = true;
  std::string reason;  // "" when ok
  double s = 0.0;      // first failing arc length
  Vec3 point = Vec3::Zero();
  double curvature = 0.0;  // largest principal curvature towards the ball there
};

// A ball of radius R touches a surface at one point (locally) only while
// R k1 < 1, k1 the largest principal curvature towards the ball (inside a
// sphere: R < r; inside a cylinder: R < a; on a saddle: R < the concave
// principal radius). Scans `samples` uniform points, 16 per arc-length panel
// and every breakpoint, and bisects to the first failing s. Global overlaps far from the contact point
// are not checked.
[[nodiscard]] ContactCheck checkSingleContact(const SurfaceCurvePath& path, double ballRadius, int samples = 4000);

}  // namespace rollspin::geometry
