// `rollspin render SCENE -o NAME.html` (the web viewer, issue 52) and
// `rollspin timeline --at-s FILE` (the timeline at the arc lengths the
// browser test checks the page against), from the command line: what the
// page holds, and bad input refused with exit 2 and nothing left behind.
// The page in a browser: viewer_browser_test.mjs (ctest Browser.Viewer).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "support/cli_runner.hpp"

namespace fs = std::filesystem;
using namespace rollspin;

namespace {

std::string readText(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

// The content of the one <script ... id="ID"> of the page.
std::string scriptText(const std::string& page, const std::string& id) {
  const std::size_t tag = page.find("id=\"" + id + "\"");
  if (tag == std::string::npos) return {};
  const std::size_t start = page.find('>', tag) + 1;
  return page.substr(start, page.find("</script>", start) - start);
}

std::vector<std::vector<double>> csvRows(const fs::path& path) {
  std::ifstream in(path);
  std::vector<std::vector<double>> rows;
  std::string line;
  bool header = true;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') continue;
    if (std::exchange(header, false)) continue;
    std::vector<double> row;
    std::stringstream cells(line);
    for (std::string cell; std::getline(cells, cell, ',');) row.push_back(std::stod(cell));
    rows.push_back(row);
  }
  return rows;
}

TEST(ViewerCli, WritesOnePageWithTheSceneTheTimelineAndTheMeshes) {
  const fs::path dir = test::freshTempDir("viewer_page");
  const fs::path out = dir / "storyboard.html";
  const auto r = test::runRollspin({"render", test::shippedScenePath("storyboard"), "-o", out.string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string page = readText(out);
  EXPECT_EQ(page.rfind("<!DOCTYPE html>", 0), 0u);
  EXPECT_LE(page.size(), 3u << 20) << "the page must stay under 3 MB";
  EXPECT_NE(page.find("<meta name=\"generator\" content=\"rollspin "), std::string::npos);
  EXPECT_EQ(page.find("{{"), std::string::npos) << "a template marker was left unfilled";
  const std::string scene = scriptText(page, "rollspin-scene");
  EXPECT_NE(scene.find("[[segment]]"), std::string::npos) << "the resolved scene text";
  const std::string timeline = scriptText(page, "rollspin-timeline");
  for (const char* key : {"\"length\"", "\"chapters\"", "\"caption\"", "\"s\"", "\"q\"", "\"B\"", "\"centre\""})
    EXPECT_NE(timeline.find(key), std::string::npos) << key;
  // The GLB: base64 of "glTF" (its magic) then the version 2.
  EXPECT_EQ(scriptText(page, "rollspin-glb").rfind("Z2xURgIAAA", 0), 0u);
  EXPECT_NE(r.err.find("wrote " + out.string()), std::string::npos) << r.err;
}

TEST(ViewerCli, RefusesBadOutputsWithExit2AndLeavesNothing) {
  const fs::path dir = test::freshTempDir("viewer_refused");
  const std::string scene = test::shippedScenePath("lollipop");
  struct Case {
    std::vector<std::string> args;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{"render", scene, "-o", (dir / "x.htmx").string()}, "htmx"},
      {{"render", scene, "-o", "/proc/x.html"}, "cannot write in the folder '/proc'"},
      {{"render", scene, "-o", (dir / "x.html").string(), "--frames", "0:3"}, "not to the web viewer"},
      {{"render", scene, "--still", "-o", (dir / "x.html").string()}, "html"},
  };
  for (const Case& c : cases) {
    const auto r = test::runRollspin(c.args);
    EXPECT_EQ(r.exitCode, 2) << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
  }
  EXPECT_TRUE(fs::is_empty(dir)) << "nothing written, no temporary left";
}

TEST(TimelineAtS, SamplesTheFilesArcLengthsSortedAsTheDefaultSamplingDoes) {
  const fs::path dir = test::freshTempDir("timeline_at_s");
  const std::string scene = test::shippedScenePath("lollipop");
  ASSERT_EQ(test::runRollspin({"timeline", scene, "-o", (dir / "all.csv").string()}).exitCode, 0);
  const auto all = csvRows(dir / "all.csv");
  ASSERT_GT(all.size(), 40u);
  // Three of the default rows' s, out of order, two on one line, with a comment.
  {
    std::ofstream arcs(dir / "s.txt");
    arcs << std::setprecision(17) << all.back()[0] << " # the last\n" << all[31][0] << "  " << all[7][0] << "\n";
  }
  const auto r =
      test::runRollspin({"timeline", scene, "--at-s", (dir / "s.txt").string(), "-o", (dir / "some.csv").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto some = csvRows(dir / "some.csv");
  ASSERT_EQ(some.size(), 3u);
  const std::vector<std::vector<double>> expected{all[7], all[31], all.back()};
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t c = 0; c < expected[i].size(); ++c)
      EXPECT_NEAR(some[i][c], expected[i][c], 1e-11) << "row " << i << " column " << c;
}

TEST(TimelineAtS, RefusesAnArcLengthOffThePathAtItsLine) {
  const fs::path dir = test::freshTempDir("timeline_at_s_bad");
  std::ofstream(dir / "s.txt") << "0.5\n1e9\n";
  const auto r = test::runRollspin({"timeline", test::shippedScenePath("lollipop"), "--at-s", (dir / "s.txt").string(),
                                    "-o", (dir / "x.csv").string()});
  EXPECT_EQ(r.exitCode, 2) << r.err;
  EXPECT_NE(r.err.find((dir / "s.txt").string() + ":2"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("expected an arc length in [0,"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
}

}  // namespace
