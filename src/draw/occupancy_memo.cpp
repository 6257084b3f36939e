#include "draw/occupancy_memo.hpp"

#include <bit>
#include <utility>

namespace rollspin::draw {

OccupancyMemo::OccupancyMemo(Projection project) : project_(std::move(project)) {}

Occupancy OccupancyMemo::operator()(const NdcWindow& window) {
  // Keyed by the exact bits of the window: a window the search computes
  // again the same way compares equal, any other is projected anew.
  const Key key{std::bit_cast<std::uint64_t>(window.x0), std::bit_cast<std::uint64_t>(window.x1),
                std::bit_cast<std::uint64_t>(window.y0), std::bit_cast<std::uint64_t>(window.y1)};
  auto it = seen_->find(key);
  if (it == seen_->end()) it = seen_->emplace(key, project_(window)).first;
  return it->second;
}

}  // namespace rollspin::draw
