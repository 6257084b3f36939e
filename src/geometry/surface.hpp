// Surface — the rigid surface the ball rolls on, as a parametrised surface
//   x(u, v),  partial derivatives x_u, x_v, x_uu, x_uv, x_vv,
//   unit normal on the ball's side  n = ς (x_u × x_v)/|x_u × x_v|  (ς = ±1),
// first fundamental form  E = x_u·x_u, F = x_u·x_v, G = x_v·x_v and second
//   L = x_uu·n, M = x_uv·n, N = x_vv·n  (signed towards the ball: a bowl seen
// from inside has positive curvature), from which κ_n, κ_g and τ_g of any curve
// on it follow (see surface_curve.hpp). The independent kinematic oracle reads
// only the point and the normal, never the curvatures.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>
#include <optional>
#include <string>

namespace rollspin::geometry {

using Vec3 = Eigen::Vector3d;

using Vec2 = Eigen::Vector2d;

// x(u, v) with its first and second partial derivatives.
struct SurfaceJet {
  Vec3 x = Vec3::Zero();
  Vec3 xu = Vec3::UnitX(), xv = Vec3::UnitY();
  Vec3 xuu = Vec3::Zero(), xuv = Vec3::Zero(), xvv = Vec3::Zero();

  // Every value and derivative is finite (a formula such as sqrt(-1 - x²) is not).
  [[nodiscard]] bool allFinite() const {
    return x.allFinite() && xu.allFinite() && xv.allFinite() && xuu.allFinite() && xuv.allFinite() && xvv.allFinite();
  }
};

// The parameter rectangle (bounds may be infinite; open at finite bounds,
// where the parametrisation degenerates, e.g. a sphere's poles). A period
// > 0 says the coordinate is an angle: x(u + uPeriod, v) = x(u, v), so a box
// wider than one period covers the surface twice.
struct ParameterDomain {
  double uMin = -std::numeric_limits<double>::infinity(), uMax = std::numeric_limits<double>::infinity();
  double vMin = -std::numeric_limits<double>::infinity(), vMax = std::numeric_limits<double>::infinity();
  double uPeriod = 0.0, vPeriod = 0.0;
  [[nodiscard]] bool contains(const Vec2& uv) const {
    return uv.x() > uMin && uv.x() < uMax && uv.y() > vMin && uv.y() < vMax;
  }
};

// Local shape at one parameter point: fundamental forms w.r.t. the ball-side
// normal, mean curvature H = (EN − 2FM + GL) / 2(EG − F²), Gaussian curvature
// K = (LN − M²)/(EG − F²), principal curvatures k1 ≥ k2 (H ± √(H² − K)).
struct SurfaceShape {
  Vec3 point = Vec3::Zero(), normal = Vec3::UnitZ();
  double E = 1.0, F = 0.0, G = 1.0, L = 0.0, M = 0.0, N = 0.0;
  double meanCurvature = 0.0, gaussCurvature = 0.0;
  double maxCurvature = 0.0, minCurvature = 0.0;  // k1 ≥ k2; k > 0 curves towards the ball
};

// How a picture shows the surface, for draw/ (no GL here): which mesh it
// gets, what is "up" for the camera and the light, and whether a cap facing
// the eye is cut away. Every surface answers (Surface::look); draw/ never
// asks which class it is.
struct SurfaceLook {
  enum class Mesh {
    Chart,   // x(u, v) over the parameter box the path visits, padded by ~3R
    Board,   // a flat square board under the path (a plane)
    Sphere,  // the whole sphere of radius `radius` about the origin
  };
  Mesh mesh = Mesh::Chart;
  Vec3 up = Vec3::UnitZ();        // Board: the plane's normal (walls and ceilings are framed and lit by it)
  bool orientedByUp = false;      // the camera's default angles and the key light follow `up`
  double radius = 0.0;            // Sphere: r
  bool cutAwayTowardEye = false;  // the ball rolls inside: the cap facing the eye is cut away, the whole surface framed
  bool canHideBall = true;        // the surface can stand between the eye and the ball (a board under it cannot)
};

class Surface {
 public:
  virtual ~Surface() = default;
  // Unit normal at a point on the surface, pointing to the ball's side.
  [[nodiscard]] virtual Vec3 normalAt(const Vec3& point) const = 0;
  // Signed distance of a point from the surface (0 on it); used to check
  // that a path stays on the surface.
  [[nodiscard]] virtual double distance(const Vec3& point) const = 0;
  [[nodiscard]] virtual std::string describe() const = 0;

  // --- parametric interface ---
  // x(u, v) and its derivatives up to second order (exact: no differencing).
  [[nodiscard]] virtual SurfaceJet jet(const Vec2& uv) const = 0;
  // x(u, v).
  [[nodiscard]] virtual Vec3 position(const Vec2& uv) const { return jet(uv).x; }
  // ς = +1 when the ball is on the side of x_u × x_v, −1 otherwise.
  [[nodiscard]] virtual double orientation() const = 0;
  // Unit normal on the ball's side at (u, v).
  [[nodiscard]] Vec3 normal(const Vec2& uv) const;
  [[nodiscard]] virtual ParameterDomain domain() const { return {}; }
  // Parameters of the surface point nearest `point` (exact for points on the
  // surface); nullopt where the chart has no inverse (e.g. a sphere's pole).
  [[nodiscard]] virtual std::optional<Vec2> parametersOf(const Vec3& point) const = 0;
  // What u and v are, for messages and documentation.
  [[nodiscard]] virtual std::string parameterNames() const = 0;
  // Where a geodesic starts when the scene names no point: x(0, 0) unless the
  // chart degenerates there.
  [[nodiscard]] virtual Vec3 defaultStart() const { return position(Vec2(0.0, 0.0)); }
  // How a picture shows it (mesh, up, cut-away).
  [[nodiscard]] virtual SurfaceLook look() const { return {}; }
};

// Fundamental forms, H, K and principal curvatures at (u, v).
[[nodiscard]] SurfaceShape shapeAt(const Surface& surface, const Vec2& uv);
[[nodiscard]] SurfaceShape shapeFromJet(const SurfaceJet& j, double orientation);

// Plane through the origin with unit normal `normal` (the ball's side).
class Plane final : public Surface {
 public:
  explicit Plane(const Vec3& normal);
  [[nodiscard]] Vec3 normalAt(const Vec3& point) const override;
  [[nodiscard]] double distance(const Vec3& point) const override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] const Vec3& normal() const { return normal_; }
  // x(u, v) = u e1 + v e2 with e1 = defaultTangentFor(n), e2 = n × e1.
  [[nodiscard]] SurfaceJet jet(const Vec2& uv) const override;
  [[nodiscard]] double orientation() const override { return 1.0; }
  [[nodiscard]] std::optional<Vec2> parametersOf(const Vec3& point) const override;
  [[nodiscard]] std::string parameterNames() const override;
  [[nodiscard]] const Vec3& axisU() const { return e1_; }
  [[nodiscard]] const Vec3& axisV() const { return e2_; }
  [[nodiscard]] SurfaceLook look() const override;

 private:
  Vec3 normal_, e1_, e2_;
};

enum class Side { Outside, Inside };

// Sphere of radius r centred at the origin; the ball rolls on its outside
// (n = P/r) or inside (n = −P/r). Parameters: colatitude θ ∈ (0, π) and
// azimuth φ (radians): x = r (sin θ cos φ, sin θ sin φ, cos θ).
class Sphere final : public Surface {
 public:
  Sphere(double radius, Side side);
  [[nodiscard]] Vec3 normalAt(const Vec3& point) const override;
  [[nodiscard]] double distance(const Vec3& point) const override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] double radius() const { return radius_; }
  [[nodiscard]] Side side() const { return side_; }
  // +1 outside, −1 inside: n = sideSign · P / r.
  [[nodiscard]] double sideSign() const { return side_ == Side::Outside ? 1.0 : -1.0; }
  [[nodiscard]] SurfaceJet jet(const Vec2& uv) const override;
  [[nodiscard]] double orientation() const override { return sideSign(); }
  [[nodiscard]] ParameterDomain domain() const override;
  [[nodiscard]] std::optional<Vec2> parametersOf(const Vec3& point) const override;
  [[nodiscard]] std::string parameterNames() const override;
  // r (sin 60°, 0, cos 60°): the pole (θ = 0) has no chart.
  [[nodiscard]] Vec3 defaultStart() const override;
  [[nodiscard]] SurfaceLook look() const override;

 private:
  double radius_;
  Side side_;
};

}  // namespace rollspin::geometry
