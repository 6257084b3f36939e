// Shared by the reports: reference solutions (closed form, or a converged
// magnus6 cross-checked against the independent kinematics), one measured
// solver run (errors at samples, status, unitarity, median time), number
// formatting that never prints NaN as a number, files written atomically,
// and gnuplot driven with a generated script.
#pragma once

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "geometry/contact_path.hpp"
#include "spin/propagator.hpp"

namespace rollspin::report {

inline constexpr double kEpsilon = 2.220446049250313e-16;  // 2⁻⁵²

// The reports' test paths: a circle of radius r on the plane z = 0 (from
// (r, 0, 0), counter-clockwise), and the parallel at colatitude theta on a
// sphere of radius r, outside or inside, once round.
[[nodiscard]] std::shared_ptr<const geometry::ContactPath> circle(double r, double turns = 1.0);
[[nodiscard]] std::shared_ptr<const geometry::ContactPath> parallel(double r, bool outside, double theta);

struct Reference {
  std::vector<double> sampleS;
  std::vector<spin::Su2> samples;  // U at sampleS (the last is U(L))
  std::string source;              // "closed form" or "magnus6, N steps (±δ vs 2N)"
  double selfCheck = 0.0;          // |U_N − U_2N| for a converged reference (0 for closed form)
  double kinematicCheck = -1.0;    // SO(3) distance to the kinematic oracle (−1: not run)
  double floor = 0.0;              // ε ∫|B| ds
};

// Closed form when the path has constant curvatures, else magnus6 doubled
// until two grids agree to 1e-13 (or 4 doublings). kinematicSteps > 0 also
// runs the independent SO(3) oracle on the final orientation.
// fineMethod: magnus6, or frame4 where κ_g is piecewise constant (exact per
// piece, whatever the other curvatures).
[[nodiscard]] Reference makeReference(const geometry::ContactPath& path, double ballRadius, std::size_t samples,
                                      long long kinematicSteps, spin::Method fineMethod = spin::Method::Magnus6);

struct RunResult {
  spin::SolveStatus status = spin::SolveStatus::Ok;
  double finalError = 0.0;     // max(spinor distance, |‖U‖ − 1|) at L
  double timelineError = 0.0;  // max over the reference's samples
  double unitarity = 0.0;
  long long steps = 0;
  long long rejected = 0;
  double seconds = 0.0;  // median solver time (solveFinal), or the one run when > 0.5 s
  int repeats = 0;
  [[nodiscard]] bool ok() const { return status == spin::SolveStatus::Ok; }
};

// One timeline run for the errors, then (if it succeeded and timeIt) a
// warm-up and the median of repeats of the solver alone. stepLimit bounds
// an adaptive method's work.
[[nodiscard]] RunResult measureRun(const geometry::ContactPath& path, double ballRadius, spin::Method method,
                                   long long steps, double tolerance, const Reference& ref, bool timeIt = true,
                                   long long stepLimit = 50'000'000);

// "diverged", "step limit", ... for a failed status; "" when ok.
[[nodiscard]] std::string failureWord(spin::SolveStatus status);
// %.3g, or "—" for NaN/inf (never a number that is not one).
[[nodiscard]] std::string fmtNum(double v);
[[nodiscard]] std::string fmtSeconds(double seconds);
// Text for a Markdown table cell: '|' escaped so |B| does not split the cell.
[[nodiscard]] std::string mdCell(const std::string& text);

// Writes text to path via a temporary name and rename (core/atomic_file).
void writeFile(const std::filesystem::path& path, const std::string& text);

// Runs gnuplot on `script` (written next to the PNG as scriptPath); the
// script must write to `tempPng`, which is renamed to finalPng on success.
// Returns "" on success, else what went wrong (gnuplot missing, failed).
[[nodiscard]] std::string runGnuplot(const std::filesystem::path& scriptPath, const std::string& script,
                                     const std::filesystem::path& tempPng, const std::filesystem::path& finalPng);

// Quotes a path for a gnuplot string literal.
[[nodiscard]] std::string gnuplotQuote(const std::filesystem::path& p);

}  // namespace rollspin::report
