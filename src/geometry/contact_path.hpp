// ContactPath — the curve traced by the contact point on the surface,
// parametrised by arc length s ∈ [0, length()], with its Darboux frame:
//   t = dP/ds,  n = unit surface normal pointing from the surface to the ball
//   centre,  u = n × t,  and (Darboux equations, (t, u, n) right-handed)
//   dt/ds =  κ_g u + κ_n n,   du/ds = −κ_g t + τ_g n,   dn/ds = −κ_n t − τ_g u.
// The ball centre is C(s) = P(s) + R n(s).
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace rollspin::geometry {

using Vec3 = Eigen::Vector3d;

// Frame and curvatures at one arc length.
struct DarbouxSample {
  double s = 0.0;
  Vec3 point = Vec3::Zero();           // P(s)
  Vec3 tangent = Vec3::UnitX();        // t
  Vec3 normal = Vec3::UnitZ();         // n, towards the ball centre
  Vec3 tangentNormal = Vec3::UnitY();  // u = n × t
  double normalCurvature = 0.0;        // κ_n
  double geodesicCurvature = 0.0;      // κ_g
  double geodesicTorsion = 0.0;        // τ_g (the paper's τ_r)

  [[nodiscard]] Vec3 centre(double ballRadius) const { return point + ballRadius * normal; }
};

class ContactPath;

// One piece of a joined path (joined_path.hpp): the piece and the arc length
// at which it starts in the whole path.
struct PathPiece {
  const ContactPath* path = nullptr;
  double start = 0.0;
};

class ContactPath {
 public:
  virtual ~ContactPath() = default;

  [[nodiscard]] virtual double length() const = 0;
  // Frame and curvatures (closed form or from the fundamental forms).
  [[nodiscard]] virtual DarbouxSample at(double s) const = 0;
  // Contact point and normal only, from the surface's own point and normal
  // functions: the independent kinematic oracle uses these and nothing else.
  [[nodiscard]] virtual Vec3 point(double s) const = 0;
  [[nodiscard]] virtual Vec3 normal(double s) const = 0;
  // True when κ_n, κ_g and τ_g are constant along the whole path, so the
  // closed-form propagator applies.
  [[nodiscard]] virtual bool hasConstantCurvatures() const = 0;
  // Interior arc lengths where a curvature jumps; steppers land on them.
  [[nodiscard]] virtual std::vector<double> breakpoints() const { return {}; }
  // Number of closed circuits (0 for an open path); sets default sampling.
  [[nodiscard]] virtual double turns() const { return 0.0; }
  [[nodiscard]] virtual std::string describe() const = 0;
  // Paths made of pieces (a storyboard): each piece with its start. Empty
  // for a path of one piece. The propagator solves piece by piece and
  // composes, U(s) = U_k(s − s_k) U_{k−1}(L_{k−1}) ⋯ U_1(L_1).
  [[nodiscard]] virtual std::span<const PathPiece> pieces() const { return {}; }
  // For a path that is itself an approximation (a geodesic, integrated and
  // fitted): the same curve approximated independently and more finely, so
  // that re-solving on it measures what the path's own error does to U(L)
  // (docs/solver.md#the-error-estimate). nullptr for paths in closed form
  // or built from exact data (lines, parallels, splines, expressions).
  [[nodiscard]] virtual std::unique_ptr<ContactPath> finerApproximation() const { return nullptr; }
};

// The Darboux vector d with dX/ds = d × X for X ∈ {t, u, n}:
//   d = τ_g t − κ_n u + κ_g n.
[[nodiscard]] Vec3 darbouxVector(const DarbouxSample& f);

// A number as describe() strings show it ("%g").
[[nodiscard]] std::string describeNumber(double v);

// A count of turns as describe() strings show it: "1 turn", "2.5 turns".
[[nodiscard]] std::string describeTurns(double turns);

// A unit vector perpendicular to n, chosen deterministically: horizontal
// (ẑ × n) when n is not vertical, else x̂. The default in-plane direction.
[[nodiscard]] Vec3 defaultTangentFor(const Vec3& n);

}  // namespace rollspin::geometry
