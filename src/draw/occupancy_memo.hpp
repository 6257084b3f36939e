// A window's occupancy projected once: layoutView's search asks for the
// same NdcWindow again (each of its passes starts over from the whole
// view), and one projection samples the whole clip (48 to 480 cameras).
// occupancy(window) = project(window) for the first call with that window;
// later calls return a copy of that first result. Plain data, no GL.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>

#include "draw/clip_layout.hpp"

namespace rollspin::draw {

class OccupancyMemo {
 public:
  using Projection = std::function<Occupancy(const NdcWindow&)>;
  explicit OccupancyMemo(Projection project);
  // The occupancy for `window`, projected on the first call with it.
  Occupancy operator()(const NdcWindow& window);
  // How many windows have been projected (each once).
  [[nodiscard]] std::size_t projections() const { return seen_->size(); }

 private:
  using Key = std::array<std::uint64_t, 4>;  // the window's bits
  Projection project_;
  // Shared: layoutView takes a std::function, which copies its callable.
  std::shared_ptr<std::map<Key, Occupancy>> seen_ = std::make_shared<std::map<Key, Occupancy>>();
};

}  // namespace rollspin::draw
