#include "jobs/left_out_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "jobs/figure_job.hpp"
#include "jobs/job_setup.hpp"
#include "jobs/render_jobs.hpp"

namespace rollspin::jobs {

namespace {

// A text is kept by a drawing that does not leave it out and draws each of
// its words (a line broken to fit is drawn as pieces; a narrow twin names
// the spin without its formula: that one is not "kept").
bool keeps(const render::DrawList& list, const std::string& text) {
  if (std::find(list.leftOut.begin(), list.leftOut.end(), text) != list.leftOut.end()) return false;
  std::istringstream words(text);
  for (std::string word; words >> word;)
    if (std::none_of(list.labels.begin(), list.labels.end(),
                     [&](const render::LabelItem& l) { return l.text.find(word) != std::string::npos; }))
      return false;
  return true;
}

// The still at another width or body size (the layout follows both).
// Only the keys the layout reads change, and go back: the model refers
// into the spec, which must stay where it is.
render::DrawList drawnAt(DrawJob& job, const std::optional<std::string>& at, double widthMm, double fontPt) {
  scene::SceneSpec& spec = job.spec;
  const auto width = spec.figure.widthMm;
  const auto size = spec.figure.fontSizePt;
  const auto fontScale = spec.render.fontScale;
  const draw::FigureText figureText = job.figureText;
  spec.figure.widthMm = widthMm;
  spec.figure.fontSizePt = fontPt;
  job.figureText = fitTextToFigure(spec, false);
  render::DrawList list = drawStill(job, at);
  spec.figure.widthMm = width;
  spec.figure.fontSizePt = size;
  spec.render.fontScale = fontScale;
  job.figureText = figureText;
  return list;
}

}  // namespace

std::vector<render::FigureLayout::LeftOut> whereLeftOutIsKept(DrawJob& job, const std::optional<std::string>& at,
                                                              const render::DrawList& list) {
  std::vector<render::FigureLayout::LeftOut> out;
  for (const std::string& text : list.leftOut) out.push_back({text, std::nullopt, std::nullopt});
  const double widthMm = job.spec.figure.widthMm, fontPt = figureTextPt(job.spec);
  // Each drawing answers for every text still unanswered: widths upwards,
  // then sizes downwards, stopping once each text has its answer.
  auto unanswered = [&](auto member) {
    return std::any_of(out.begin(), out.end(), [&](const auto& l) { return !(l.*member); });
  };
  for (const double width : kLeftOutWidthsMm) {
    if (width <= widthMm + 1e-9) continue;
    if (!unanswered(&render::FigureLayout::LeftOut::keptAtWidthMm)) break;
    const render::DrawList wider = drawnAt(job, at, width, fontPt);
    for (auto& l : out)
      if (!l.keptAtWidthMm && keeps(wider, l.text)) l.keptAtWidthMm = width;
  }
  for (double size = fontPt - kLeftOutFontStepPt; size >= kLeastFigureTextPt - 1e-9; size -= kLeftOutFontStepPt) {
    if (!unanswered(&render::FigureLayout::LeftOut::keptAtFontPt)) break;
    const render::DrawList smaller = drawnAt(job, at, widthMm, size);
    for (auto& l : out)
      if (!l.keptAtFontPt && keeps(smaller, l.text)) l.keptAtFontPt = size;
  }
  return out;
}

void reportLeftOut(const std::vector<render::FigureLayout::LeftOut>& leftOut, double widthMm, double fontPt) {
  for (const auto& l : leftOut) {
    const std::string wider = l.keptAtWidthMm
                                  ? fmt::format("kept at {:g} mm wide", *l.keptAtWidthMm)
                                  : fmt::format("not kept at any width up to {:g} mm", std::end(kLeftOutWidthsMm)[-1]);
    const std::string smaller = l.keptAtFontPt ? fmt::format("at {:g} pt", *l.keptAtFontPt)
                                               : fmt::format("at no size down to {:g} pt", kLeastFigureTextPt);
    fmt::print(stderr,
               "figure: \"{}\" left out: no room at {:g} mm and {:g} pt; {}, or {} "
               "(figure.width_mm, figure.font_size_pt)\n",
               l.text, widthMm, fontPt, wider, smaller);
  }
}

}  // namespace rollspin::jobs
