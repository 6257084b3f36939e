// A table of surface × curve cases for the tests, built straight from
// geometry (no scene file): every surface kind, both sides, with each curve
// family on it, at ball radii where the ball touches at one point.
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "geometry/contact_path.hpp"

namespace rollspin::test {

struct SurfaceCase {
  std::string name;
  std::function<std::unique_ptr<geometry::ContactPath>()> make;
  double R;
};

// Every surface × curve kind, at sizes where the ball touches at one point.
std::vector<SurfaceCase> allSurfaceCases();

}  // namespace rollspin::test
