// The reports as files: the errors report on one small scene writes its CSV,
// Markdown (and the PNG when gnuplot is there) atomically, with no NaN
// printed as a number; the paper report's verdicts are the ones
// docs/solver.md#notes-on-the-paper documents.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "geometry/analytic_paths.hpp"
#include "report/report.hpp"
#include "support/cli_runner.hpp"

using namespace rollspin;

namespace {
std::filesystem::path freshDir(const std::string& name) {
  const std::filesystem::path dir = rollspin::test::testTmpRoot() / name;
  std::filesystem::remove_all(dir);
  return dir;
}
}  // namespace

TEST(ReportFiles, ErrorsReportOnOneSceneWritesCsvMarkdownAndPlot) {
  auto plane = std::make_shared<const geometry::Plane>(Eigen::Vector3d::UnitZ());
  const report::ReportScene scene{"lollipop", "circle r = 3",
                                  std::make_shared<geometry::PlaneCirclePath>(plane, Eigen::Vector3d::Zero(),
                                                                              Eigen::Vector3d::UnitX(), 3.0, 1.0, true),
                                  1.0};
  report::ReportOptions options;
  options.outDir = freshDir("report_errors");
  const report::ReportOutcome out = report::errorsReport({scene}, options);
  const std::string csv = test::readFile(options.outDir / "errors.csv");
  const std::string md = test::readFile(options.outDir / "errors.md");
  for (const char* method : {"exact", "magnus2", "magnus4", "rk4", "frame4", "cf4", "magnus6", "rk45", "frame6a"})
    EXPECT_NE(csv.find(std::string("lollipop,") + method + ","), std::string::npos) << method;
  EXPECT_EQ(csv.find("nan"), std::string::npos);
  EXPECT_EQ(md.find("nan"), std::string::npos);
  EXPECT_NE(md.find("| 1e-12 |"), std::string::npos);
  EXPECT_NE(md.find("rk45 / magnus4 time ratio"), std::string::npos);
  if (out.plotError.empty()) {
    EXPECT_GT(std::filesystem::file_size(options.outDir / "errors.png"), 10000u);
  }
  for (const auto& entry : std::filesystem::directory_iterator(options.outDir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();  // no temporaries left
}

TEST(ReportFiles, PaperReportVerdicts) {
  report::ReportOptions options;
  options.outDir = freshDir("report_paper");
  (void)report::paperReport(options);
  const std::string csv = test::readFile(options.outDir / "paper.csv");
  auto verdict = [&](const std::string& claim) {
    const auto at = csv.find("\n" + claim + ",");
    if (at == std::string::npos) return std::string("missing");
    const auto end = csv.find('\n', at + 1);
    const std::string line = csv.substr(at + 1, end - at - 1);
    return line.substr(line.rfind(',') + 1);
  };
  for (const char* c : {"lollipop", "tennis-ball", "brockett-plate", "sphere-outside", "sphere-outside-r=R",
                        "sphere-inside-derived", "axis-tan-beta"})
    EXPECT_EQ(verdict(c), "agree") << c;
  EXPECT_EQ(verdict("adiabatic-outside"), "agree (asymptotically)");
  for (const char* c : {"sphere-inside", "sphere-inside-r=3R", "adiabatic-inside", "penny"})
    EXPECT_EQ(verdict(c), "disagree") << c;
}

// On the user's own scene the report says how to use its finding — the exact
// --set options, which `solve` accepts as printed — and leaves out the
// lollipop magnus4-vs-rk45 section (docs/solver.md#reports).
TEST(ReportFiles, ErrorsReportOnAUserSceneGivesTheSettingsToUse) {
  const std::filesystem::path dir = freshDir("report_user_scene");
  const std::string scene = (test::sourceDir() / "scenes" / "cornu.toml").string();
  const auto r = test::runRollspin({"report", "errors", scene, "-o", dir.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string md = test::readFile(dir / "errors.md");
  EXPECT_EQ(md.find("lollipop"), std::string::npos) << md;
  EXPECT_EQ(r.out.find("lollipop"), std::string::npos) << r.out;
  EXPECT_EQ(r.err.find("lollipop"), std::string::npos) << r.err;
  EXPECT_NE(md.find("| `--set solver.method="), std::string::npos) << md;
  const auto at = r.out.find("with --set solver.method=");
  ASSERT_NE(at, std::string::npos) << r.out;
  const std::string line = r.out.substr(at + 5, r.out.find('\n', at) - at - 5);
  EXPECT_TRUE(line.find("--set solver.steps=") != std::string::npos ||
              line.find("--set solver.tolerance=") != std::string::npos)
      << line;
  std::vector<std::string> args{"solve", scene};
  std::istringstream words(line);
  for (std::string w; words >> w;) args.push_back(w);
  const auto solved = test::runRollspin(args);
  EXPECT_EQ(solved.exitCode, 0) << line << "\n" << solved.err;
}
