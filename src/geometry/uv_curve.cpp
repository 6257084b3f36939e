#include "geometry/uv_curve.hpp"

#include "geometry/contact_path.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <numbers>

namespace rollspin::geometry {

namespace {
double cross2(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Index of the piece containing σ among knots k0 < k1 < … (clamped).
std::size_t pieceIndex(const std::vector<double>& knots, double sigma) {
  const auto it = std::upper_bound(knots.begin() + 1, knots.end() - 1, sigma);
  return static_cast<std::size_t>(it - knots.begin()) - 1;
}
}  // namespace

// ---- closed-form curves ------------------------------------------------------

FunctionUvCurve::FunctionUvCurve(Function f, double start, double end, std::string description)
    : f_(std::move(f)), start_(start), end_(end), description_(std::move(description)) {}

UvJet FunctionUvCurve::at(double sigma) const {
  const std::array<Jet, 2> p = f_(Jet::variableA(sigma));
  UvJet j;
  j.uv = Vec2(p[0].v, p[1].v);
  j.d1 = Vec2(p[0].da, p[1].da);
  j.d2 = Vec2(p[0].daa, p[1].daa);
  return j;
}

// ---- splines -----------------------------------------------------------------

std::shared_ptr<SplineUvCurve> SplineUvCurve::cubic(const std::vector<Vec2>& points, bool closed) {
  const std::size_t n = points.size();
  if (n < (closed ? 3u : 2u))
    throw GeometryError(std::string("a ") + (closed ? "closed" : "open") + " spline needs at least " +
                        (closed ? "3" : "2") + " points, got " + std::to_string(n));
  const std::size_t segments = closed ? n : n - 1;
  auto P = [&](std::size_t i) -> const Vec2& { return points[i % n]; };
  std::vector<double> h(segments);
  for (std::size_t i = 0; i < segments; ++i) {
    h[i] = (P(i + 1) - P(i)).norm();
    if (!(h[i] > 0.0))
      throw GeometryError("points " + std::to_string(i + 1) + " and " + std::to_string((i + 1) % n + 1) +
                          " coincide: a spline needs distinct consecutive points");
  }
  // Second derivatives M at the knots: the C² conditions (periodic, or
  // natural ends M = 0), solved densely (control polygons are short).
  const std::size_t m = closed ? n : n;
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(m));
  Eigen::MatrixXd rhs = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(m), 2);
  for (std::size_t i = 0; i < m; ++i) {
    const auto r = static_cast<Eigen::Index>(i);
    if (!closed && (i == 0 || i == n - 1)) {
      A(r, r) = 1.0;
      continue;
    }
    const std::size_t prev = (i + m - 1) % m, next = (i + 1) % m;
    const double hp = h[(i + segments - 1) % segments], hn = h[i % segments];
    A(r, static_cast<Eigen::Index>(prev)) += hp;
    A(r, r) += 2.0 * (hp + hn);
    A(r, static_cast<Eigen::Index>(next)) += hn;
    const Vec2 slope = (P(i + 1) - P(i)) / hn - (P(i) - P(i + n - 1)) / hp;
    rhs.row(r) = 6.0 * slope.transpose();
  }
  const Eigen::MatrixXd M = A.partialPivLu().solve(rhs);
  auto Mi = [&](std::size_t i) { return Vec2(M.row(static_cast<Eigen::Index>(i % m)).transpose()); };

  auto curve = std::make_shared<SplineUvCurve>(SplineUvCurve());
  curve->knots_.push_back(0.0);
  for (std::size_t i = 0; i < segments; ++i) {
    Piece piece;
    const Vec2 m0 = Mi(i), m1 = Mi(i + 1);
    piece.c0 = P(i);
    piece.c1 = (P(i + 1) - P(i)) / h[i] - h[i] * (2.0 * m0 + m1) / 6.0;
    piece.c2 = 0.5 * m0;
    piece.c3 = (m1 - m0) / (6.0 * h[i]);
    curve->pieces_.push_back(piece);
    curve->knots_.push_back(curve->knots_.back() + h[i]);
  }
  curve->description_ =
      std::string(closed ? "closed" : "open") + " cubic spline through " + std::to_string(n) + " points";
  return curve;
}

std::shared_ptr<SplineUvCurve> SplineUvCurve::roundedPolyline(const std::vector<Vec2>& points, bool closed,
                                                              double cornerRadius) {
  const std::size_t n = points.size();
  if (n < (closed ? 3u : 2u))
    throw GeometryError(std::string("a ") + (closed ? "closed" : "open") + " polyline needs at least " +
                        (closed ? "3" : "2") + " points, got " + std::to_string(n));
  const std::size_t legs = closed ? n : n - 1;
  auto P = [&](std::size_t i) -> const Vec2& { return points[i % n]; };
  std::vector<Vec2> dir(legs);
  std::vector<double> legLength(legs);
  for (std::size_t i = 0; i < legs; ++i) {
    legLength[i] = (P(i + 1) - P(i)).norm();
    if (!(legLength[i] > 0.0))
      throw GeometryError("points " + std::to_string(i + 1) + " and " + std::to_string((i + 1) % n + 1) + " coincide");
    dir[i] = (P(i + 1) - P(i)) / legLength[i];
  }
  // Corner k sits at point k, between leg k−1 and leg k; turn angle θ_k.
  std::vector<double> turn(n, 0.0), tangentLength(n, 0.0);
  for (std::size_t k = 0; k < n; ++k) {
    if (!closed && (k == 0 || k == n - 1)) continue;
    const Vec2& a = dir[(k + legs - 1) % legs];
    const Vec2& b = dir[k % legs];
    turn[k] = std::atan2(cross2(a, b), a.dot(b));
    if (std::abs(turn[k]) < 1e-12) continue;
    if (std::abs(turn[k]) > std::numbers::pi - 1e-9)
      throw GeometryError("the path turns back on itself at point " + std::to_string(k + 1));
    if (cornerRadius <= 0.0)
      throw GeometryError("corner at point " + std::to_string(k + 1) + " (the path turns by " +
                          describeNumber(turn[k] * 180.0 / std::numbers::pi) +
                          " deg): set a corner radius to round it, or use a spline");
    tangentLength[k] = cornerRadius * std::tan(0.5 * std::abs(turn[k]));
  }
  for (std::size_t i = 0; i < legs; ++i) {
    const double used = tangentLength[i] + tangentLength[(i + 1) % n];
    if (used > legLength[i] * (1.0 + 1e-12))
      throw GeometryError("corner radius " + describeNumber(cornerRadius) + " is too large for the leg from point " +
                          std::to_string(i + 1) + " to point " + std::to_string((i + 1) % n + 1) + " (length " +
                          describeNumber(legLength[i]) + ")");
  }

  auto curve = std::make_shared<SplineUvCurve>(SplineUvCurve());
  curve->knots_.push_back(0.0);
  auto addLine = [&](const Vec2& from, const Vec2& to) {
    const double len = (to - from).norm();
    if (len <= 1e-14) return;
    Piece piece;
    piece.c0 = from;
    piece.c1 = (to - from) / len;
    piece.c2 = piece.c3 = Vec2::Zero();
    curve->pieces_.push_back(piece);
    curve->knots_.push_back(curve->knots_.back() + len);
  };
  auto addArc = [&](std::size_t k) {
    const Vec2& a = dir[(k + legs - 1) % legs];
    const double sign = turn[k] > 0.0 ? 1.0 : -1.0;
    const Vec2 from = P(k) - tangentLength[k] * a;
    const Vec2 leftNormal(-a.y(), a.x());
    Piece piece;
    piece.arc = true;
    piece.radius = cornerRadius;
    piece.centre = from + sign * cornerRadius * leftNormal;
    const Vec2 r0 = from - piece.centre;
    piece.theta0 = std::atan2(r0.y(), r0.x());
    piece.rate = sign / cornerRadius;
    curve->pieces_.push_back(piece);
    curve->knots_.push_back(curve->knots_.back() + cornerRadius * std::abs(turn[k]));
  };
  for (std::size_t i = 0; i < legs; ++i) {
    const Vec2 from = P(i) + tangentLength[i] * dir[i];
    const Vec2 to = P(i + 1) - tangentLength[(i + 1) % n] * dir[i];
    addLine(from, to);
    const std::size_t k = (i + 1) % n;
    if (tangentLength[k] > 0.0 && (closed || k != 0)) addArc(k);
  }
  curve->description_ = std::string(closed ? "closed" : "open") + " polyline through " + std::to_string(n) + " points" +
                        (cornerRadius > 0.0 ? " with corners rounded to radius " + describeNumber(cornerRadius) : "");
  return curve;
}

UvJet SplineUvCurve::at(double sigma) const {
  const std::size_t i = pieceIndex(knots_, sigma);
  const Piece& p = pieces_[i];
  const double tau = sigma - knots_[i];
  UvJet j;
  if (p.arc) {
    const double th = p.theta0 + p.rate * tau, c = std::cos(th), s = std::sin(th);
    j.uv = p.centre + p.radius * Vec2(c, s);
    j.d1 = p.radius * p.rate * Vec2(-s, c);
    j.d2 = -p.radius * p.rate * p.rate * Vec2(c, s);
    return j;
  }
  j.uv = p.c0 + tau * (p.c1 + tau * (p.c2 + tau * p.c3));
  j.d1 = p.c1 + tau * (2.0 * p.c2 + 3.0 * tau * p.c3);
  j.d2 = 2.0 * p.c2 + 6.0 * tau * p.c3;
  return j;
}

std::vector<double> SplineUvCurve::breakpoints() const { return {knots_.begin() + 1, knots_.end() - 1}; }

// ---- Chebyshev ---------------------------------------------------------------

std::vector<double> chebyshevLobattoNodes(int n) {
  std::vector<double> x(static_cast<std::size_t>(n) + 1);
  for (int j = 0; j <= n; ++j) x[static_cast<std::size_t>(j)] = std::cos(std::numbers::pi * j / n);
  return x;
}

std::vector<double> chebyshevCoefficients(const std::vector<double>& values) {
  const int n = static_cast<int>(values.size()) - 1;
  std::vector<double> c(values.size(), 0.0);
  for (int k = 0; k <= n; ++k) {
    double sum = 0.0;
    for (int j = 0; j <= n; ++j) {
      const double w = (j == 0 || j == n) ? 0.5 : 1.0;
      sum += w * values[static_cast<std::size_t>(j)] * std::cos(std::numbers::pi * j * k / n);
    }
    c[static_cast<std::size_t>(k)] = (2.0 / n) * sum * ((k == 0 || k == n) ? 0.5 : 1.0);
  }
  return c;
}

double chebyshevValue(const std::vector<double>& c, double x) {
  // Clenshaw's recurrence.
  double b1 = 0.0, b2 = 0.0;
  for (std::size_t k = c.size() - 1; k >= 1; --k) {
    const double b0 = 2.0 * x * b1 - b2 + c[k];
    b2 = b1;
    b1 = b0;
  }
  return x * b1 - b2 + c[0];
}

void chebyshevEvaluate(const std::vector<double>& c, double x, double& f, double& df, double& d2f) {
  double t0 = 1.0, t1 = x, d0 = 0.0, d1 = 1.0, s0 = 0.0, s1 = 0.0;
  f = c[0] + (c.size() > 1 ? c[1] * x : 0.0);
  df = c.size() > 1 ? c[1] : 0.0;
  d2f = 0.0;
  for (std::size_t k = 2; k < c.size(); ++k) {
    const double t2 = 2.0 * x * t1 - t0;
    const double d2 = 2.0 * t1 + 2.0 * x * d1 - d0;
    const double s2 = 4.0 * d1 + 2.0 * x * s1 - s0;
    f += c[k] * t2;
    df += c[k] * d2;
    d2f += c[k] * s2;
    t0 = t1, t1 = t2, d0 = d1, d1 = d2, s0 = s1, s1 = s2;
  }
}

namespace {
thread_local PanelBudget* currentPanelBudget = nullptr;
}  // namespace

PanelBudget::PanelBudget(std::size_t panels) : limit_(panels), left_(panels), outer_(currentPanelBudget) {
  currentPanelBudget = this;
}

PanelBudget::~PanelBudget() { currentPanelBudget = outer_; }

void PanelBudget::spend(double sigma) {
  PanelBudget* budget = currentPanelBudget;
  if (budget == nullptr) return;
  if (budget->left_ == 0)
    throw GeometryError("the path needs more than the " + std::to_string(budget->limit_) +
                        " panels this run allows (reached near curve parameter " + describeNumber(sigma) +
                        "): shorten its parameter range, turns or length");
  --budget->left_;
}

PiecewiseChebyshevUvCurve::PiecewiseChebyshevUvCurve(const std::function<Vec2(double)>& sample,
                                                     std::vector<double> cuts, int degree, std::string description)
    : cuts_(std::move(cuts)), description_(std::move(description)) {
  const std::vector<double> x = chebyshevLobattoNodes(degree);
  for (std::size_t p = 0; p + 1 < cuts_.size(); ++p) {
    PanelBudget::spend(cuts_[p]);
    const double mid = 0.5 * (cuts_[p] + cuts_[p + 1]), half = 0.5 * (cuts_[p + 1] - cuts_[p]);
    std::vector<double> us(x.size()), vs(x.size());
    for (std::size_t j = 0; j < x.size(); ++j) {
      // Lobatto end nodes land exactly on the cuts, so panels join continuously.
      const double sigma = j == 0 ? cuts_[p + 1] : (j + 1 == x.size() ? cuts_[p] : mid + half * x[j]);
      const Vec2 uv = sample(sigma);
      us[j] = uv.x();
      vs[j] = uv.y();
    }
    const std::vector<double> cu = chebyshevCoefficients(us), cv = chebyshevCoefficients(vs);
    std::vector<Vec2> c(x.size());
    for (std::size_t k = 0; k < x.size(); ++k) c[k] = Vec2(cu[k], cv[k]);
    coefficients_.push_back(std::move(c));
  }
}

UvJet PiecewiseChebyshevUvCurve::at(double sigma) const {
  const std::size_t p = pieceIndex(cuts_, sigma);
  const double mid = 0.5 * (cuts_[p] + cuts_[p + 1]), half = 0.5 * (cuts_[p + 1] - cuts_[p]);
  const double x = (sigma - mid) / half;
  const auto& c = coefficients_[p];
  std::vector<double> cu(c.size()), cv(c.size());
  for (std::size_t k = 0; k < c.size(); ++k) cu[k] = c[k].x(), cv[k] = c[k].y();
  double fu, du, ddu, fv, dv, ddv;
  chebyshevEvaluate(cu, x, fu, du, ddu);
  chebyshevEvaluate(cv, x, fv, dv, ddv);
  UvJet j;
  j.uv = Vec2(fu, fv);
  j.d1 = Vec2(du, dv) / half;
  j.d2 = Vec2(ddu, ddv) / (half * half);
  return j;
}

std::vector<double> PiecewiseChebyshevUvCurve::breakpoints() const { return {cuts_.begin() + 1, cuts_.end() - 1}; }

}  // namespace rollspin::geometry
