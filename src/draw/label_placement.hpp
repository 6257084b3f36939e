// Labels placed off what they must not cover: a still's world-anchored
// labels (the Bloch sphere's axis and pole labels, the marks' numbers) each
// take, of a ring of candidate offsets around their own, the nearest whose
// box (padded by a quarter em) keeps clear of the view's projected arrows
// (shaft and head), of its paths and trails (PolylineItem::labelsKeepOff),
// of the text plates and labels placed before it and of the view's edges.
// A box meets a segment of half width h when their distance is below h.
#pragma once

#include <cstddef>

#include "draw/clip_layout.hpp"
#include "render/draw_list.hpp"

namespace rollspin::draw {

// Moves the world-anchored labels of `view` from index `first` on (the last
// first); a label moved over 2 em gets a thin leader line to its anchor,
// and one with no clear place within 6 em is left out (its text emptied).
// The text blocks' plates must be placed already: labels keep off them.
// nearestToAnchor (a figure's Bloch sphere): of the clear places, the one
// whose box is nearest the label's anchor, on a finer ring.
void keepLabelsClear(render::DrawList& list, int view, std::size_t first, bool nearestToAnchor = false);

// A still's text blocks (of `view`, whose arrows and paths are drawn
// already) kept off its arrows, its paths, the `subject` (the ball) and
// each other: a block whose plate meets one moves to the nearest clear
// place (half-em grid); with none, it breaks onto more, narrower lines
// (down to a quarter of the view), then gives up its last lines (a broken
// line whole), and with no line left it is not drawn. Returns the origins.
std::vector<glm::vec2> keepBlocksClear(const render::DrawList& list, int view, std::vector<TextBlock>& blocks,
                                       std::vector<glm::vec2> origins, const Occupancy& subject);

}  // namespace rollspin::draw
