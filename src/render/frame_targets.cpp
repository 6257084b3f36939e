#include "render/frame_targets.hpp"

#include <fmt/format.h>

namespace rollspin::render {

namespace {

GlObject textureOf(GLenum target) {
  GlObject t = GlObject::generate(GlKind::Texture);
  glBindTexture(target, t);
  return t;
}

GlObject renderbuffer(int samples, GLenum format, int w, int h) {
  GlObject rb = GlObject::generate(GlKind::Renderbuffer);
  glBindRenderbuffer(GL_RENDERBUFFER, rb);
  if (samples > 0) glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, format, w, h);
  else glRenderbufferStorage(GL_RENDERBUFFER, format, w, h);
  return rb;
}

}  // namespace

bool FrameTargets::ensure(int w, int h, int s) {
  if (w == width && h == height && s == samples) return false;
  for (GlObject* o : {&sceneFbo, &opaqueFbo, &resolveFbo, &sceneDepth, &opaqueDepth, &scenePacked, &sceneColor,
                      &opaquePacked, &opaqueColor})
    o->reset();
  const std::string what = fmt::format("framebuffer with {} samples", s);
  // The scene has one sample; its colour is a texture so that the resolve
  // pass can write it as packed words.
  sceneColor = textureOf(GL_TEXTURE_2D);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, w, h);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  scenePacked = GlObject::generate(GlKind::Texture);
  glTextureView(scenePacked, GL_TEXTURE_2D, sceneColor, GL_R32UI, 0, 1, 0, 1);
  // An integer texture with the default LINEAR filter is incomplete and
  // texelFetch returns 0.
  glBindTexture(GL_TEXTURE_2D, scenePacked);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  sceneDepth = renderbuffer(0, GL_DEPTH_COMPONENT24, w, h);
  sceneFbo = makeFramebuffer(
      {{GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, sceneColor}, {GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, sceneDepth}}, w, h,
      what);
  if (s > 1) {
    // A texture, viewed as packed words by the resolve pass.
    opaqueColor = textureOf(GL_TEXTURE_2D_MULTISAMPLE);
    glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, s, GL_RGBA8, w, h, GL_TRUE);
    opaquePacked = GlObject::generate(GlKind::Texture);
    glTextureView(opaquePacked, GL_TEXTURE_2D_MULTISAMPLE, opaqueColor, GL_R32UI, 0, 1, 0, 1);
    opaqueDepth = renderbuffer(s, GL_DEPTH_COMPONENT24, w, h);
    opaqueFbo = makeFramebuffer({{GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, opaqueColor},
                                 {GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, opaqueDepth}},
                                w, h, what);
    // The scene's colour as packed words, written by the resolve pass.
    resolveFbo = makeFramebuffer({{GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, scenePacked}}, w, h, what);
  }
  width = w;
  height = h;
  samples = s;
  return true;
}

void FrameTargets::ensureSnapshot() {
  if (snapshotWidth_ == width && snapshotHeight_ == height && snapshotSamples_ == samples) return;
  for (GlObject* o : {&snapshotFbo, &snapshotColor, &snapshotDepth, &snapshotSamplesFbo, &snapshotSamplesColor,
                      &snapshotSamplesDepth})
    o->reset();
  const std::string what = fmt::format("retained layer with {} samples", samples);
  snapshotColor = textureOf(GL_TEXTURE_2D);
  glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, width, height);
  snapshotDepth = renderbuffer(0, GL_DEPTH_COMPONENT24, width, height);
  snapshotFbo = makeFramebuffer(
      {{GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, snapshotColor}, {GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, snapshotDepth}},
      width, height, what);
  if (opaqueFbo != 0) {
    snapshotSamplesColor = renderbuffer(samples, GL_RGBA8, width, height);
    snapshotSamplesDepth = renderbuffer(samples, GL_DEPTH_COMPONENT24, width, height);
    snapshotSamplesFbo = makeFramebuffer({{GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, snapshotSamplesColor},
                                          {GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, snapshotSamplesDepth}},
                                         width, height, what);
  }
  snapshotWidth_ = width;
  snapshotHeight_ = height;
  snapshotSamples_ = samples;
}

void FrameTargets::clear(const DrawList& list, bool samplesToo) const {
  glDisable(GL_SCISSOR_TEST);
  glViewport(0, 0, list.width, list.height);
  glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
  glDepthMask(GL_TRUE);
  for (const GLuint fbo : {samplesToo ? GLuint(opaqueFbo) : 0u, GLuint(sceneFbo)}) {
    if (fbo == 0) continue;
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  }
}

void FrameTargets::resolve(const DrawList& list, const PixelRect& r, Programs& programs,
                           const VertexStreams& streams) const {
  if (opaqueFbo == 0) return;
  glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo);
  glViewport(0, 0, list.width, list.height);
  glEnable(GL_SCISSOR_TEST);
  glScissor(r.x0, list.height - r.y1, r.x1 - r.x0, r.y1 - r.y0);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glDisable(GL_CULL_FACE);
  glActiveTexture(GL_TEXTURE0);
  glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, opaquePacked);
  Program& resolver = programs.resolve(samples);
  resolver.use();
  resolver.set("samples", 0);
  glBindVertexArray(streams.empty);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  glEnable(GL_DEPTH_TEST);
}

void FrameTargets::copyRects(const DrawList& list, GLuint from, GLuint to, const std::vector<PixelRect>& rects) {
  glDisable(GL_SCISSOR_TEST);
  glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
  for (const PixelRect& r : rects) {
    const int y0 = list.height - r.y1, y1 = list.height - r.y0;
    glBlitFramebuffer(r.x0, y0, r.x1, y1, r.x0, y0, r.x1, y1, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
  }
}

}  // namespace rollspin::render
