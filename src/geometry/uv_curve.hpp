// UvCurve — a curve in a surface's parameter plane, σ ↦ (u(σ), v(σ)) for
// σ ∈ [start, end], with exact first and second derivatives. Interior
// breakpoints are the σ where a derivative may jump (spline knots, corner
// arcs); each piece between them is smooth (C^∞).
//   FunctionUvCurve   closed-form or expression curves written over Jet;
//   SplineUvCurve     cubic spline through control points (open: natural
//                     ends, zero curvature; closed: periodic), chord-length
//                     knots, C² (third derivative jumps at knots);
//                     or a polyline whose corners are rounded by circular
//                     arcs of a given radius (C¹, curvature jumps at the
//                     tangent points);
//   PiecewiseChebyshevUvCurve  (u, v) sampled on Chebyshev–Lobatto nodes per
//                     panel (the integrated geodesic), C⁰ between panels.
#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/jet.hpp"

namespace rollspin::geometry {

using Vec2 = Eigen::Vector2d;

// A curve or path that cannot be built: corners, leaving the domain, zero
// speed... `where` is the σ or arc length it concerns (NaN when none).
class GeometryError : public std::runtime_error {
 public:
  explicit GeometryError(const std::string& message) : std::runtime_error(message) {}
};

// The surface itself has no finite value or derivative at parameters `at`
// (a height field z = sqrt(-1 - x²) anywhere): the surface's formula is to
// blame, not the path that reached it. `arcLength`: where on the path (NaN
// when not known).
class SurfaceUndefinedError : public GeometryError {
 public:
  SurfaceUndefinedError(const std::string& message, const Vec2& at, double arcLength)
      : GeometryError(message), at_(at), arcLength_(arcLength) {}
  [[nodiscard]] const Vec2& at() const { return at_; }
  [[nodiscard]] double arcLength() const { return arcLength_; }

 private:
  Vec2 at_;
  double arcLength_;
};

// Bounds the panels that paths built on this thread may fit while the
// budget lives (the innermost of nested ones counts): the arc-length panels
// of a SurfaceCurvePath and the pieces of a PiecewiseChebyshevUvCurve. Past
// the bound the path throws GeometryError. Building a path costs about its
// panels (some 1 ms each with expression curves in a Release build, 25×
// that under the fuzzer's sanitizers, then a contact check per panel), and
// a long parameter range needs panels in proportion: a caller that must
// bound its time per input, as the fuzzer does, sets a budget. None by
// default: a scene may ask for as long a path as it likes.
class PanelBudget {
 public:
  explicit PanelBudget(std::size_t panels);
  ~PanelBudget();
  PanelBudget(const PanelBudget&) = delete;
  PanelBudget& operator=(const PanelBudget&) = delete;
  // One more panel, at curve parameter `sigma` (for the message).
  static void spend(double sigma);

 private:
  std::size_t limit_, left_;
  PanelBudget* outer_;
};

struct UvJet {
  Vec2 uv = Vec2::Zero();  // (u, v)
  Vec2 d1 = Vec2::Zero();  // d(u, v)/dσ
  Vec2 d2 = Vec2::Zero();  // d²(u, v)/dσ²
};

class UvCurve {
 public:
  virtual ~UvCurve() = default;
  [[nodiscard]] virtual UvJet at(double sigma) const = 0;
  [[nodiscard]] virtual double start() const = 0;
  [[nodiscard]] virtual double end() const = 0;
  [[nodiscard]] virtual std::vector<double> breakpoints() const { return {}; }
  [[nodiscard]] virtual std::string describe() const = 0;
};

class FunctionUvCurve final : public UvCurve {
 public:
  // f(σ as a Jet in variable a) → (u, v) as Jets.
  using Function = std::function<std::array<Jet, 2>(const Jet& sigma)>;
  FunctionUvCurve(Function f, double start, double end, std::string description);
  [[nodiscard]] UvJet at(double sigma) const override;
  [[nodiscard]] double start() const override { return start_; }
  [[nodiscard]] double end() const override { return end_; }
  [[nodiscard]] std::string describe() const override { return description_; }

 private:
  Function f_;
  double start_, end_;
  std::string description_;
};

class SplineUvCurve final : public UvCurve {
 public:
  // Cubic spline through points (≥ 2 open, ≥ 3 closed). Throws GeometryError
  // when two consecutive points coincide.
  static std::shared_ptr<SplineUvCurve> cubic(const std::vector<Vec2>& points, bool closed);
  // Polyline through points with each interior corner (and every corner of a
  // closed polygon) replaced by a circular arc of radius cornerRadius tangent
  // to both legs. cornerRadius = 0 with a real corner throws GeometryError
  // naming the corner; so does a radius too large for the legs.
  static std::shared_ptr<SplineUvCurve> roundedPolyline(const std::vector<Vec2>& points, bool closed,
                                                        double cornerRadius);
  [[nodiscard]] UvJet at(double sigma) const override;
  [[nodiscard]] double start() const override { return knots_.front(); }
  [[nodiscard]] double end() const override { return knots_.back(); }
  [[nodiscard]] std::vector<double> breakpoints() const override;
  [[nodiscard]] std::string describe() const override { return description_; }

 private:
  // One piece on [knots_[i], knots_[i+1]]: p(τ) = Σ c_k τ^k, τ = σ − knot.
  struct Piece {
    Vec2 c0 = Vec2::Zero(), c1 = Vec2::Zero(), c2 = Vec2::Zero(), c3 = Vec2::Zero();
    bool arc = false;            // a circular arc instead of a cubic
    Vec2 centre = Vec2::Zero();  // arc: p = centre + r (cos(θ0 + wτ), sin(θ0 + wτ))
    double radius = 0.0, theta0 = 0.0, rate = 0.0;
  };
  std::vector<double> knots_;
  std::vector<Piece> pieces_;
  std::string description_;
};

class PiecewiseChebyshevUvCurve final : public UvCurve {
 public:
  // sample(σ) → (u, v), fitted on each panel [cuts[i], cuts[i+1]] by a
  // degree-`degree` Chebyshev–Lobatto interpolant.
  PiecewiseChebyshevUvCurve(const std::function<Vec2(double)>& sample, std::vector<double> cuts, int degree,
                            std::string description);
  [[nodiscard]] UvJet at(double sigma) const override;
  [[nodiscard]] double start() const override { return cuts_.front(); }
  [[nodiscard]] double end() const override { return cuts_.back(); }
  [[nodiscard]] std::vector<double> breakpoints() const override;
  [[nodiscard]] std::string describe() const override { return description_; }

 private:
  std::vector<double> cuts_;
  std::vector<std::vector<Vec2>> coefficients_;  // Chebyshev coefficients per panel
  std::string description_;
};

// Chebyshev–Lobatto interpolation helpers (shared with the arc-length map).
// Nodes x_j = cos(π j / n), j = 0…n, on [−1, 1].
[[nodiscard]] std::vector<double> chebyshevLobattoNodes(int n);
// Coefficients c_k of Σ c_k T_k(x) interpolating values f_j at those nodes.
[[nodiscard]] std::vector<double> chebyshevCoefficients(const std::vector<double>& values);
// Σ c_k T_k(x) with its first and second derivatives in x (Clenshaw-like).
void chebyshevEvaluate(const std::vector<double>& c, double x, double& f, double& df, double& d2f);
[[nodiscard]] double chebyshevValue(const std::vector<double>& c, double x);

}  // namespace rollspin::geometry
