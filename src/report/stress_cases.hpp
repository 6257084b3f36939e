// The stress suite's cases (shared by `rollspin report stress` and the
// tests): stiff and extreme paths, each with the grid given to fixed-step
// methods, the tolerance given to adaptive ones, and the bound a run must
// meet, max(1e-8, 10 ε ∫|B| ds) — ten times the round-off floor, or 1e-8.
// Also the Landau–Zener transition probability on a clothoid,
//   P = (1 + n·R(U) n)/2  (the body point that started on top, still on top)
// against P_LZ = exp(−π/(2 α R²)) for the sweep κ_g = α s, s ∈ [−S, S].
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geometry/contact_path.hpp"
#include "spin/propagator.hpp"

namespace rollspin::report {

struct StressCase {
  std::string name;  // short, for tables
  std::string what;  // one line: why it is hard
  std::shared_ptr<const geometry::ContactPath> path;
  double ballRadius = 1.0;
  long long fixedSteps = 64;                           // for the fixed-step methods
  std::string grid;                                    // how fixedSteps was chosen, for the table
  double tolerance = 1e-9;                             // for the adaptive methods
  spin::Method referenceMethod = spin::Method::Exact;  // Exact: closed form; else converged fine grid
  bool stiff = false;                                  // R/r ≤ 1e-3: the "stiff plane and sphere" cases
};

[[nodiscard]] std::vector<StressCase> stressCases();

// max(1e-8, 10 ε ∫|B| ds).
[[nodiscard]] double stressBound(const StressCase& c);

// P for the final spinor of a sweep on a horizontal plane (n = ẑ).
[[nodiscard]] double stayProbability(const spin::Su2& u);
[[nodiscard]] double landauZener(double curvatureRate, double ballRadius);

}  // namespace rollspin::report
