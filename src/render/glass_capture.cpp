// The glass capture and its replay (see glass_capture.hpp).
#include "render/glass_capture.hpp"

#include "render/sphere_pass.hpp"

namespace rollspin::render {

// Drawn into its own framebuffer, as SpherePass::draw draws it, with texel
// (0, 0) at an even window pixel: the derivatives pair the pixels of the
// same 2×2 quads. (Binding that framebuffer makes llvmpipe run the scene
// binned so far: once per layer.) The GL state it changes is put back.
const SphereCapture& SphereCaptures::of(const Drawable& d, const PixelRect& rect, int pattern,
                                        const glm::mat4& worldFromClip, const glm::vec4& viewport,
                                        const DrawScope& scope, int fbHeight, Programs& programs, RenderStats& stats) {
  const View& v = *scope.view;
  SphereInputs inputs{d.worldFromModel,
                      scope.clipFromWorld,
                      glm::normalize(v.light.towardLight),
                      v.light.color,
                      v.camera.position,
                      v.light.ambient,
                      viewport,
                      rect,
                      *d.material};
  for (const SphereCapture& c : captures_)
    if (c.inputs == inputs) return c;
  if (captures_.size() == kKept) captures_.pop_front();
  SphereCapture& c = captures_.emplace_back(SphereCapture{std::move(inputs), {}, {}, {}});
  c.originX = rect.x0 & ~1;
  c.originY = (fbHeight - rect.y1) & ~1;
  const int width = rect.x1 - c.originX, height = fbHeight - rect.y0 - c.originY;
  // Made without binding: the active unit holds the sphere's own texture.
  for (const auto& [texture, format] : {std::pair{&c.color, GL_RGBA32F}, std::pair{&c.depth, GL_R32F}}) {
    *texture = GlObject::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(*texture, 1, format, width, height);
    glTextureParameteri(*texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTextureParameteri(*texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  }
  GLint drawFbo = 0, viewportBox[4], scissorBox[4];
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
  glGetIntegerv(GL_VIEWPORT, viewportBox);
  glGetIntegerv(GL_SCISSOR_BOX, scissorBox);
  const bool scissored = glIsEnabled(GL_SCISSOR_TEST), blended = glIsEnabled(GL_BLEND),
             depthTested = glIsEnabled(GL_DEPTH_TEST);
  c.fbo =
      makeFramebuffer({{GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, c.color}, {GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, c.depth}},
                      width, height, "float framebuffer");
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f}, noDepth[4] = {-1.0f, 0.0f, 0.0f, 0.0f};
  glClearBufferfv(GL_COLOR, 0, none);
  glClearBufferfv(GL_COLOR, 1, noDepth);
  const glm::vec4 shifted = viewport - glm::vec4(float(c.originX), float(c.originY), 0.0f, 0.0f);
  glViewport(int(shifted.x), int(shifted.y), int(shifted.z), int(shifted.w));
  const Material& m = *d.material;
  Program& program = programs.mesh(pattern, false, m.lit, m.specular > 0.0f, 1, false, true);
  program.use();
  setMeshUniforms(program, d, scope, false);
  program.set("worldFromClip", worldFromClip);
  program.set("viewportRect", shifted);
  program.set("ndcDepth", 0.0f);
  glEnable(GL_SCISSOR_TEST);
  for (const PixelRect& band :
       sphereBands(v, rect, glm::vec3(d.worldFromModel[3]), glm::length(glm::vec3(d.worldFromModel[0])),
                   kImpostorMarginPx, kImpostorBandRows)) {
    glScissor(band.x0 - c.originX, fbHeight - band.y1 - c.originY, band.x1 - band.x0, band.y1 - band.y0);
    program.set("ndcRect", ndcRectOf(v, band));
    glDrawArrays(GL_TRIANGLES, 0, 3);
  }
  ++stats.sphereCaptures;
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(drawFbo));
  glViewport(viewportBox[0], viewportBox[1], viewportBox[2], viewportBox[3]);
  glScissor(scissorBox[0], scissorBox[1], scissorBox[2], scissorBox[3]);
  if (!scissored) glDisable(GL_SCISSOR_TEST);
  if (blended) glEnable(GL_BLEND);
  if (depthTested) glEnable(GL_DEPTH_TEST);
  return c;
}

// The sphere's parts (parts_, see SpherePass::draw) from its capture: two
// triangles a part, two texel fetches a pixel.
void SpherePass::replayCaptured(const Drawable& d, const DrawScope& scope, const PixelRect& rect, int pattern,
                                const glm::mat4& worldFromClip, const glm::vec4& viewport, const SphereDrawing& with) {
  const int fbHeight = with.fbHeight;
  const SphereCapture& capture =
      with.captures.of(d, rect, pattern, worldFromClip, viewport, scope, fbHeight, with.programs, with.stats);
  glBindTextureUnit(2, capture.color);
  glBindTextureUnit(3, capture.depth);
  Program& replay = with.programs.sphereReplay;
  replay.use();
  replay.set("capturedColor", 2);
  replay.set("capturedDepth", 3);
  replay.set("captureOrigin", glm::ivec2(capture.originX, capture.originY));
  replay.set("viewportRect", viewport);
  std::vector<glm::vec3>& corners = replayCorners_;
  corners.clear();
  for (const PixelRect& p : parts_) {
    const float x0 = float(p.x0), x1 = float(p.x1), y0 = float(fbHeight - p.y1), y1 = float(fbHeight - p.y0);
    for (const glm::vec2 corner : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y0),
                                   glm::vec2(x1, y1), glm::vec2(x0, y1)})
      corners.emplace_back(corner, 0.0f);
  }
  with.streams.uploadPoints(corners);
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(corners.size()));
  ++with.stats.sphereReplays;
}

}  // namespace rollspin::render
