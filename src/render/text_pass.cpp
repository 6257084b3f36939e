// Text: labels as glyph quads from a font atlas (font_atlas.hpp), in a
// view's pixels or the image's, and the inset frame as solid quads.
#include "render/text_pass.hpp"

#include <algorithm>
#include <cmath>

#include "render/layer_key.hpp"

namespace rollspin::render {

namespace {

// The pixels glyph quads (relative to a view at ox, oy) can touch, with a
// margin for their filtered edges.
PixelRect glyphBounds(std::span<const GlyphQuad> quads, int ox, int oy) {
  float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
  for (const GlyphQuad& q : quads) {
    x0 = std::min({x0, q.x0, q.x1}), x1 = std::max({x1, q.x0, q.x1});
    y0 = std::min({y0, q.y0, q.y1}), y1 = std::max({y1, q.y0, q.y1});
  }
  auto toInt = [](float f) { return static_cast<int>(std::clamp(f, -1e7f, 1e7f)); };
  return PixelRect{ox + toInt(std::floor(x0)) - 2, oy + toInt(std::floor(y0)) - 2, ox + toInt(std::ceil(x1)) + 3,
                   oy + toInt(std::ceil(y1)) + 3};
}

}  // namespace

void drawQuads(std::span<const GlyphQuad> quads, glm::vec2 viewportSize, const glm::vec4& color, GLuint atlas,
               bool solid, const TextDrawing& with) {
  if (quads.empty()) return;
  std::vector<float> data;
  data.reserve(quads.size() * 24);
  for (const GlyphQuad& q : quads) {
    const float v[6][4] = {{q.x0, q.y0, q.s0, q.t0}, {q.x0, q.y1, q.s0, q.t1}, {q.x1, q.y1, q.s1, q.t1},
                           {q.x0, q.y0, q.s0, q.t0}, {q.x1, q.y1, q.s1, q.t1}, {q.x1, q.y0, q.s1, q.t0}};
    for (const auto& vert : v) data.insert(data.end(), vert, vert + 4);
  }
  Program& text = with.text;
  text.use();
  text.set("viewportSize", viewportSize);
  text.set("textColor", color);
  text.set("solid", solid ? 1 : 0);
  text.set("glyphAtlas", 0);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D, atlas);
  with.streams.uploadGlyphs(data);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(quads.size() * 6));
}

GpuFont* labelQuads(const LabelItem& label, glm::vec2 viewportSize, const glm::mat4* clipFromWorld,
                    std::vector<GlyphQuad>& quads, GpuCaches& caches) {
  glm::vec2 pen(label.anchor.x, label.anchor.y);
  if (label.worldAnchored && clipFromWorld != nullptr) {
    const glm::vec4 c = *clipFromWorld * glm::vec4(label.anchor, 1.0f);
    if (c.w <= 0.0f) return nullptr;
    pen = glm::vec2((c.x / c.w * 0.5f + 0.5f) * viewportSize.x, (0.5f - c.y / c.w * 0.5f) * viewportSize.y);
  }
  pen += label.offsetPx;
  GpuFont& f = caches.font(label.sizePx, label.bold);
  const float width = f.atlas->layout(label.text, 0.0f, 0.0f, nullptr);
  if (label.align == Align::Center) pen.x -= 0.5f * width;
  if (label.align == Align::Right) pen.x -= width;
  // Anchor = the middle of the capital height, which centres labels on points.
  const float baseline = pen.y + 0.36f * f.atlas->pixelHeight();
  quads.clear();
  f.atlas->layout(label.text, std::round(pen.x), std::round(baseline), &quads);
  return &f;
}

// A label as `which` takes it. A layer's static items take the static
// part of a dynamic label (its leading words); everything else draws a
// label whole, in one draw, as a still does. Over a retained layer
// (scope.clips), a label whose glyphs reach none of the island's
// rectangles is not drawn: it could change only pixels that are not read
// back (each label is a draw of its own, with its vertices uploaded; a
// frame has about twenty).
void drawLabelAs(const LabelItem& label, Items which, glm::vec2 viewportSize, const glm::mat4* clipFromWorld,
                 const DrawScope& scope, const TextDrawing& with) {
  auto draw = [&](const LabelItem& l) {
    std::vector<GlyphQuad> quads;
    GpuFont* f = labelQuads(l, viewportSize, clipFromWorld, quads, with.caches);
    if (f == nullptr || quads.empty()) return;
    if (scope.clips != nullptr && !reachesAny(*scope.clips, glyphBounds(quads, scope.view->x, scope.view->y))) return;
    drawQuads(quads, viewportSize, l.color, f->texture, false, with);
  };
  if (which == Items::StaticOnly) {
    if (const auto part = staticPartOf(label)) draw(*part);
  } else if (takes(which, label.dynamic)) {
    draw(label);
  }
}

void drawImageLabels(const DrawList& list, Items which, const PixelRect& clip, GLuint sceneFbo,
                     const TextDrawing& with) {
  glBindFramebuffer(GL_FRAMEBUFFER, sceneFbo);
  glEnable(GL_SCISSOR_TEST);
  glScissor(clip.x0, list.height - clip.y1, clip.x1 - clip.x0, clip.y1 - clip.y0);
  glViewport(0, 0, list.width, list.height);
  glDisable(GL_DEPTH_TEST);
  glEnable(GL_BLEND);
  glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  for (const LabelItem& l : list.labels)
    if (l.view < 0) drawLabelAs(l, which, glm::vec2(list.width, list.height), nullptr, DrawScope{}, with);
}

PixelRect labelBounds(const LabelItem& l, const DrawList& list, const View* v, const glm::mat4& clipFromWorld,
                      GpuCaches& caches) {
  const glm::vec2 size = v != nullptr ? glm::vec2(v->width, v->height) : glm::vec2(list.width, list.height);
  const glm::mat4* clip = v != nullptr ? &clipFromWorld : nullptr;
  std::vector<GlyphQuad> quads;
  if (labelQuads(l, size, clip, quads, caches) == nullptr || quads.empty()) return {};
  // A dynamic label's static part is in the layer: only the glyphs after
  // it change (the part's glyphs are the label's first ones).
  std::size_t first = 0;
  if (l.dynamic)
    if (const auto part = staticPartOf(l)) {
      std::vector<GlyphQuad> partQuads;
      if (labelQuads(*part, size, clip, partQuads, caches) != nullptr) first = partQuads.size();
    }
  if (first >= quads.size()) return {};
  const PixelRect area = v != nullptr ? PixelRect{v->x, v->y, v->x + v->width, v->y + v->height}
                                      : PixelRect{0, 0, list.width, list.height};
  return intersect(glyphBounds(std::span(quads).subspan(first), v != nullptr ? v->x : 0, v != nullptr ? v->y : 0),
                   area);
}

}  // namespace rollspin::render
