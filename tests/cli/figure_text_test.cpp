// Figures at journal sizes: for every scene in scenes/ (a still at its
// middle, the lollipop also as an 8-position strobe) at 60, 85, 120 and 175
// mm and at 6, 8 and 10 pt, the PDF's own text boxes (pdftotext -bbox) stay
// on the page and no two lines overlap; the default body text is 7–9 pt
// (--verbose). Subprocess runs of the CLI (label gl); needs poppler-utils.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/cli_runner.hpp"
#include "support/pdf_text_boxes.hpp"
#include "support/sweep.hpp"
#include "support/test_files.hpp"

namespace rollspin {
namespace {

using test::PdfPage;
using test::PdfWord;

TEST(FigureText, EveryScenesFigureKeepsItsTextApartAndOnThePageAtJournalSizes) {
  if (std::system("command -v pdftotext > /dev/null") != 0) GTEST_SKIP() << "pdftotext (poppler-utils) missing";
  const std::filesystem::path dir = test::freshTempDir("figure_text");
  std::vector<std::pair<std::string, std::vector<std::string>>> cases;
  for (const auto& file : test::sweep(test::bundledSceneFiles())) cases.push_back({file.string(), {}});
  cases.push_back({test::shippedScenePath("lollipop"), {"--set", "render.strobe=8"}});
  // Every scene at a column and 8 pt; the strobe at every size (a sample
  // of the sizes too, under ROLLSPIN_TEST_SWEEP=sample).
  std::vector<std::pair<double, double>> strobeSizes;
  for (const double mm : {60.0, 85.0, 120.0, 175.0})
    for (const double pt : {6.0, 8.0, 10.0}) strobeSizes.push_back({mm, pt});
  strobeSizes = test::sweep(strobeSizes);
  int figures = 0;
  for (const auto& [scene, extra] : cases)
    for (const double mm : {60.0, 85.0, 120.0, 175.0})
      for (const double pt : {6.0, 8.0, 10.0}) {
        const bool strobeSize =
            std::find(strobeSizes.begin(), strobeSizes.end(), std::pair{mm, pt}) != strobeSizes.end();
        if (extra.empty() ? !(mm == 85.0 && pt == 8.0) : !strobeSize) continue;
        const std::filesystem::path pdf = dir / ("f" + std::to_string(figures++) + ".pdf");
        std::vector<std::string> args{"render",     scene,
                                      "--still",    "-o",
                                      pdf.string(), "--quiet",
                                      "--set",      "figure.width_mm=" + std::to_string(mm),
                                      "--set",      "figure.font_size_pt=" + std::to_string(pt),
                                      "--set",      "figure.font=Latin Modern Roman"};
        args.insert(args.end(), extra.begin(), extra.end());
        const test::CliResult r = test::runRollspin(args);
        ASSERT_EQ(r.exitCode, 0) << scene << " " << mm << " mm " << pt << " pt: " << r.err;
        const PdfPage page = test::readPdfWords(pdf);
        const std::string where = std::filesystem::path(scene).stem().string() + " at " + std::to_string(int(mm)) +
                                  " mm, " + std::to_string(int(pt)) + " pt";
        ASSERT_GT(page.width, 0.0) << where;
        ASSERT_FALSE(page.words.empty()) << where;
        for (const PdfWord& w : page.words) {
          EXPECT_TRUE(w.x0 >= -0.5 && w.y0 >= -0.5 && w.x1 <= page.width + 0.5 && w.y1 <= page.height + 0.5)
              << where << ": \"" << w.text << "\" leaves the page";
        }
        for (std::size_t i = 0; i < page.words.size(); ++i)
          for (std::size_t j = i + 1; j < page.words.size(); ++j)
            EXPECT_FALSE(test::wordsOverlap(page.words[i], page.words[j]))
                << where << ": \"" << page.words[i].text << "\" and \"" << page.words[j].text << "\" overlap";
      }
}

TEST(FigureText, TheDefaultBodyTextIsBetweenSevenAndNinePointsAtAnyWidth) {
  const std::filesystem::path dir = test::freshTempDir("figure_text_default");
  for (const std::string width :
       {"figure.width_mm=60", "figure.width=column", "figure.width_mm=120", "figure.width=page"}) {
    const test::CliResult r = test::runRollspin({"--verbose", "render", test::shippedScenePath("lollipop"), "--still",
                                                 "-o", (dir / "f.pdf").string(), "--set", width});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.err, m, std::regex(R"(figure: ([0-9]+) mm wide, body text ([0-9.]+) pt)")))
        << r.err;
    const double pt = std::stod(m[2]);
    EXPECT_GE(pt, 7.0) << width;
    EXPECT_LE(pt, 9.0) << width;
  }
  // The presets are the journals' widths, and a preset with a width conflicts.
  const test::CliResult column =
      test::runRollspin({"--verbose", "render", test::shippedScenePath("lollipop"), "--still", "-o",
                         (dir / "c.pdf").string(), "--set", "figure.width=column"});
  EXPECT_NE(column.err.find("figure: 85 mm wide"), std::string::npos) << column.err;
  const test::CliResult both =
      test::runRollspin({"render", test::shippedScenePath("lollipop"), "--still", "-o", (dir / "b.pdf").string(),
                         "--set", "figure.width=page", "--set", "figure.width_mm=100"});
  EXPECT_EQ(both.exitCode, 2);
  EXPECT_NE(both.err.find("figure.width"), std::string::npos) << both.err;
}

// Nothing is left out silently: the torus's figure at a column in 8 pt has
// no room for its twin's heading; stderr and --layout-json name it with the
// width and the size that keep it, and at that width the figure draws it.
struct LeftOutEntry {
  std::string text;
  std::optional<double> widthMm, fontPt;
};

std::vector<LeftOutEntry> leftOutOf(const std::string& json) {
  std::vector<LeftOutEntry> entries;
  const std::regex entry(
      R"re(\{"text": "([^"]*)", "kept_at_width_mm": ([0-9.]+|null), "kept_at_font_size_pt": ([0-9.]+|null)\})re");
  for (auto it = std::sregex_iterator(json.begin(), json.end(), entry); it != std::sregex_iterator(); ++it) {
    auto number = [](const std::string& v) { return v == "null" ? std::nullopt : std::optional<double>(std::stod(v)); };
    entries.push_back({(*it)[1], number((*it)[2]), number((*it)[3])});
  }
  return entries;
}

// Whether each word of `text` is the text of some drawn label's word ("texts" of the layout JSON).
bool drawn(const std::string& json, const std::string& text) {
  const std::size_t end = json.find("\"left_out\"");
  const std::string texts = json.substr(0, end);
  std::istringstream words(text);
  for (std::string word; words >> word;)
    if (texts.find(word) == std::string::npos) return false;
  return true;
}

TEST(FigureText, ATextLeftOutIsNamedWithTheWidthAndTheSizeThatKeepIt) {
  const std::filesystem::path dir = test::freshTempDir("figure_left_out");
  auto figure = [&](const std::string& width, const std::string& name) {
    const test::CliResult r =
        test::runRollspin({"render", test::shippedScenePath("torus"), "--still", "-o", (dir / (name + ".pdf")).string(),
                           "--set", "render.dpi=60", "--set", "figure.width_mm=" + width, "--set",
                           "figure.font_size_pt=8", "--layout-json", (dir / (name + ".json")).string()});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    return std::pair{r.err, test::readFile(dir / (name + ".json"))};
  };
  const auto [err, json] = figure("85", "column");
  const std::vector<LeftOutEntry> leftOut = leftOutOf(json);
  ASSERT_FALSE(leftOut.empty()) << json;
  for (const LeftOutEntry& e : leftOut) {
    EXPECT_NE(err.find("\"" + e.text + "\" left out: no room at 85 mm and 8 pt"), std::string::npos) << err;
    EXPECT_EQ(json.find("{\"text\": \"" + e.text + "\", \"box\""), std::string::npos) << e.text << " is drawn too";
    if (e.widthMm) {
      EXPECT_GT(*e.widthMm, 85.0) << e.text;
    }
    if (e.fontPt) {
      EXPECT_LT(*e.fontPt, 8.0) << e.text;
    }
  }
  const auto named = std::find_if(leftOut.begin(), leftOut.end(), [](const LeftOutEntry& e) { return e.widthMm; });
  ASSERT_NE(named, leftOut.end()) << "no width keeps any of them: " << json;
  const auto [wideErr, wideJson] = figure(std::to_string(int(*named->widthMm)), "wider");
  EXPECT_TRUE(drawn(wideJson, named->text)) << named->text << " at " << *named->widthMm << " mm: " << wideJson;
  for (const LeftOutEntry& e : leftOutOf(wideJson)) EXPECT_NE(e.text, named->text);
  EXPECT_EQ(wideErr.find("\"" + named->text + "\" left out"), std::string::npos) << wideErr;
}

}  // namespace
}  // namespace rollspin
