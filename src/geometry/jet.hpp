// Jet — second-order forward-mode automatic differentiation in two variables:
// a value f together with its gradient (f_a, f_b) and Hessian (f_aa, f_ab, f_bb)
// at one point, propagated exactly (to round-off) through +, −, ×, ÷ and the
// elementary functions by the chain rule
//   g(f)   : g' ∇f,   g' ∇²f + g'' ∇f ∇fᵀ
//   f · h  : f ∇h + h ∇f,   f ∇²h + h ∇²f + ∇f ∇hᵀ + ∇h ∇fᵀ.
// Surfaces (x(u, v)) and parameter curves (u(σ), v(σ); only variable a used)
// are written once as templates over the scalar type and evaluated with Jet
// to get their first and second derivatives without truncation error.
#pragma once

#include <cmath>

namespace rollspin::geometry {

struct Jet {
  double v = 0.0;                          // value
  double da = 0.0, db = 0.0;               // first derivatives
  double daa = 0.0, dab = 0.0, dbb = 0.0;  // second derivatives

  Jet() = default;
  Jet(double value) : v(value) {}  // NOLINT: constants promote implicitly
  Jet(double value, double a, double b, double aa, double ab, double bb)
      : v(value), da(a), db(b), daa(aa), dab(ab), dbb(bb) {}
  static Jet variableA(double value) {
    Jet j(value);
    j.da = 1.0;
    return j;
  }
  static Jet variableB(double value) {
    Jet j(value);
    j.db = 1.0;
    return j;
  }
};

// g(f) with g' = d1, g'' = d2 at f.v.
[[nodiscard]] inline Jet chain(const Jet& f, double g, double d1, double d2) {
  Jet r;
  r.v = g;
  r.da = d1 * f.da;
  r.db = d1 * f.db;
  r.daa = d1 * f.daa + d2 * f.da * f.da;
  r.dab = d1 * f.dab + d2 * f.da * f.db;
  r.dbb = d1 * f.dbb + d2 * f.db * f.db;
  return r;
}

inline Jet operator+(const Jet& a, const Jet& b) {
  return {a.v + b.v, a.da + b.da, a.db + b.db, a.daa + b.daa, a.dab + b.dab, a.dbb + b.dbb};
}
inline Jet operator-(const Jet& a, const Jet& b) {
  return {a.v - b.v, a.da - b.da, a.db - b.db, a.daa - b.daa, a.dab - b.dab, a.dbb - b.dbb};
}
inline Jet operator-(const Jet& a) { return {-a.v, -a.da, -a.db, -a.daa, -a.dab, -a.dbb}; }
inline Jet operator*(const Jet& a, const Jet& b) {
  return {a.v * b.v,
          a.v * b.da + b.v * a.da,
          a.v * b.db + b.v * a.db,
          a.v * b.daa + b.v * a.daa + 2.0 * a.da * b.da,
          a.v * b.dab + b.v * a.dab + a.da * b.db + a.db * b.da,
          a.v * b.dbb + b.v * a.dbb + 2.0 * a.db * b.db};
}
inline Jet operator*(double k, const Jet& a) { return {k * a.v, k * a.da, k * a.db, k * a.daa, k * a.dab, k * a.dbb}; }
inline Jet operator*(const Jet& a, double k) { return k * a; }
inline Jet reciprocal(const Jet& a) {
  const double r = 1.0 / a.v;
  return chain(a, r, -r * r, 2.0 * r * r * r);
}
inline Jet operator/(const Jet& a, const Jet& b) { return a * reciprocal(b); }
inline Jet operator/(const Jet& a, double k) { return (1.0 / k) * a; }
inline Jet& operator+=(Jet& a, const Jet& b) { return a = a + b; }
inline Jet& operator-=(Jet& a, const Jet& b) { return a = a - b; }
inline Jet& operator*=(Jet& a, const Jet& b) { return a = a * b; }

inline Jet sin(const Jet& a) {
  const double s = std::sin(a.v), c = std::cos(a.v);
  return chain(a, s, c, -s);
}
inline Jet cos(const Jet& a) {
  const double s = std::sin(a.v), c = std::cos(a.v);
  return chain(a, c, -s, -c);
}
inline Jet tan(const Jet& a) {
  const double t = std::tan(a.v), sec2 = 1.0 + t * t;
  return chain(a, t, sec2, 2.0 * t * sec2);
}
inline Jet exp(const Jet& a) {
  const double e = std::exp(a.v);
  return chain(a, e, e, e);
}
inline Jet log(const Jet& a) { return chain(a, std::log(a.v), 1.0 / a.v, -1.0 / (a.v * a.v)); }
inline Jet sqrt(const Jet& a) {
  const double r = std::sqrt(a.v);
  return chain(a, r, 0.5 / r, -0.25 / (r * a.v));
}
inline Jet sinh(const Jet& a) {
  const double s = std::sinh(a.v), c = std::cosh(a.v);
  return chain(a, s, c, s);
}
inline Jet cosh(const Jet& a) {
  const double s = std::sinh(a.v), c = std::cosh(a.v);
  return chain(a, c, s, c);
}
inline Jet tanh(const Jet& a) {
  const double t = std::tanh(a.v), d = 1.0 - t * t;
  return chain(a, t, d, -2.0 * t * d);
}
inline Jet asin(const Jet& a) {
  const double q = 1.0 - a.v * a.v, d1 = 1.0 / std::sqrt(q);
  return chain(a, std::asin(a.v), d1, a.v * d1 / q);
}
inline Jet acos(const Jet& a) {
  const double q = 1.0 - a.v * a.v, d1 = 1.0 / std::sqrt(q);
  return chain(a, std::acos(a.v), -d1, -a.v * d1 / q);
}
inline Jet atan(const Jet& a) {
  const double q = 1.0 / (1.0 + a.v * a.v);
  return chain(a, std::atan(a.v), q, -2.0 * a.v * q * q);
}
inline Jet asinh(const Jet& a) {
  const double q = 1.0 + a.v * a.v, d1 = 1.0 / std::sqrt(q);
  return chain(a, std::asinh(a.v), d1, -a.v * d1 / q);
}
inline Jet acosh(const Jet& a) {
  const double q = a.v * a.v - 1.0, d1 = 1.0 / std::sqrt(q);
  return chain(a, std::acosh(a.v), d1, -a.v * d1 / q);
}
inline Jet atanh(const Jet& a) {
  const double q = 1.0 / (1.0 - a.v * a.v);
  return chain(a, std::atanh(a.v), q, 2.0 * a.v * q * q);
}
// |f| is smooth away from f = 0 only; there it takes the one-sided branch.
inline Jet abs(const Jet& a) { return a.v < 0.0 ? -a : a; }
// f^p for a constant exponent p.
inline Jet pow(const Jet& a, double p) {
  if (p == 0.0) return Jet(1.0);
  if (p == 1.0) return a;
  if (p == 2.0) return a * a;
  const double g = std::pow(a.v, p);
  return chain(a, g, p * std::pow(a.v, p - 1.0), p * (p - 1.0) * std::pow(a.v, p - 2.0));
}
// f^h with both varying: exp(h log f) (f > 0).
inline Jet pow(const Jet& a, const Jet& b) {
  const bool constantExponent = b.da == 0.0 && b.db == 0.0 && b.daa == 0.0 && b.dab == 0.0 && b.dbb == 0.0;
  if (constantExponent) return pow(a, b.v);
  return exp(b * log(a));
}

}  // namespace rollspin::geometry
