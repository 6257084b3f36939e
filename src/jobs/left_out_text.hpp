// Where a figure's left-out text would be kept: the same still laid out
// again (no GL) at wider widths (the same body size) and at smaller body
// sizes (the same width, never under 6 pt), so that stderr and
// --layout-json can name, for each text the layout had no room for, the
// least width and the largest size that keep it. Nothing is left out
// silently (docs/figures.md, "What is left out").
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "render/draw_list.hpp"
#include "render/vector_figure.hpp"

namespace rollspin::jobs {

struct DrawJob;

// The widths tried (mm), in order; only those wider than the figure's.
inline constexpr double kLeftOutWidthsMm[] = {60, 70, 85, 100, 120, 140, 175, 210, 250, 300, 400, 500};
// The body sizes tried: from the figure's down to 6 pt in steps of this.
inline constexpr double kLeftOutFontStepPt = 0.5;

// list.leftOut, each with the least width and the largest body size tried
// that keep it (nullopt where none does). job.spec is restored.
[[nodiscard]] std::vector<render::FigureLayout::LeftOut> whereLeftOutIsKept(DrawJob& job,
                                                                            const std::optional<std::string>& at,
                                                                            const render::DrawList& list);

// One stderr line for each: what is left out at this width and size, and
// what keeps it.
void reportLeftOut(const std::vector<render::FigureLayout::LeftOut>& leftOut, double widthMm, double fontPt);

}  // namespace rollspin::jobs
