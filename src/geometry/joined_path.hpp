// JoinedPath — a storyboard's contact path: pieces played one after another,
// s running on through them. Piece k occupies [s_k, s_k + L_k) with
// s_1 = 0, s_{k+1} = s_k + L_k; at(s), point(s) and normal(s) are the piece's
// own at s − s_k (a join belongs to the piece that starts there; s = L to the
// last). The joins are breakpoints, so steppers and the kinematic oracle
// never straddle one. The pieces must meet (P_k(L_k) = P_{k+1}(0), checked by
// the caller); their tangents may differ (a corner: the ball changes
// direction without spinning, so its orientation is continuous there).
#pragma once

#include <memory>
#include <vector>

#include "geometry/contact_path.hpp"

namespace rollspin::geometry {

class JoinedPath final : public ContactPath {
 public:
  // At least one piece, each of positive length.
  explicit JoinedPath(std::vector<std::unique_ptr<ContactPath>> pieces);

  [[nodiscard]] double length() const override { return length_; }
  [[nodiscard]] DarbouxSample at(double s) const override;
  [[nodiscard]] Vec3 point(double s) const override;
  [[nodiscard]] Vec3 normal(double s) const override;
  // False as soon as there are two pieces: the curvatures jump at a join.
  // (The exact method still applies piece by piece when every piece has
  // constant curvatures: the propagator solves joined paths per piece.)
  [[nodiscard]] bool hasConstantCurvatures() const override;
  [[nodiscard]] std::vector<double> breakpoints() const override;
  [[nodiscard]] double turns() const override;
  [[nodiscard]] std::string describe() const override;
  [[nodiscard]] std::span<const PathPiece> pieces() const override { return pieces_; }
  // The pieces' finer approximations where they have one (geodesics), the
  // others borrowed from this path (which must outlive the result); nullptr
  // when no piece has one.
  [[nodiscard]] std::unique_ptr<ContactPath> finerApproximation() const override;

  // Index of the piece that holds s.
  [[nodiscard]] std::size_t pieceAt(double s) const;

 private:
  std::vector<std::unique_ptr<ContactPath>> owned_;
  std::vector<PathPiece> pieces_;
  double length_ = 0.0;
};

}  // namespace rollspin::geometry
