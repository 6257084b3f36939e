#include "geometry/joined_path.hpp"

#include <algorithm>
#include <cassert>

namespace rollspin::geometry {

JoinedPath::JoinedPath(std::vector<std::unique_ptr<ContactPath>> pieces) : owned_(std::move(pieces)) {
  assert(!owned_.empty());
  for (const auto& piece : owned_) {
    assert(piece->length() > 0.0);
    pieces_.push_back({piece.get(), length_});
    length_ += piece->length();
  }
}

std::size_t JoinedPath::pieceAt(double s) const {
  // The last piece whose start is ≤ s: a join belongs to the piece after it.
  const auto it = std::upper_bound(pieces_.begin(), pieces_.end(), s,
                                   [](double x, const PathPiece& p) { return x < p.start; });
  return it == pieces_.begin() ? 0 : static_cast<std::size_t>(it - pieces_.begin()) - 1;
}

DarbouxSample JoinedPath::at(double s) const {
  const PathPiece& p = pieces_[pieceAt(s)];
  DarbouxSample f = p.path->at(std::clamp(s - p.start, 0.0, p.path->length()));
  f.s = s;
  return f;
}

Vec3 JoinedPath::point(double s) const {
  const PathPiece& p = pieces_[pieceAt(s)];
  return p.path->point(std::clamp(s - p.start, 0.0, p.path->length()));
}

Vec3 JoinedPath::normal(double s) const {
  const PathPiece& p = pieces_[pieceAt(s)];
  return p.path->normal(std::clamp(s - p.start, 0.0, p.path->length()));
}

bool JoinedPath::hasConstantCurvatures() const { return pieces_.size() == 1 && owned_[0]->hasConstantCurvatures(); }

std::vector<double> JoinedPath::breakpoints() const {
  std::vector<double> out;
  for (std::size_t k = 0; k < pieces_.size(); ++k) {
    if (k > 0) out.push_back(pieces_[k].start);
    for (double b : pieces_[k].path->breakpoints()) out.push_back(pieces_[k].start + b);
  }
  return out;
}

double JoinedPath::turns() const {
  double t = 0.0;
  for (const auto& p : owned_) t += p->turns();
  return t;
}

std::string JoinedPath::describe() const {
  std::string out = "storyboard of " + std::to_string(pieces_.size()) + (pieces_.size() == 1 ? " piece" : " pieces");
  for (std::size_t k = 0; k < pieces_.size(); ++k) out += (k ? "; " : ": ") + pieces_[k].path->describe();
  return out;
}

}  // namespace rollspin::geometry
