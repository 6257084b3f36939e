// Figures at journal sizes, against the layout the code computes
// (render::figureLayout: the plates, the labels' boxes and anchors, the
// projected arrows and paths): every word of the PDF (pdftotext -bbox) lies
// inside a text plate, or is a free label (axis, pole, mark number) whose
// box clears every arrow and every path (the title's band is its plate);
// words stay on the page and apart; every text prints at the size asked
// for (a long line wraps) and at least 6 pt; no plate covers a path. Every scene in scenes/ (and the
// lollipop as an 8-position strobe), at 60, 85, 120 and 175 mm, in Latin
// Modern at 6–10 pt. In process and without GL: the text and the vectors of
// a figure do not depend on its raster images, which are left out here.
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "draw/clip_layout.hpp"
#include "jobs/figure_job.hpp"
#include "jobs/job_setup.hpp"
#include "jobs/render_jobs.hpp"
#include "render/vector_figure.hpp"
#include "support/cli_runner.hpp"
#include "support/pdf_text_boxes.hpp"
#include "support/sweep.hpp"

namespace rollspin {
namespace {

namespace fs = std::filesystem;
using render::FigureBox;
using render::FigureLayout;
using test::PdfWord;

constexpr std::array<double, 4> kWidthsMm{60.0, 85.0, 120.0, 175.0};
constexpr std::array<double, 5> kSizesPt{6.0, 7.0, 8.0, 9.0, 10.0};

// The text size a scene is drawn at, at the width with index w: one of the
// five, turning with the scene's index, so that across the scenes (more
// than five) every width meets every size. Drawing every scene at every
// size costs five times the time (a drawer lays its text out per size).
double sizeFor(std::size_t scene, std::size_t w) { return kSizesPt[(scene + w) % kSizesPt.size()]; }

bool inside(const PdfWord& w, const FigureBox& b, double slack) {
  return w.x0 >= b.x0 - slack && w.y0 >= b.y0 - slack && w.x1 <= b.x1 + slack && w.y1 <= b.y1 + slack;
}

double distanceToSegment(glm::dvec2 p, const FigureLayout::Segment& s) {
  const glm::dvec2 d = s.b - s.a;
  const double t = glm::clamp(glm::dot(p - s.a, d) / std::max(glm::dot(d, d), 1e-12), 0.0, 1.0);
  return glm::length(p - (s.a + t * d));
}

// The distance from a word's box to a segment (0 where they meet).
double distance(const PdfWord& w, const FigureLayout::Segment& s) {
  auto in = [&](glm::dvec2 p) { return p.x >= w.x0 && p.x <= w.x1 && p.y >= w.y0 && p.y <= w.y1; };
  if (in(s.a) || in(s.b)) return 0.0;
  const glm::dvec2 corners[4] = {{w.x0, w.y0}, {w.x1, w.y0}, {w.x1, w.y1}, {w.x0, w.y1}};
  auto side = [](glm::dvec2 o, glm::dvec2 p, glm::dvec2 q) {
    return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x);
  };
  double best = 1e300;
  for (int k = 0; k < 4; ++k) {
    const glm::dvec2 c = corners[k], e = corners[(k + 1) % 4];
    if ((side(c, e, s.a) > 0) != (side(c, e, s.b) > 0) && (side(s.a, s.b, c) > 0) != (side(s.a, s.b, e) > 0))
      return 0.0;
    best = std::min(best, distanceToSegment(c, s));
  }
  for (const glm::dvec2 end : {s.a, s.b})
    best = std::min(best, glm::length(end - glm::clamp(end, glm::dvec2(w.x0, w.y0), glm::dvec2(w.x1, w.y1))));
  return best;
}

struct Figure {
  FigureLayout layout;
  test::PdfPage page;
};

// The figure of `job` at a width and a text size, as `render --still -o
// FILE.pdf` writes it but for its raster images; its layout and its words.
Figure figureOf(jobs::DrawJob& job, double mm, double pt, const fs::path& pdf) {
  job.spec.figure.widthMm = mm;
  job.spec.figure.fontSizePt = pt;
  job.figureText = jobs::fitTextToFigure(job.spec);
  const render::DrawList list = jobs::drawStill(job, std::nullopt);
  const render::FigureStyle style = jobs::figureStyleOf(job.spec, list);
  render::writeFigure(pdf, render::FigureFormat::Pdf, list, render::FigureRasters{}, style);
  return {render::figureLayout(list, style), test::readPdfWords(pdf)};
}

// The distance from a box to a segment (0 where they meet).
double distance(const FigureBox& b, const FigureLayout::Segment& s) {
  return distance(PdfWord{b.x0, b.y0, b.x1, b.y1, ""}, s);
}

void checkFigure(const Figure& f, const std::string& where, double requestedPt) {
  const FigureLayout& layout = f.layout;
  ASSERT_NEAR(f.page.width, layout.widthPt, 0.01) << where;
  ASSERT_FALSE(f.page.words.empty()) << where;
  // Text prints at the size asked for: a line too long for its view breaks
  // onto more lines instead of shrinking (the bold heading and title face
  // measures a little smaller: 1 %), and nothing prints under 6 pt.
  for (const FigureLayout::Text& t : layout.texts) {
    EXPECT_GE(t.sizePt, 6.0 - 1e-6) << where << ": \"" << t.text << "\" prints at " << t.sizePt << " pt";
    if (!t.free) {
      EXPECT_GE(t.sizePt, 0.99 * requestedPt) << where << ": \"" << t.text << "\" shrunk to " << t.sizePt << " pt";
    }
  }
  // No text plate lies over a path (the title's band holds none).
  for (const FigureBox& plate : layout.plates)
    for (const FigureLayout::Segment& s : layout.paths)
      EXPECT_GT(distance(plate, s), s.halfWidth)
          << where << ": the plate (" << plate.x0 << ", " << plate.y0 << ")–(" << plate.x1 << ", " << plate.y1
          << ") covers the path from (" << s.a.x << ", " << s.a.y << ") to (" << s.b.x << ", " << s.b.y << ")";
  // The free labels' boxes in the layout are the font's ascent and descent
  // over the advance, where poppler's are the glyphs' font box: a word
  // belongs to the label whose box holds its centre.
  auto freeLabelOf = [&](const PdfWord& w) -> const FigureLayout::Text* {
    const glm::dvec2 c(0.5 * (w.x0 + w.x1), 0.5 * (w.y0 + w.y1));
    for (const FigureLayout::Text& t : layout.texts)
      if (t.free && c.x >= t.box.x0 - 0.5 && c.x <= t.box.x1 + 0.5 && c.y >= t.box.y0 - 0.5 && c.y <= t.box.y1 + 0.5)
        return &t;
    return nullptr;
  };
  for (const PdfWord& w : f.page.words) {
    const std::string word = where + ": \"" + w.text + "\"";
    EXPECT_TRUE(w.x0 >= -0.5 && w.y0 >= -0.5 && w.x1 <= f.page.width + 0.5 && w.y1 <= f.page.height + 0.5)
        << word << " leaves the page";
    // Poppler's box is the font's (its ascent and descent, a little more
    // than the layout's for a fallback face): a quarter point of slack.
    const bool onPlate =
        std::any_of(layout.plates.begin(), layout.plates.end(), [&](const FigureBox& b) { return inside(w, b, 0.25); });
    if (onPlate) continue;
    if (const FigureLayout::Text* label = freeLabelOf(w)) {
      for (const auto* segments : {&layout.arrows, &layout.paths})
        for (const FigureLayout::Segment& s : *segments)
          EXPECT_GT(distance(w, s), s.halfWidth) << word << " (label \"" << label->text << "\") sits on "
                                                 << (segments == &layout.arrows ? "an arrow" : "a path") << " from ("
                                                 << s.a.x << ", " << s.a.y << ") to (" << s.b.x << ", " << s.b.y << ")";
      continue;
    }
    ADD_FAILURE() << word << " at (" << w.x0 << ", " << w.y0 << ")–(" << w.x1 << ", " << w.y1 << ") leaves its plate";
  }
  for (std::size_t i = 0; i < f.page.words.size(); ++i)
    for (std::size_t j = i + 1; j < f.page.words.size(); ++j)
      EXPECT_FALSE(test::wordsOverlap(f.page.words[i], f.page.words[j]))
          << where << ": \"" << f.page.words[i].text << "\" and \"" << f.page.words[j].text << "\" overlap";
}

TEST(FigureLayout, TextStaysOnItsPlateAndLabelsOffArrowsAndPathsAtJournalSizes) {
  if (std::system("command -v pdftotext > /dev/null") != 0) GTEST_SKIP() << "pdftotext (poppler-utils) missing";
  const fs::path dir = test::freshTempDir("figure_layout");
  std::vector<std::pair<std::string, std::vector<std::string>>> cases;
  for (const auto& file : test::bundledSceneFiles()) cases.push_back({file.string(), {}});
  cases.push_back({test::shippedScenePath("lollipop"), {"render.strobe=8"}});
  int figures = 0;
  std::array<std::array<int, 5>, 4> covered{};
  for (const std::size_t i : test::sweepIndices(cases.size())) {
    const auto& [scene, extra] = cases[i];
    std::vector<std::string> overrides{"figure.font=Latin Modern Roman"};
    overrides.insert(overrides.end(), extra.begin(), extra.end());
    const fs::path pdf = dir / ("f" + std::to_string(i) + ".pdf");
    jobs::DrawJob job =
        jobs::prepareDrawJob({scene, overrides, {}, {}, {}, false, pdf, media::OutputUse::Still, 0, {}});
    for (std::size_t w = 0; w < kWidthsMm.size(); ++w) {
      const double pt = sizeFor(i, w);
      const std::string where = fs::path(scene).stem().string() + (extra.empty() ? "" : " (strobe)") + " at " +
                                std::to_string(int(kWidthsMm[w])) + " mm, " + std::to_string(int(pt)) + " pt";
      checkFigure(figureOf(job, kWidthsMm[w], pt, pdf), where, pt);
      ++covered[w][std::size_t(pt) - 6];
      ++figures;
    }
  }
  for (std::size_t w = 0; w < kWidthsMm.size(); ++w)
    for (std::size_t p = 0; p < kSizesPt.size() && !test::sweepSampled(); ++p)
      EXPECT_GT(covered[w][p], 0) << kWidthsMm[w] << " mm at " << kSizesPt[p] << " pt is never drawn";
  std::printf("%d figures checked\n", figures);
}

// The Bloch sphere of a figure fills the room its text leaves. Room: the
// shorter side S of the largest rectangle of the twin view clear of its text plates; the
// sphere's projected diameter (its silhouette, from the view's camera) is at
// least 0.8 (S − 3 em, em here the labels' line height): the labels keep
// about 0.9 of a line all round it.
// Its labels: each drawn, its box (advance × ascent + descent) within
// 4.5 em (the printed size) of its anchor (an axis's end, a pole), and
// 85 % of them within 1.5 em. A label keeps off the arrows, the axes and
// the trails, which can crowd a pole seen from high above (the lollipop's
// strobe): there the nearest clear place lies farther.
constexpr double kCloseLabelEm = 1.5, kFarthestLabelEm = 4.5, kCloseShare = 0.85;
struct LabelCount {
  int count = 0, close = 0;
};

// The twin is the last view (scene_drawer); `labels`: the scene's labels are on.
void checkTwin(const render::DrawList& list, const FigureLayout& layout, const std::string& where, bool labelsOn,
               LabelCount& labels) {
  ASSERT_FALSE(list.views.empty()) << where;
  const int twin = int(list.views.size()) - 1;
  const render::View& v = list.views[std::size_t(twin)];
  const double unit = layout.widthPt / double(list.width);  // points per layout pixel
  const FigureBox& view = layout.views[std::size_t(twin)];
  std::vector<std::pair<glm::vec2, glm::vec2>> plates;
  for (const FigureBox& p : layout.plates)
    if (p.x0 >= view.x0 - 0.5 && p.x1 <= view.x1 + 0.5 && p.y0 >= view.y0 - 0.5 && p.y1 <= view.y1 + 0.5)
      plates.emplace_back(glm::vec2((p.x0 - view.x0) / unit, (p.y0 - view.y0) / unit),
                          glm::vec2((p.x1 - view.x0) / unit, (p.y1 - view.y0) / unit));
  const draw::NdcWindow room = draw::clearWindow(v.width, v.height, plates, 0.0f);
  const double roomSide = std::min(0.5 * (room.x1 - room.x0) * v.width, 0.5 * (room.y1 - room.y0) * v.height);
  // The unit sphere's silhouette: its points' projected extent.
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  glm::dvec2 lo(1e30), hi(-1e30);
  for (int i = 0; i <= 90; ++i)
    for (int j = 0; j < 180; ++j) {
      const double theta = M_PI * i / 90.0, phi = 2.0 * M_PI * j / 180.0;
      const glm::vec4 c =
          clipFromWorld * glm::vec4(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                                    float(std::cos(theta)), 1.0f);
      const glm::dvec2 px((c.x / c.w * 0.5 + 0.5) * v.width, (0.5 - c.y / c.w * 0.5) * v.height);
      lo = glm::min(lo, px), hi = glm::max(hi, px);
    }
  const double diameter = std::min(hi.x - lo.x, hi.y - lo.y);
  float em = 0.0f;  // the labels' size in layout pixels
  for (const render::LabelItem& l : list.labels)
    if (l.view == twin && l.worldAnchored) em = std::max(em, l.sizePx);
  EXPECT_GE(diameter, 0.8 * (roomSide - 3.0 * em))
      << where << ": the sphere is " << diameter << " px across in a room " << roomSide << " px (em " << em << " px)";
  for (const char* name : {"x", "y", "z", "|0⟩", "|1⟩"}) {
    if (!labelsOn) break;
    const auto t = std::find_if(layout.texts.begin(), layout.texts.end(), [&](const FigureLayout::Text& x) {
      return x.view == twin && x.free && x.text == name;
    });
    if (t == layout.texts.end()) {
      ADD_FAILURE() << where << ": the label \"" << name << "\" is left out";
      continue;
    }
    const glm::dvec2 nearest =
        glm::clamp(t->anchor, glm::dvec2(t->box.x0, t->box.y0), glm::dvec2(t->box.x1, t->box.y1));
    const double ems = glm::length(nearest - t->anchor) / t->sizePt;
    EXPECT_LE(ems, kFarthestLabelEm) << where << ": \"" << name << "\" lies " << ems << " em from its point";
    ++labels.count;
    if (ems <= kCloseLabelEm) ++labels.close;
  }
}

TEST(FigureLayout, TheBlochSphereFillsTheRoomItsTextLeaves) {
  const fs::path dir = test::freshTempDir("figure_twin");
  std::vector<std::pair<std::string, std::vector<std::string>>> cases;
  for (const auto& file : test::bundledSceneFiles()) cases.push_back({file.string(), {}});
  cases.push_back({test::shippedScenePath("lollipop"), {"render.strobe=8"}});
  LabelCount labels;
  for (const std::size_t i : test::sweepIndices(cases.size())) {
    const auto& [scene, extra] = cases[i];
    std::vector<std::string> overrides{"figure.font=Latin Modern Roman"};
    overrides.insert(overrides.end(), extra.begin(), extra.end());
    const fs::path pdf = dir / ("t" + std::to_string(i) + ".pdf");
    jobs::DrawJob job =
        jobs::prepareDrawJob({scene, overrides, {}, {}, {}, false, pdf, media::OutputUse::Still, 0, {}});
    if (job.spec.render.layout == scene::RenderLayout::Ball) continue;  // no sphere
    for (std::size_t w = 0; w < kWidthsMm.size(); ++w) {
      const double pt = sizeFor(i, w);
      job.spec.figure.widthMm = kWidthsMm[w];
      job.spec.figure.fontSizePt = pt;
      job.figureText = jobs::fitTextToFigure(job.spec);
      const render::DrawList list = jobs::drawStill(job, std::nullopt);
      const FigureLayout layout = render::figureLayout(list, jobs::figureStyleOf(job.spec, list));
      checkTwin(list, layout,
                fs::path(scene).stem().string() + (extra.empty() ? "" : " (strobe)") + " at " +
                    std::to_string(int(kWidthsMm[w])) + " mm, " + std::to_string(int(pt)) + " pt",
                job.spec.render.labels, labels);
    }
  }
  ASSERT_GT(labels.count, 0);
  EXPECT_GE(labels.close, kCloseShare * labels.count)
      << labels.close << " of " << labels.count << " labels within " << kCloseLabelEm << " em of their points";
  std::printf("%d of %d Bloch labels within %.1f em of their points\n", labels.close, labels.count, kCloseLabelEm);
}

// The layout is what the figure draws: its text boxes hold the PDF's words
// (a label moved by the layout is found where the layout says), and
// `render --layout-json` writes the same layout from the CLI.
TEST(FigureLayout, TheLayoutHoldsThePdfsWordsAndTheCliWritesIt) {
  if (std::system("command -v pdftotext > /dev/null") != 0) GTEST_SKIP() << "pdftotext (poppler-utils) missing";
  const fs::path dir = test::freshTempDir("figure_layout_json");
  const fs::path pdf = dir / "fig.pdf";
  jobs::DrawJob job = jobs::prepareDrawJob({test::shippedScenePath("lollipop"),
                                            {"render.strobe=8"},
                                            {},
                                            {},
                                            {},
                                            false,
                                            pdf,
                                            media::OutputUse::Still,
                                            0,
                                            {}});
  const Figure f = figureOf(job, 85.0, 8.0, pdf);
  int found = 0;
  for (const FigureLayout::Text& t : f.layout.texts) {
    const bool held = std::any_of(f.page.words.begin(), f.page.words.end(), [&](const PdfWord& w) {
      return w.x0 >= t.box.x0 - 0.5 && w.x1 <= t.box.x1 + 0.5 && 0.5 * (w.y0 + w.y1) > t.box.y0 &&
             0.5 * (w.y0 + w.y1) < t.box.y1;
    });
    EXPECT_TRUE(held) << "\"" << t.text << "\" is not where the layout puts it";
    found += held ? 1 : 0;
  }
  EXPECT_GE(found, 10);  // the facts, the axis and pole labels, the legend
  EXPECT_FALSE(f.layout.plates.empty());
  EXPECT_GE(f.layout.arrows.size(), 2u * 9u);  // the spin, the field and the 8 strobe spins... at least 9
  EXPECT_FALSE(f.layout.paths.empty());

  const test::CliResult r = test::runRollspin(
      {"render", test::shippedScenePath("lollipop"), "--still", "-o", (dir / "cli.pdf").string(), "--quiet", "--set",
       "render.strobe=8", "--set", "figure.width=column", "--layout-json", (dir / "layout.json").string()});
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const std::string json = test::readFile(dir / "layout.json");
  for (const char* key : {"\"width_pt\": 240.945", "\"plates\"", "\"texts\"", "\"arrows\"", "\"paths\"", "\"|0⟩\""})
    EXPECT_NE(json.find(key), std::string::npos) << key << " not in " << json.substr(0, 400);
  // Only for a figure still.
  const test::CliResult png =
      test::runRollspin({"render", test::shippedScenePath("lollipop"), "--still", "-o", (dir / "still.png").string(),
                         "--layout-json", (dir / "x.json").string()});
  EXPECT_EQ(png.exitCode, 2) << png.err;
  EXPECT_NE(png.err.find("--layout-json"), std::string::npos) << png.err;
  EXPECT_FALSE(fs::exists(dir / "x.json"));
}

}  // namespace
}  // namespace rollspin
