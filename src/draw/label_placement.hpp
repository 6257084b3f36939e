// Labels placed off what they must not cover: a still's world-anchored
// labels (the Bloch sphere's axis and pole labels, the marks' numbers) each
// take, of a ring of candidate offsets around their own, the nearest whose
// box (padded by a quarter em) keeps clear of the view's projected arrows
// (shaft and head), of its paths and trails (PolylineItem::labelsKeepOff),
// of the text plates and labels placed before it and of the view's edges.
// A box meets a segment of half width h when their distance is below h.
#pragma once

#include <cstddef>

#include "render/draw_list.hpp"

namespace rollspin::draw {

// Moves the world-anchored labels of `view` from index `first` on (the last
// first); a label moved over 2 em gets a thin leader line to its anchor,
// and one with no clear place within 6 em is left out (its text emptied).
// The text blocks' plates must be placed already: labels keep off them.
void keepLabelsClear(render::DrawList& list, int view, std::size_t first);

}  // namespace rollspin::draw
