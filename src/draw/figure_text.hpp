// FigureText — the drawer's text policy: a clip's (no floor under the text
// sizes) or a printed figure's, whose least text size is leastScale times its
// body size (6 pt over figure.font_size_pt; jobs/figure_job computes it).
#pragma once

namespace rollspin::draw {

struct FigureText {
  double leastScale = 0.0;  // > 0: text laid out for a printed size
  [[nodiscard]] bool figure() const { return leastScale > 0.0; }
};

}  // namespace rollspin::draw
