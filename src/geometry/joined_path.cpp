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
  const auto it =
      std::upper_bound(pieces_.begin(), pieces_.end(), s, [](double x, const PathPiece& p) { return x < p.start; });
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

namespace {
// A piece of another path, borrowed for a finer approximation that keeps it.
class BorrowedPath final : public ContactPath {
 public:
  explicit BorrowedPath(const ContactPath& path) : path_(path) {}
  [[nodiscard]] double length() const override { return path_.length(); }
  [[nodiscard]] DarbouxSample at(double s) const override { return path_.at(s); }
  [[nodiscard]] Vec3 point(double s) const override { return path_.point(s); }
  [[nodiscard]] Vec3 normal(double s) const override { return path_.normal(s); }
  [[nodiscard]] bool hasConstantCurvatures() const override { return path_.hasConstantCurvatures(); }
  [[nodiscard]] std::vector<double> breakpoints() const override { return path_.breakpoints(); }
  [[nodiscard]] double turns() const override { return path_.turns(); }
  [[nodiscard]] std::string describe() const override { return path_.describe(); }

 private:
  const ContactPath& path_;
};
}  // namespace

std::unique_ptr<ContactPath> JoinedPath::finerApproximation() const {
  std::vector<std::unique_ptr<ContactPath>> pieces;
  bool anyFiner = false;
  for (const auto& piece : owned_) {
    std::unique_ptr<ContactPath> finer = piece->finerApproximation();
    anyFiner = anyFiner || finer != nullptr;
    pieces.push_back(finer ? std::move(finer) : std::make_unique<BorrowedPath>(*piece));
  }
  if (!anyFiner) return nullptr;
  return std::make_unique<JoinedPath>(std::move(pieces));
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
