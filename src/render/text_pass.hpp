// The text pass: labels as glyph quads from a font atlas (font_atlas.hpp),
// in a view's pixels or the image's, and the inset frame as solid quads.
// Renderer-internal.
#pragma once

#include <span>
#include <vector>

#include "render/draw_scope.hpp"
#include "render/font_atlas.hpp"
#include "render/gpu_caches.hpp"
#include "render/programs.hpp"

namespace rollspin::render {

// What text is drawn with: the text program (Programs::text), the glyph
// stream, and the caches that hold the fonts.
struct TextDrawing {
  Program& text;
  const VertexStreams& streams;
  GpuCaches& caches;
};

// Pixel-space quads (x0, y0, x1, y1, s0, t0, s1, t1) with the text program,
// sampling `atlas` (solid: its colour alone).
void drawQuads(std::span<const GlyphQuad> quads, glm::vec2 viewportSize, const glm::vec4& color, GLuint atlas,
               bool solid, const TextDrawing& with);
// The label's glyph quads in the viewport's pixels (top-left origin) and
// its font (from `caches`); null when a world anchor lies behind the camera.
GpuFont* labelQuads(const LabelItem& label, glm::vec2 viewportSize, const glm::mat4* clipFromWorld,
                    std::vector<GlyphQuad>& quads, GpuCaches& caches);
// A label as `which` takes it, in scope's view (clipFromWorld null: in
// image pixels).
void drawLabelAs(const LabelItem& label, Items which, glm::vec2 viewportSize, const glm::mat4* clipFromWorld,
                 const DrawScope& scope, const TextDrawing& with);
// Image-level labels (titles) over everything, into the framebuffer
// `sceneFbo`, scissored to `clip`.
void drawImageLabels(const DrawList& list, Items which, const PixelRect& clip, GLuint sceneFbo,
                     const TextDrawing& with);
// Where a label can draw, in image pixels (v null: an image-level label):
// for a dynamic label over the layer, only the glyphs after its static part.
PixelRect labelBounds(const LabelItem& l, const DrawList& list, const View* v, const glm::mat4& clipFromWorld,
                      GpuCaches& caches);

}  // namespace rollspin::render
