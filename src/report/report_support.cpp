#include "report/report_support.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <system_error>

#include "core/atomic_file.hpp"
#include "core/error.hpp"
#include "geometry/analytic_paths.hpp"
#include "kinematics/rolling_kinematics.hpp"
#include "spin/field.hpp"

namespace rollspin::report {

std::shared_ptr<const geometry::ContactPath> circle(double r, double turns) {
  auto plane = std::make_shared<const geometry::Plane>(geometry::Vec3::UnitZ());
  return std::make_shared<geometry::PlaneCirclePath>(plane, geometry::Vec3::Zero(), geometry::Vec3::UnitX(), r, turns,
                                                     true);
}

std::shared_ptr<const geometry::ContactPath> parallel(double r, bool outside, double theta) {
  auto sphere = std::make_shared<const geometry::Sphere>(r, outside ? geometry::Side::Outside : geometry::Side::Inside);
  return std::make_shared<geometry::SphereParallelPath>(sphere, theta, 1.0, true);
}

namespace {
std::vector<spin::Su2> runAt(const geometry::ContactPath& path, double R, spin::Method m, long long steps,
                             const std::vector<double>& s, spin::SolveStatus& status) {
  std::vector<spin::Su2> out(s.size());
  status =
      spin::Propagator(path, R, m, steps).run(s, [&](std::size_t j, double, const spin::Su2& q) { out[j] = q; }).status;
  return out;
}

double maxDistance(const std::vector<spin::Su2>& a, const std::vector<spin::Su2>& b) {
  double worst = 0.0;
  for (std::size_t j = 0; j < a.size(); ++j) worst = std::max(worst, spin::spinorDistance(a[j], b[j]));
  return worst;
}
}  // namespace

Reference makeReference(const geometry::ContactPath& path, double ballRadius, std::size_t samples,
                        long long kinematicSteps, spin::Method fineMethod) {
  Reference ref;
  ref.sampleS = spin::uniformSamples(path.length(), samples);
  ref.floor = kEpsilon * spin::integratedFieldStrength(path, ballRadius);
  spin::SolveStatus status{};
  if (path.hasConstantCurvatures()) {
    ref.samples = runAt(path, ballRadius, spin::Method::Exact, 0, ref.sampleS, status);
    ref.source = "closed form";
  } else {
    // magnus6 at h·(|ω| + |d|) ≈ 1/40 is near round-off on smooth paths;
    // doubling until two grids agree guards the rest.
    long long n = std::max<long long>(2000, std::llround(40.0 * spin::integratedStepBudget(path, ballRadius)));
    std::vector<spin::Su2> coarse = runAt(path, ballRadius, fineMethod, n, ref.sampleS, status);
    for (int k = 0; k < 4; ++k) {
      std::vector<spin::Su2> fine = runAt(path, ballRadius, fineMethod, 2 * n, ref.sampleS, status);
      ref.selfCheck = maxDistance(coarse, fine);
      coarse = std::move(fine);
      n *= 2;
      if (ref.selfCheck < std::max(1e-13, 10.0 * ref.floor)) break;
    }
    ref.samples = std::move(coarse);
    ref.source =
        fmt::format("{}, {} steps ({} against half as many)", spin::methodName(fineMethod), n, fmtNum(ref.selfCheck));
  }
  if (kinematicSteps > 0) {
    const Eigen::Matrix3d q = kinematics::RollingKinematics(path, ballRadius, {kinematicSteps, 0.0}).finalOrientation();
    const Eigen::Quaterniond kq(q);
    ref.kinematicCheck = spin::rotationDistance(ref.samples.back(), spin::Su2{kq.w(), kq.x(), kq.y(), kq.z()});
  }
  return ref;
}

RunResult measureRun(const geometry::ContactPath& path, double ballRadius, spin::Method method, long long steps,
                     double tolerance, const Reference& ref, bool timeIt, long long stepLimit) {
  RunResult r;
  spin::Propagator propagator(path, ballRadius, method, steps, tolerance);
  propagator.setStepLimit(stepLimit);
  // The spinor distance is blind to the norm; a raw-spinor method whose norm
  // has decayed (rk4 over 1e6 turns) would look exact. The error is the
  // larger of the orientation error and the loss of norm.
  auto errorOf = [](const spin::Su2& q, const spin::Su2& ref) {
    return std::max(spin::spinorDistance(q, ref), std::abs(q.norm() - 1.0));
  };
  double worst = 0.0;
  const spin::SolveStats st = propagator.run(ref.sampleS, [&](std::size_t j, double, const spin::Su2& q) {
    worst = std::max(worst, errorOf(q, ref.samples[j]));
  });
  r.status = st.status;
  r.steps = st.steps;
  r.rejected = st.rejectedSteps;
  r.unitarity = st.unitarityError;
  r.seconds = st.seconds;
  r.repeats = 1;
  if (!r.ok()) return r;
  r.finalError = errorOf(st.final, ref.samples.back());
  r.timelineError = std::max(worst, r.finalError);
  if (!std::isfinite(r.finalError) || !std::isfinite(r.timelineError)) {
    r.status = spin::SolveStatus::NonFinite;
    return r;
  }
  if (!timeIt) return r;
  // Warm-up (caches, branch predictors, page faults), then the median of
  // repeats; a slow run (> 50 ms) is timed three times, and one over 0.5 s
  // keeps the time of the run above (timing noise is small there, and a
  // report must finish).
  if (r.seconds > 0.5) return r;
  const double first = propagator.solveFinal().seconds;
  const int repeats = first > 0.05 ? 3 : std::clamp(static_cast<int>(0.02 / std::max(first, 1e-9)), 5, 25);
  std::vector<double> times;
  for (int k = 0; k < repeats; ++k) times.push_back(propagator.solveFinal().seconds);
  std::nth_element(times.begin(), times.begin() + repeats / 2, times.end());
  r.seconds = times[static_cast<std::size_t>(repeats / 2)];
  r.repeats = repeats;
  return r;
}

std::string failureWord(spin::SolveStatus status) {
  switch (status) {
    case spin::SolveStatus::Ok: return "";
    case spin::SolveStatus::NonFinite: return "diverged";
    case spin::SolveStatus::StepLimit: return "step limit";
    case spin::SolveStatus::StepSizeUnderflow: return "step underflow";
    case spin::SolveStatus::ExactNeedsConstantCurvature: return "n/a";
    case spin::SolveStatus::BadSteps:
    case spin::SolveStatus::BadTolerance: return "bad settings";
  }
  return "failed";
}

std::string fmtNum(double v) { return std::isfinite(v) ? fmt::format("{:.3g}", v) : std::string("—"); }

std::string fmtSeconds(double s) {
  if (!std::isfinite(s)) return "—";
  if (s < 1e-3) return fmt::format("{:.3g} µs", s * 1e6);
  if (s < 1.0) return fmt::format("{:.3g} ms", s * 1e3);
  return fmt::format("{:.3g} s", s);
}

std::string mdCell(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
  return out;
}

void writeFile(const std::filesystem::path& path, const std::string& text) {
  AtomicFile file(path);
  file.write(text);
  file.commit();
}

std::string gnuplotQuote(const std::filesystem::path& p) {
  std::string out = "'";
  for (char c : p.string()) out += (c == '\'') ? std::string("''") : std::string(1, c);
  return out + "'";
}

std::string runGnuplot(const std::filesystem::path& scriptPath, const std::string& script,
                       const std::filesystem::path& tempPng, const std::filesystem::path& finalPng) {
  writeFile(scriptPath, script);
  // gnuplot reads the script file; its messages go to a log next to it.
  const std::filesystem::path log = scriptPath.string() + ".log";
  auto shellQuote = [](const std::filesystem::path& p) {
    std::string out = "'";
    for (char c : p.string()) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
    return out + "'";
  };
  const std::string command = "gnuplot " + shellQuote(scriptPath) + " > " + shellQuote(log) + " 2>&1";
  const int rc = std::system(command.c_str());
  std::error_code ec;
  if (rc != 0 || !std::filesystem::exists(tempPng, ec) || std::filesystem::file_size(tempPng, ec) == 0) {
    std::filesystem::remove(tempPng, ec);
    return fmt::format("gnuplot failed (exit status {}; is gnuplot installed? see {})", rc, log.string());
  }
  std::filesystem::rename(tempPng, finalPng, ec);
  if (ec) return fmt::format("cannot rename {} to {}: {}", tempPng.string(), finalPng.string(), ec.message());
  std::filesystem::remove(log, ec);
  return "";
}

}  // namespace rollspin::report
