// rollspin's three reports, as a library that sees geometry, spin and the
// kinematic oracle (never TOML or GL):
//   errors  work-precision sweeps: for each scene and method, steps (or
//           tolerances) against the final and the max-over-timeline error
//           (spinor distance to a reference) and the solver's own time
//           (a warm-up, then the median of repeats);
//   stress  stiff and extreme cases × methods: error, unitarity drift, steps,
//           time, pass/fail against a stated bound; the Landau–Zener sweep on
//           a clothoid; the adiabatic (dynamic + geometric phase) split;
//   paper   every closed-form claim of Rojo & Bloch on a parameter grid
//           against the solver: agree / disagree, largest deviation, where.
// Each writes CSV, Markdown (and errors a PNG via gnuplot) into outDir.
// Round-off floor of a path: ε ∫|B| ds (ε = 2⁻⁵²).
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "geometry/contact_path.hpp"

namespace rollspin::report {

struct ReportScene {
  std::string name;         // file-name safe
  std::string description;  // one line for the summary
  std::shared_ptr<const geometry::ContactPath> path;
  double ballRadius = 1.0;
};

struct ReportOptions {
  std::filesystem::path outDir = "output/report";
  // Progress lines for the user (the report itself never prints).
  std::function<void(const std::string&)> progress;
  // report errors: the magnus4-vs-rk45 lollipop section (docs/solver.md#reports); off for a
  // report on the user's own scenes, where it would be beside the point.
  bool lollipopSpeedRatio = true;
};

struct ReportOutcome {
  std::vector<std::filesystem::path> written;
  std::string headline;   // a few lines for the terminal
  std::string plotError;  // non-empty when the plot could not be drawn
};

// plane (lollipop), sphere outside and inside, a torus knot (a curved surface
// with varying κ_n, κ_g, τ_g), a clothoid (varying κ_g on a plane) and a stiff
// lollipop (R/r = 1e-2, 100 ball turns per circuit).
[[nodiscard]] std::vector<ReportScene> defaultErrorScenes();

// Throw rollspin::Error (Runtime) when an output cannot be written.
[[nodiscard]] ReportOutcome errorsReport(const std::vector<ReportScene>& scenes, const ReportOptions& options);
[[nodiscard]] ReportOutcome stressReport(const ReportOptions& options);
[[nodiscard]] ReportOutcome paperReport(const ReportOptions& options);

}  // namespace rollspin::report
