// The line pass: a polyline as capsules (line.geom/line.frag), antialiased
// by its coverage, drawn with adjacency so that each segment sees its
// neighbours. Renderer-internal.
#pragma once

#include <vector>

#include "render/draw_scope.hpp"
#include "render/gl_objects.hpp"
#include "render/renderer.hpp"
#include "render/screen_bounds.hpp"

namespace rollspin::render {

// Draws polylines; holds the vectors it reuses from draw to draw (no
// allocation per draw).
class LinePass {
 public:
  // Draws `p` in scope's view with `line` (Programs::line) through
  // `streams`, in a framebuffer `fbHeight` rows tall; over a retained
  // layer (scope.clips) only the runs of segments that reach a rectangle,
  // counted in `stats`.
  void draw(const PolylineItem& p, const DrawScope& scope, Program& line, const VertexStreams& streams, int fbHeight,
            RenderStats& stats);

 private:
  std::vector<glm::vec3> padded_;  // the points with their ends repeated
  RunsOfParts kept_;
  std::vector<GLint> firsts_;
  std::vector<GLsizei> counts_;
};

}  // namespace rollspin::render
