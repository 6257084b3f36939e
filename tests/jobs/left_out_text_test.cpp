// jobs/left_out_text.hpp: for each text a figure leaves out, the least width and the largest body size tried that
// keep it (checked against figures drawn afresh at those and the next sizes), and the stderr line naming them.
#include "jobs/left_out_text.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "jobs/figure_job.hpp"
#include "jobs/job_setup.hpp"
#include "jobs/render_jobs.hpp"
#include "support/test_files.hpp"

namespace rollspin::jobs {
namespace {

using LeftOut = render::FigureLayout::LeftOut;

// The torus in a column at 8 pt has no room for some of its text (tests/cli/figure_text_test.cpp).
DrawJob torusFigureJob(double widthMm, double fontPt) {
  const std::vector<std::string> overrides{"render.dpi=60", "figure.width_mm=" + std::to_string(widthMm),
                                           "figure.font_size_pt=" + std::to_string(fontPt)};
  const std::filesystem::path pdf = test::freshTempDir("left_out_text") / "torus.pdf";
  DrawJob job = prepareDrawJob(
      {test::shippedScenePath("torus"), overrides, {}, {}, {}, false, pdf, media::OutputUse::Still, 0, {}});
  job.figureText = fitTextToFigure(job.spec, false);
  return job;
}

// Kept: not left out, and each of its words drawn in some label (a shortened text is not the text).
bool keptIn(const render::DrawList& list, const std::string& text) {
  if (std::find(list.leftOut.begin(), list.leftOut.end(), text) != list.leftOut.end()) return false;
  std::istringstream words(text);
  for (std::string word; words >> word;)
    if (std::none_of(list.labels.begin(), list.labels.end(),
                     [&](const render::LabelItem& l) { return l.text.find(word) != std::string::npos; }))
      return false;
  return true;
}

// The torus's still drawn afresh at a width and a size, each drawn once.
class FreshFigures {
 public:
  const render::DrawList& at(double widthMm, double fontPt) {
    const auto key = std::make_pair(widthMm, fontPt);
    auto it = lists_.find(key);
    if (it == lists_.end()) {
      DrawJob job = torusFigureJob(widthMm, fontPt);
      it = lists_.emplace(key, drawStill(job, std::nullopt)).first;
    }
    return it->second;
  }

 private:
  std::map<std::pair<double, double>, render::DrawList> lists_;
};

TEST(LeftOutText, EachTextLeftOutGetsTheLeastWidthAndTheLargestSizeThatKeepIt) {
  constexpr double kWidth = 85.0, kSize = 8.0;
  DrawJob job = torusFigureJob(kWidth, kSize);
  const render::DrawList list = drawStill(job, std::nullopt);
  ASSERT_FALSE(list.leftOut.empty()) << "the torus at 85 mm in 8 pt keeps all its text: choose another figure";
  const double fontScale = job.spec.render.fontScale;
  const double leastScale = job.figureText.leastScale;

  const std::vector<LeftOut> found = whereLeftOutIsKept(job, std::nullopt, list);

  // The job is as it was: the same figure keys and text policy.
  EXPECT_EQ(job.spec.figure.widthMm, kWidth);
  EXPECT_EQ(job.spec.figure.fontSizePt, kSize);
  EXPECT_EQ(job.spec.render.fontScale, fontScale);
  EXPECT_EQ(job.figureText.leastScale, leastScale);
  EXPECT_EQ(drawStill(job, std::nullopt).leftOut, list.leftOut);

  ASSERT_EQ(found.size(), list.leftOut.size());
  FreshFigures fresh;
  bool anyWidth = false, anySize = false;
  for (std::size_t i = 0; i < found.size(); ++i) {
    const LeftOut& l = found[i];
    SCOPED_TRACE(l.text);
    EXPECT_EQ(l.text, list.leftOut[i]);
    // Widths: those tried above 85 mm, the text left out at each one narrower than its answer.
    for (const double width : kLeftOutWidthsMm) {
      if (width <= kWidth) continue;
      if (l.keptAtWidthMm && width > *l.keptAtWidthMm) break;
      const bool kept = keptIn(fresh.at(width, kSize), l.text);
      EXPECT_EQ(kept, l.keptAtWidthMm && width == *l.keptAtWidthMm) << width << " mm";
    }
    if (l.keptAtWidthMm) {
      EXPECT_NE(std::find(std::begin(kLeftOutWidthsMm), std::end(kLeftOutWidthsMm), *l.keptAtWidthMm),
                std::end(kLeftOutWidthsMm));
    }
    // Sizes: 7.5 pt down to 6 pt, the text left out at each one larger than its answer.
    for (double size = kSize - kLeftOutFontStepPt; size >= kLeastFigureTextPt; size -= kLeftOutFontStepPt) {
      if (l.keptAtFontPt && size < *l.keptAtFontPt) break;
      const bool kept = keptIn(fresh.at(kWidth, size), l.text);
      EXPECT_EQ(kept, l.keptAtFontPt && size == *l.keptAtFontPt) << size << " pt";
    }
    anyWidth = anyWidth || l.keptAtWidthMm;
    anySize = anySize || l.keptAtFontPt;
  }
  // Both searches are shown to find something (at 100–120 mm and 6.5–7.5 pt when written).
  EXPECT_TRUE(anyWidth) << "no width keeps any text: choose another figure";
  EXPECT_TRUE(anySize) << "no size keeps any text: choose another figure";
}

// Kept means drawn word for word, not merely absent from the list of what is left out (a narrow twin names the
// spin without its formula): a text no figure draws is kept at no width and no size.
TEST(LeftOutText, ATextNoFigureDrawsIsKeptNowhere) {
  DrawJob job = torusFigureJob(85.0, 8.0);
  render::DrawList list = drawStill(job, std::nullopt);
  list.leftOut = {"spin Ξ(s) = never drawn"};
  const std::vector<LeftOut> found = whereLeftOutIsKept(job, std::nullopt, list);
  ASSERT_EQ(found.size(), 1U);
  EXPECT_EQ(found[0].text, "spin Ξ(s) = never drawn");
  EXPECT_EQ(found[0].keptAtWidthMm, std::nullopt);
  EXPECT_EQ(found[0].keptAtFontPt, std::nullopt);
}

TEST(LeftOutText, TheReportNamesEachTextWithWhatKeepsIt) {
  const std::vector<LeftOut> leftOut{{"spin X(s)", 120.0, 7.5}, {"Torus facts", std::nullopt, std::nullopt}};
  ::testing::internal::CaptureStderr();
  reportLeftOut(leftOut, 85, 8);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(),
            "figure: \"spin X(s)\" left out: no room at 85 mm and 8 pt; kept at 120 mm wide, or at 7.5 pt "
            "(figure.width_mm, figure.font_size_pt)\n"
            "figure: \"Torus facts\" left out: no room at 85 mm and 8 pt; not kept at any width up to 500 mm, or at "
            "no size down to 6 pt (figure.width_mm, figure.font_size_pt)\n");
  ::testing::internal::CaptureStderr();
  reportLeftOut({}, 85, 8);
  EXPECT_EQ(::testing::internal::GetCapturedStderr(), "") << "nothing left out, nothing said";
}

}  // namespace
}  // namespace rollspin::jobs
