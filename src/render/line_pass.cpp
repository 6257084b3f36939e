// Lines: a polyline as capsules (line.geom/line.frag), antialiased by its
// coverage, drawn with adjacency so that each segment sees its neighbours.
#include "render/line_pass.hpp"

#include <algorithm>

namespace rollspin::render {

namespace {

// Segments per part tested against a retained frame's rectangles.
constexpr std::size_t kLineRun = 32;

}  // namespace

// Over a retained layer only the dirty rectangles are read back (see
// drawOverLayer), so a polyline draws only the runs of segments whose
// screen bounds reach one (scope.clips): the geometry shader pays per
// segment, and the static lines (the whole path, the Bloch grid) are long.
// Segments are independent quads, drawn in the same order either way: the
// bytes of the dirty pixels do not change.
void LinePass::draw(const PolylineItem& p, const DrawScope& scope, Program& line, const VertexStreams& streams,
                    int fbHeight, RenderStats& stats) {
  if (p.points.size() < 2) return;
  const View& v = *scope.view;
  const glm::mat4& clipFromWorld = scope.clipFromWorld;
  line.use();
  line.set("clipFromWorld", clipFromWorld);
  line.set("viewportOrigin", glm::vec2(v.x, fbHeight - v.y - v.height));  // GL counts rows from the bottom
  line.set("viewportSize", glm::vec2(v.width, v.height));
  line.set("widthPx", p.widthPx);
  line.set("depthBias", p.depthTested ? 0.0008f : 0.0f);
  line.set("lineColor", p.color);
  // Drawn with adjacency (each segment sees its neighbours, see line.frag):
  // the ends repeated, so point k is vertex k + 1 and the segments from
  // point a to point b are the strip's vertices a to b + 2.
  std::vector<glm::vec3>& padded = padded_;
  padded.clear();
  padded.push_back(p.points.front());
  padded.insert(padded.end(), p.points.begin(), p.points.end());
  padded.push_back(p.points.back());
  streams.uploadPoints(padded);
  if (scope.clips == nullptr) {
    glDrawArrays(GL_LINE_STRIP_ADJACENCY, 0, static_cast<GLsizei>(padded.size()));
    return;
  }
  // A segment draws only within half a width of its ends' span (a capsule).
  // A part is the points [first, last] of up to kLineRun segments; the
  // next part begins at its last point, so adjacent parts merge.
  const float margin = 0.7072f * p.widthPx + 2.0f;
  RunsOfParts& kept = kept_;
  kept.clear();
  for (std::size_t first = 0; first + 1 < p.points.size(); first += kLineRun) {
    const std::size_t last = std::min(first + kLineRun, p.points.size() - 1);
    if (reachesAny(*scope.clips, screenBounds(v, clipFromWorld, &p.points[first], last - first + 1, margin)))
      kept.add(first, last);
  }
  // The runs go to GL in one call, as a mesh's do.
  firsts_.clear();
  counts_.clear();
  for (const RunsOfParts::Run& r : kept.runs()) {
    firsts_.push_back(static_cast<GLint>(r.begin));
    counts_.push_back(static_cast<GLsizei>(r.end - r.begin + 3));
    stats.lineSegmentsDrawn += static_cast<long long>(r.end - r.begin);
  }
  if (!firsts_.empty())
    glMultiDrawArrays(GL_LINE_STRIP_ADJACENCY, firsts_.data(), counts_.data(), static_cast<GLsizei>(firsts_.size()));
  stats.lineSegmentsInRects += static_cast<long long>(p.points.size() - 1);
}

}  // namespace rollspin::render
