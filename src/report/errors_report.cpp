// `rollspin report errors`: work-precision sweeps. Each fixed-step method
// runs on grids doubling from h·(|ω| + |d|) ≈ 4 until its error reaches
// round-off, stops improving, or one solve takes more than 50 ms; each
// adaptive method runs at tolerances 1e-2 … 1e-14 under the same rules.
#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <numbers>

#include "core/error.hpp"
#include "geometry/analytic_paths.hpp"
#include "geometry/clothoid_path.hpp"
#include "geometry/joined_path.hpp"
#include "geometry/surface_curve.hpp"
#include "geometry/surface_paths.hpp"
#include "geometry/surfaces.hpp"
#include "report/report.hpp"
#include "report/report_support.hpp"
#include "spin/field.hpp"

namespace rollspin::report {

namespace {
using geometry::Vec3;
using std::numbers::pi;
constexpr double kTimeCap = 0.05;     // s per solve: the sweep's last point
constexpr std::size_t kSamples = 65;  // timeline samples for the max error
constexpr double kTargets[] = {1e-6, 1e-9, 1e-12};

struct Point {
  std::string scene;
  spin::Method method;
  long long steps = 0;
  double tolerance = 0.0;
  RunResult run;
};

std::vector<Point> sweep(const ReportScene& sc, spin::Method m, const Reference& ref) {
  std::vector<Point> points;
  auto record = [&](long long steps, double tol) {
    Point p{sc.name, m, steps, tol, measureRun(*sc.path, sc.ballRadius, m, steps, tol, ref, true, 20'000'000)};
    points.push_back(p);
    return p.run;
  };
  if (m == spin::Method::Exact) {
    if (sc.path->hasConstantCurvatures()) record(0, 0.0);
    return points;
  }
  auto done = [&](const RunResult& r, double previousError) {
    if (!r.ok()) return false;  // a diverged coarse grid: try finer
    if (r.seconds > kTimeCap || r.timelineError < 1e-15) return true;
    return previousError < 1e-9 && r.timelineError > 0.5 * previousError;  // at the floor
  };
  double previous = INFINITY;
  if (spin::isAdaptive(m)) {
    for (int k = 2; k <= 14; ++k) {
      const RunResult r = record(0, std::pow(10.0, -k));
      if (done(r, previous)) break;
      if (r.ok()) previous = r.timelineError;
    }
    return points;
  }
  const double budget = spin::integratedStepBudget(*sc.path, sc.ballRadius);
  for (long long n = std::max<long long>(4, std::llround(budget / 4.0)); n <= (1LL << 25); n *= 2) {
    const RunResult r = record(n, 0.0);
    if (done(r, previous)) break;
    if (r.ok()) previous = r.timelineError;
  }
  return points;
}

// The number docs/solver.md#reports quotes: magnus4 against rk45 at 1e-11 (final orientation) on
// one lollipop revolution (R = 1, r = 3), both timed here in the same run.
struct SpeedRatio {
  long long magnusSteps = 0;
  double rkTolerance = 0.0;
  long long rkSteps = 0;
  double magnusError = 0.0, rkError = 0.0;
  double magnusSeconds = 0.0, rkSeconds = 0.0;
};

double medianOf(const spin::Propagator& p, int repeats) {
  for (int k = 0; k < 20; ++k) (void)p.solveFinal();  // warm-up
  std::vector<double> t;
  for (int k = 0; k < repeats; ++k) t.push_back(p.solveFinal().seconds);
  std::nth_element(t.begin(), t.begin() + repeats / 2, t.end());
  return t[static_cast<std::size_t>(repeats / 2)];
}

SpeedRatio magnus4VersusRk45() {
  auto plane = std::make_shared<const geometry::Plane>(Vec3::UnitZ());
  const geometry::PlaneCirclePath path(plane, Vec3::Zero(), Vec3::UnitX(), 3.0, 1.0, true);
  const spin::Su2 exact = spin::Propagator(path, 1.0, spin::Method::Exact, 0).solveFinal().final;
  SpeedRatio r;
  for (long long n = 64; n < (1 << 22); n += 64) {
    r.magnusError =
        spin::spinorDistance(spin::Propagator(path, 1.0, spin::Method::Magnus4, n).solveFinal().final, exact);
    if (r.magnusError <= 1e-11) {
      r.magnusSteps = n;
      break;
    }
  }
  for (int k = 0; k < 64; ++k) {
    const double tol = 1e-8 * std::pow(10.0, -k / 8.0);
    const spin::SolveStats st = spin::Propagator(path, 1.0, spin::Method::Rk45, 0, tol).solveFinal();
    r.rkError = spin::spinorDistance(st.final, exact);
    if (st.status == spin::SolveStatus::Ok && r.rkError <= 1e-11) {
      r.rkTolerance = tol;
      r.rkSteps = st.steps;
      break;
    }
  }
  r.magnusSeconds = medianOf(spin::Propagator(path, 1.0, spin::Method::Magnus4, r.magnusSteps), 201);
  r.rkSeconds = medianOf(spin::Propagator(path, 1.0, spin::Method::Rk45, 0, r.rkTolerance), 201);
  return r;
}

std::string methodList() {
  std::string s;
  for (spin::Method m : spin::allMethods()) s += (s.empty() ? "" : ", ") + std::string(spin::methodName(m));
  return s;
}
// The --set options that reproduce a run of the report from the command line.
std::string commandLineSettings(const Point& p) {
  const std::string method = fmt::format("--set solver.method={}", spin::methodName(p.method));
  if (p.method == spin::Method::Exact) return method;
  if (spin::isAdaptive(p.method)) return fmt::format("{} --set solver.tolerance={:.0e}", method, p.tolerance);
  return fmt::format("{} --set solver.steps={}", method, p.steps);
}

}  // namespace

std::vector<ReportScene> defaultErrorScenes() {
  using geometry::Vec3;
  std::vector<ReportScene> scenes;
  auto plane = std::make_shared<const geometry::Plane>(Vec3::UnitZ());
  scenes.push_back({"lollipop", "plane, circle r = 3, R = 1, one circuit (constant curvatures: closed form)",
                    std::make_shared<geometry::PlaneCirclePath>(plane, Vec3::Zero(), Vec3::UnitX(), 3.0, 1.0, true),
                    1.0});
  scenes.push_back({"sphere-outside", "outside a sphere r = 3, parallel at 60°, R = 1, one circuit",
                    std::make_shared<geometry::SphereParallelPath>(
                        std::make_shared<const geometry::Sphere>(3.0, geometry::Side::Outside), pi / 3, 1.0, true),
                    1.0});
  scenes.push_back({"sphere-inside", "inside a sphere r = 3, parallel at 60°, R = 1, one circuit",
                    std::make_shared<geometry::SphereParallelPath>(
                        std::make_shared<const geometry::Sphere>(3.0, geometry::Side::Inside), pi / 3, 1.0, true),
                    1.0});
  {
    // A (2, 3) torus knot: κ_n, κ_g and τ_g all vary (a curved surface
    // without a closed form).
    auto torus = std::make_shared<const geometry::Torus>(3.0, 1.0, geometry::Side::Outside);
    auto curve = std::make_shared<geometry::FunctionUvCurve>(
        [](const geometry::Jet& t) {
          return std::array<geometry::Jet, 2>{2.0 * t, 3.0 * t};
        },
        0.0, 2.0 * pi, "(2, 3) torus knot");
    scenes.push_back(
        {"torus-knot", "outside a torus (A = 3, a = 1) along a (2, 3) torus knot, R = 0.3",
         std::make_shared<geometry::SurfaceCurvePath>(torus, curve, geometry::SurfaceCurveOptions{false, 1.0}), 0.3});
  }
  scenes.push_back(
      {"clothoid", "plane, clothoid κ_g = s − 10 on [0, 20] (a Landau–Zener sweep), R = 1",
       std::shared_ptr<const geometry::ContactPath>(geometry::PlaneClothoidPath::symmetricSweep(1.0, 20.0)), 1.0});
  scenes.push_back({"stiff-lollipop", "plane, circle r = 1, R = 0.01: 100 ball turns per circuit (stiff)",
                    std::make_shared<geometry::PlaneCirclePath>(plane, Vec3::Zero(), Vec3::UnitX(), 1.0, 1.0, true),
                    0.01});
  {
    // A polygon drawn the natural way: five points on a tilted plane with
    // corner arcs of radius 0.004 (R = 0.88): each corner turns the frame
    // through its whole angle in a length of a few thousandths.
    auto tilted = std::make_shared<const geometry::Plane>(Vec3(0.3, -0.2, 1.0).normalized());
    const std::vector<geometry::Vec2> corners{{0.0, 0.0}, {3.0, 0.5}, {3.5, 3.0}, {0.5, 4.0}, {-1.0, 2.0}};
    scenes.push_back({"polyline-corners",
                      "tilted plane, polyline through 5 points, corner radius 0.004, R = 0.88 (tight corners)",
                      std::shared_ptr<const geometry::ContactPath>(
                          geometry::pointsPath(tilted, corners, false, geometry::PointsInterpolation::Polyline, 0.004)),
                      0.88});
  }
  {
    // A curved storyboard: on the paraboloid z = (x² + y²)/4, half a
    // parallel of radius 1, a geodesic on from its end, then a polyline with
    // corner radius 0.05 from the geodesic's end.
    auto paraboloid = geometry::HeightField::quadric(2.0, 2.0, false, true);
    std::vector<std::unique_ptr<geometry::ContactPath>> pieces;
    pieces.push_back(geometry::heightFieldParallel(paraboloid, 1.0, 0.5, true));
    const geometry::DarbouxSample end = pieces.back()->at(pieces.back()->length());
    auto geodesic = geometry::geodesicPath(paraboloid, geometry::Vec2(end.point.x(), end.point.y()), end.tangent, 1.5);
    const geometry::Vec2 from = geodesic->uvAt(geodesic->length());
    const geometry::Vec2 along = geodesic->curve().at(geodesic->parameterAt(geodesic->length())).d1.normalized();
    const geometry::Vec2 left(-along.y(), along.x());
    pieces.push_back(std::move(geodesic));
    pieces.push_back(geometry::pointsPath(paraboloid,
                                          {from, from + along, from + along + 0.8 * left, from + 1.6 * left}, false,
                                          geometry::PointsInterpolation::Polyline, 0.05));
    scenes.push_back({"paraboloid-storyboard",
                      "paraboloid z = (x² + y²)/4: half a parallel ρ = 1, a geodesic, a polyline with corner radius "
                      "0.05, R = 0.5",
                      std::make_shared<geometry::JoinedPath>(std::move(pieces)), 0.5});
  }
  return scenes;
}

namespace {

// ---- CSV ----
// The a posteriori estimate each run would print (spin::estimateError),
// beside its true final error: the worst ratio per scene goes in the summary
// (worstUnder, one per scene).
std::string errorsCsv(const std::vector<ReportScene>& scenes, const std::vector<Point>& all,
                      const std::vector<Reference>& refs, std::vector<double>& worstUnder) {
  std::string csv =
      "scene,method,steps_requested,tolerance,status,steps,rejected,final_error,timeline_error,unitarity_error,"
      "seconds,repeats,roundoff_floor,error_estimate\n";
  for (const Point& p : all) {
    const std::size_t si = static_cast<std::size_t>(
        std::find_if(scenes.begin(), scenes.end(), [&](const ReportScene& s) { return s.name == p.scene; }) -
        scenes.begin());
    const RunResult& r = p.run;
    std::string estimate;
    if (r.ok()) {
      spin::Propagator again(*scenes[si].path, scenes[si].ballRadius, p.method, p.steps, p.tolerance);
      again.setStepLimit(20'000'000);
      spin::SolveStats st = again.solveFinal();
      if (st.status == spin::SolveStatus::Ok) {
        spin::estimateError(*scenes[si].path, scenes[si].ballRadius, p.method, p.steps, p.tolerance, st);
        estimate = fmt::format("{:.3e}", st.errorEstimate);
        worstUnder[si] = std::max(worstUnder[si], (r.finalError - 1e-13) / std::max(st.errorEstimate, 1e-300));
      }
    }
    csv += fmt::format("{},{},{},{},{},{},{},{},{},{},{},{},{:.3e},{}\n", p.scene, spin::methodName(p.method), p.steps,
                       p.tolerance > 0 ? fmt::format("{:.0e}", p.tolerance) : "", r.ok() ? "ok" : failureWord(r.status),
                       r.steps, r.rejected, r.ok() ? fmt::format("{:.3e}", r.finalError) : "",
                       r.ok() ? fmt::format("{:.3e}", r.timelineError) : "", fmt::format("{:.2e}", r.unitarity),
                       r.ok() ? fmt::format("{:.4e}", r.seconds) : "", r.repeats, refs[si].floor, estimate);
  }
  return csv;
}

// ---- plot: one panel per scene, one line per method, the floor dashed ----
void writeErrorsPlot(const std::vector<ReportScene>& scenes, const std::vector<Point>& all,
                     const std::vector<Reference>& refs, const std::filesystem::path& outDir, ReportOutcome& outcome) {
  std::string data, plots;
  int block = 0;
  const auto methods = spin::allMethods();
  for (std::size_t si = 0; si < scenes.size(); ++si) {
    std::vector<std::string> curves;
    for (std::size_t mi = 0; mi < methods.size(); ++mi) {
      std::string rows;
      for (const Point& p : all)
        if (p.scene == scenes[si].name && p.method == methods[mi] && p.run.ok())
          rows += fmt::format("{:.6e} {:.6e}\n", p.run.seconds, std::max(p.run.timelineError, 1e-17));
      if (rows.empty()) continue;
      data += rows + "\n\n";
      curves.push_back(fmt::format("DATA index {} using 1:2 with linespoints lw 1.5 pt {} ps 0.8 lc {} title '{}'",
                                   block++, static_cast<int>(mi) + 4, static_cast<int>(mi) + 1,
                                   spin::methodName(methods[mi])));
    }
    curves.push_back(
        fmt::format("{:.6e} with lines dt 2 lw 2 lc rgb 'black' title 'round-off floor ε∫|B|ds'", refs[si].floor));
    plots += fmt::format("set title '{}'\nplot ", scenes[si].name);
    for (std::size_t k = 0; k < curves.size(); ++k) plots += (k ? ", \\\n     " : "") + curves[k];
    plots += "\n";
  }
  const std::filesystem::path dataPath = outDir / "errors_plot.dat";
  writeFile(dataPath, data);
  outcome.written.push_back(dataPath);
  const std::filesystem::path png = outDir / "errors.png";
  const std::filesystem::path tempPng = outDir / ".errors.png.tmp";
  const int cols = scenes.size() > 4 ? 3 : static_cast<int>(std::min<std::size_t>(2, scenes.size()));
  const int rowsN =
      static_cast<int>((scenes.size() + static_cast<std::size_t>(cols) - 1) / static_cast<std::size_t>(cols));
  std::string script = fmt::format(
      "# Generated by `rollspin report errors`: error against solver time, one panel per scene.\n"
      "set encoding utf8\nset terminal pngcairo size {},{} font 'DejaVu Sans,10'\n"
      "set output {}\n"
      "DATA = {}\n"
      "set logscale xy\n"
      "set format x '10^{{%L}}'\nset format y '10^{{%L}}'\n"
      "set yrange [1e-17:10]\n"
      "set grid\n"
      "set xlabel 'solver time (s, median)'\nset ylabel 'max error along the timeline (rad)'\n"
      // The legend beside each panel, not on it: inside, it covered the
      // stiff lollipop's curves.
      "set key outside right center font ',8' spacing 0.9\n"
      "set multiplot layout {},{} title 'rollspin: error against run time (lower left is better)'\n",
      760 * cols, 440 * rowsN, gnuplotQuote(tempPng), gnuplotQuote(dataPath), rowsN, cols);
  script += plots + "unset multiplot\n";
  outcome.plotError = runGnuplot(outDir / "errors.gp", script, tempPng, png);
  outcome.written.push_back(outDir / "errors.gp");
  if (outcome.plotError.empty()) outcome.written.push_back(png);
}

// A run's settings as the summary table shows them.
std::string runSettingsCell(const Point* p) {
  if (!p) return std::string("—");
  if (p->method == spin::Method::Exact) return std::string("closed form");
  if (spin::isAdaptive(p->method)) return fmt::format("tol {:.0e} ({} steps)", p->tolerance, p->run.steps);
  return fmt::format("{} steps", p->steps);
}

// ---- Markdown: one section per scene, the fastest run for each target ----
// tightest: the last (tightest) target with advice, for the headline.
std::string errorsSceneSection(const ReportScene& sc, const Reference& ref, const std::vector<Point>& all,
                               double worstUnder, std::string& tightest) {
  std::string md = fmt::format("## {}\n\n{}. Reference: {}", sc.name, sc.description, ref.source);
  if (ref.kinematicCheck >= 0) md += fmt::format("; independent kinematics agrees to {}", fmtNum(ref.kinematicCheck));
  md += fmt::format(
      ". Round-off floor ε∫|B|ds = {}. Error estimate (`error_estimate` in the CSV: the "
      "difference to the same method at half the steps, or 32× the tolerance): worst (final error − "
      "1e-13) / estimate over the sweep {:.2g} (the tests require ≤ 3 on resolved grids; the "
      "sweep's first, grossly coarse grids may alias).\n\n",
      fmtNum(ref.floor), worstUnder);
  md +=
      "| target | fastest | time | error | settings | fastest stepping method | time | to use it |\n"
      "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (double target : kTargets) {
    const Point* best = nullptr;
    const Point* bestStepping = nullptr;
    for (const Point& p : all) {
      if (p.scene != sc.name || !p.run.ok() || p.run.timelineError > target) continue;
      if (!best || p.run.seconds < best->run.seconds) best = &p;
      if (p.method != spin::Method::Exact && (!bestStepping || p.run.seconds < bestStepping->run.seconds))
        bestStepping = &p;
    }
    // What to type for the fastest run.
    const Point* advice = best;
    const std::string line = advice ? commandLineSettings(*advice) : "";
    if (advice)
      tightest = fmt::format("{}: {:.0e} in {} with {}", sc.name, target, fmtSeconds(advice->run.seconds), line);
    md += fmt::format(
        "| {:.0e} | {} | {} | {} | {} | {} | {} | {} |\n", target,
        best ? std::string(spin::methodName(best->method)) : "none reached it",
        best ? fmtSeconds(best->run.seconds) : "—", best ? fmtNum(best->run.timelineError) : "—", runSettingsCell(best),
        bestStepping ? fmt::format("{} ({})", spin::methodName(bestStepping->method), runSettingsCell(bestStepping))
                     : "none reached it",
        bestStepping ? fmtSeconds(bestStepping->run.seconds) : "—", advice ? "`" + line + "`" : "—");
  }
  std::string failed;
  for (const Point& p : all)
    if (p.scene == sc.name && !p.run.ok() && p.run.status != spin::SolveStatus::ExactNeedsConstantCurvature)
      failed += fmt::format(" {} at {} ({});", spin::methodName(p.method),
                            p.tolerance > 0 ? fmt::format("tol {:.0e}", p.tolerance) : fmt::format("{} steps", p.steps),
                            failureWord(p.run.status));
  if (!failed.empty()) md += "\nFailed runs (not plotted):" + failed + "\n";
  md += "\n";
  return md;
}

std::string speedRatioSection(const SpeedRatio& ratio) {
  return fmt::format(
      "## magnus4 against rk45 at 1e-11, one lollipop revolution (R = 1, r = 3)\n\n"
      "| method | settings | final error | time (median of 201) |\n| --- | --- | --- | --- |\n"
      "| magnus4 | {} steps (smallest multiple of 64 reaching 1e-11) | {} | {} |\n"
      "| rk45 | tolerance {:.3g} ({} steps; largest of 1e-8·10^(−k/8) reaching 1e-11) | {} | {} |\n\n"
      "rk45 / magnus4 time ratio: **{:.1f}**.\n",
      ratio.magnusSteps, fmtNum(ratio.magnusError), fmtSeconds(ratio.magnusSeconds), ratio.rkTolerance, ratio.rkSteps,
      fmtNum(ratio.rkError), fmtSeconds(ratio.rkSeconds), ratio.rkSeconds / ratio.magnusSeconds);
}
}  // namespace

ReportOutcome errorsReport(const std::vector<ReportScene>& scenes, const ReportOptions& options) {
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto say = [&](const std::string& line) {
    if (options.progress) options.progress(line);
  };
  std::filesystem::create_directories(options.outDir);
  ReportOutcome outcome;

  std::vector<Point> all;
  std::vector<Reference> refs;
  for (const ReportScene& sc : scenes) {
    say(fmt::format("errors: {} — reference", sc.name));
    refs.push_back(makeReference(*sc.path, sc.ballRadius, kSamples, sc.path->hasConstantCurvatures() ? 0 : 40000));
    for (spin::Method m : spin::allMethods()) {
      std::vector<Point> p = sweep(sc, m, refs.back());
      all.insert(all.end(), p.begin(), p.end());
    }
    say(fmt::format("errors: {} done ({:.1f} s so far)", sc.name,
                    std::chrono::duration<double>(Clock::now() - start).count()));
  }
  SpeedRatio ratio;
  if (options.lollipopSpeedRatio) {
    say("errors: magnus4 against rk45 at 1e-11 on one lollipop revolution");
    ratio = magnus4VersusRk45();
  }

  std::vector<double> worstUnder(scenes.size(), 0.0);
  writeFile(options.outDir / "errors.csv", errorsCsv(scenes, all, refs, worstUnder));
  outcome.written.push_back(options.outDir / "errors.csv");
  writeErrorsPlot(scenes, all, refs, options.outDir, outcome);

  // ---- Markdown summary ----
  std::string md = "# rollspin report errors\n\n";
  md +=
      "Error = spinor distance (rad, 4π-aware) to the reference, max over 65 timeline samples; time = the "
      "solver alone (`solveFinal`), median of repeats after a warm-up. Methods: " +
      methodList() + ".\n\n";
  md += "Plot: [errors.png](errors.png); data: [errors.csv](errors.csv).\n\n";
  std::vector<std::string> tightest(scenes.size());  // per scene: the last (tightest) target with advice
  for (std::size_t si = 0; si < scenes.size(); ++si)
    md += errorsSceneSection(scenes[si], refs[si], all, worstUnder[si], tightest[si]);
  const double speedup = ratio.rkSeconds / ratio.magnusSeconds;
  if (options.lollipopSpeedRatio) md += speedRatioSection(ratio);
  const double total = std::chrono::duration<double>(Clock::now() - start).count();
  md += fmt::format("\nReport run time: {:.1f} s.\n", total);
  writeFile(options.outDir / "errors.md", md);
  outcome.written.push_back(options.outDir / "errors.md");
  if (!options.lollipopSpeedRatio) {
    // The user's scenes: the fastest stepping settings for the tightest target each reached.
    outcome.headline = "fastest stepping run for the tightest target reached (paste the --set options):";
    for (const std::string& t : tightest)
      outcome.headline += "\n  " + (t.empty() ? std::string("(no method reached 1e-6)") : t);
    outcome.headline += fmt::format("\nreport errors took {:.1f} s", total);
    return outcome;
  }
  outcome.headline = fmt::format(
      "magnus4 reaches 1e-11 on one lollipop revolution in {} ({} steps), rk45 in {} (tol {:.3g}): ratio {:.1f}\n"
      "report errors took {:.1f} s",
      fmtSeconds(ratio.magnusSeconds), ratio.magnusSteps, fmtSeconds(ratio.rkSeconds), ratio.rkTolerance, speedup,
      total);
  return outcome;
}

}  // namespace rollspin::report
