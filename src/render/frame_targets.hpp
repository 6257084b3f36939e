// The framebuffers a frame draws into. The static opaque meshes are drawn
// into the scene (a colour texture of one sample, over transparent black),
// and near their edges also into the opaque framebuffer (multisampled; none
// at msaa = 1) and resolved over the scene (resolve); every later step
// draws into the scene with analytic coverage; then it is read back. The
// retained layer keeps a snapshot of both after its static opaque meshes.
// Renderer-internal.
#pragma once

#include <vector>

#include "render/draw_list.hpp"
#include "render/gl_objects.hpp"
#include "render/programs.hpp"
#include "render/screen_bounds.hpp"

namespace rollspin::render {

class FrameTargets {
 public:
  // Made for this size and sample count; true when they were made anew
  // (whatever was drawn for the old ones is gone).
  bool ensure(int width, int height, int samples);
  // The retained layer's snapshot, for the size and samples of ensure.
  void ensureSnapshot();

  // One unscissored clear of the whole scene: llvmpipe does it per tile as
  // the tile is first rasterized; a scissored clear would be a quad draw.
  // The samples too only for a layer, which draws them whole: llvmpipe
  // fills every tile of a cleared buffer, and elsewhere only the tiles near
  // edges are drawn in samples (each cleared with a scissor first).
  void clear(const DrawList& list, bool samplesToo) const;

  // The opaque meshes' samples of `r` (image pixels) averaged into the
  // scene's colour, over what they drew there at one sample. Not their
  // depth: a resolve keeps one sample's, off the pixel centre, where a step
  // at one sample tests its own depth (a small ball would sink into the
  // surface it touches); the scene keeps the depth of the one-sample draw.
  void resolve(const DrawList& list, const PixelRect& r, Programs& programs, const VertexStreams& streams) const;

  // `rects` (image pixels) of `from` blitted into `to`, colour and depth.
  static void copyRects(const DrawList& list, GLuint from, GLuint to, const std::vector<PixelRect>& rects);

  int width = 0, height = 0, samples = 0;
  GlObject sceneFbo, sceneColor, sceneDepth;
  GlObject scenePacked;  // sceneColor viewed as R32UI: one packed RGBA8 word per pixel
  GlObject opaqueFbo, opaqueColor, opaquePacked, opaqueDepth;
  GlObject resolveFbo;  // the scene's colour as packed words (see resolve)
  // The retained layer's: the scene and, when it exists, opaqueFbo.
  GlObject snapshotFbo, snapshotColor, snapshotDepth;
  GlObject snapshotSamplesFbo, snapshotSamplesColor, snapshotSamplesDepth;

 private:
  int snapshotWidth_ = 0, snapshotHeight_ = 0, snapshotSamples_ = 0;
};

}  // namespace rollspin::render
