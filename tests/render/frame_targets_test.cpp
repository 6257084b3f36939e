// The framebuffers a frame draws into (frame_targets.cpp): made anew only
// when the size or the sample count changes, the scene's colour viewed as
// packed words, the resolve's rounded mean of the samples in a rectangle,
// the clear, and the copies of rectangles between targets.
#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <vector>

#include "gl_queries.hpp"
#include "render/frame_targets.hpp"
#include "renderer_fixture.hpp"
#include "support/test_files.hpp"

namespace rollspin::render {
namespace {

DrawList sized(int width, int height) {
  DrawList list;
  list.width = width;
  list.height = height;
  return list;
}

// The scene's colour, bottom row first (GL's order).
std::vector<std::array<std::uint8_t, 4>> sceneColours(const FrameTargets& t) {
  std::vector<std::array<std::uint8_t, 4>> pixels(std::size_t(t.width * t.height));
  TEST_GL(glGetTextureImage)(t.sceneColor, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(pixels.size() * 4), pixels.data());
  return pixels;
}

void clearTo(GLuint fbo, const std::array<float, 4>& colour, float depth) {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glDisable(GL_SCISSOR_TEST);
  glDepthMask(GL_TRUE);
  glClearBufferfv(GL_COLOR, 0, colour.data());
  glClearBufferfv(GL_DEPTH, 0, &depth);
}

TEST_F(GlContextTest, TargetsAreMadeAnewOnlyForANewSizeOrSampleCount) {
  FrameTargets targets;
  EXPECT_TRUE(targets.ensure(32, 16, 4));
  const GLuint scene = targets.sceneFbo, opaque = targets.opaqueFbo;
  EXPECT_NE(scene, 0u);
  EXPECT_NE(opaque, 0u);
  EXPECT_NE(GLuint(targets.resolveFbo), 0u);
  EXPECT_FALSE(targets.ensure(32, 16, 4));
  EXPECT_EQ(GLuint(targets.sceneFbo), scene);
  GLint samples = 0, width = 0;
  TEST_GL(glGetTextureLevelParameteriv)(targets.opaqueColor, 0, GL_TEXTURE_SAMPLES, &samples);
  TEST_GL(glGetTextureLevelParameteriv)(targets.sceneColor, 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(samples, 4);
  EXPECT_EQ(width, 32);

  // One sample: the opaque meshes draw into the scene itself.
  EXPECT_TRUE(targets.ensure(32, 16, 1));
  EXPECT_EQ(GLuint(targets.opaqueFbo), 0u);
  EXPECT_EQ(GLuint(targets.resolveFbo), 0u);
  EXPECT_TRUE(targets.ensure(48, 16, 1));
  TEST_GL(glGetTextureLevelParameteriv)(targets.sceneColor, 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 48);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(GlContextTest, TheScenesPackedViewIsItsColourOneWordAPixelRedInTheLowByte) {
  FrameTargets targets;
  targets.ensure(4, 4, 1);
  clearTo(targets.sceneFbo, {0x11 / 255.0f, 0x22 / 255.0f, 0x33 / 255.0f, 0x44 / 255.0f}, 1.0f);
  std::vector<std::uint32_t> words(16);
  TEST_GL(glGetTextureImage)
  (targets.scenePacked, 0, GL_RED_INTEGER, GL_UNSIGNED_INT, GLsizei(words.size() * 4), words.data());
  EXPECT_EQ(words[0], 0x44332211u);
  EXPECT_EQ(words[15], 0x44332211u);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(GlContextTest, AClearLeavesTransparentBlackAtTheFarPlaneInTheSceneAndOnRequestInTheSamples) {
  FrameTargets targets;
  targets.ensure(8, 8, 4);
  clearTo(targets.sceneFbo, {1, 0, 0, 1}, 0.25f);
  clearTo(targets.opaqueFbo, {0, 1, 0, 1}, 0.25f);
  targets.clear(sized(8, 8), false);
  for (const auto& p : sceneColours(targets)) EXPECT_EQ(p, (std::array<std::uint8_t, 4>{0, 0, 0, 0}));
  float depth = 0.0f;
  glBindFramebuffer(GL_FRAMEBUFFER, targets.sceneFbo);
  glReadPixels(3, 3, 1, 1, GL_DEPTH_COMPONENT, GL_FLOAT, &depth);
  EXPECT_EQ(depth, 1.0f);
  // The samples were left as they were: resolved, they are still green.
  Programs programs{ShaderLibrary{}};
  const VertexStreams streams;
  targets.resolve(sized(8, 8), PixelRect{0, 0, 8, 8}, programs, streams);
  EXPECT_EQ(sceneColours(targets)[0], (std::array<std::uint8_t, 4>{0, 255, 0, 255}));
  targets.clear(sized(8, 8), true);
  targets.resolve(sized(8, 8), PixelRect{0, 0, 8, 8}, programs, streams);
  EXPECT_EQ(sceneColours(targets)[0], (std::array<std::uint8_t, 4>{0, 0, 0, 0}));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// Each sample its own colour (a fragment shader run per sample): the
// resolve writes the rounded mean of each channel, inside its rectangle
// (image pixels, top-left origin) and nowhere else.
TEST_F(GlContextTest, TheResolveWritesTheRoundedMeanOfTheSamplesInItsRectangleOnly) {
  const auto dir = test::freshTempDir("frame_targets_resolve");
  std::ofstream(dir / "full.vert.glsl") << "#version 450 core\nvoid main() {\n"
                                           "  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);\n"
                                           "  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);\n}\n";
  std::ofstream(dir / "per_sample.frag.glsl")
      << "#version 450 core\nout vec4 colour;\nvoid main() {\n  float k = float(gl_SampleID) * 41.0 / 255.0;\n"
         "  colour = vec4(k, 1.0 - k, 0.5, 1.0);\n}\n";
  Program perSample(ShaderLibrary(dir), "full.vert", "per_sample.frag");
  FrameTargets targets;
  targets.ensure(8, 6, 4);
  clearTo(targets.sceneFbo, {0, 0, 1, 1}, 1.0f);
  clearTo(targets.opaqueFbo, {0, 0, 0, 0}, 1.0f);
  glViewport(0, 0, 8, 6);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  const VertexStreams streams;
  glBindVertexArray(streams.empty);
  perSample.use();
  glDrawArrays(GL_TRIANGLES, 0, 3);

  Programs programs{ShaderLibrary{}};
  const PixelRect rect{2, 1, 5, 3};  // columns 2–4, rows 1–2 from the top
  targets.resolve(sized(8, 6), rect, programs, streams);
  const auto pixels = sceneColours(targets);
  // Samples 0, 41, 82, 123 (mean 61.5, rounded up) and their complements to 255.
  // 0.5 is 127.5 in a byte: each sample rounds it alike.
  for (int row = 0; row < 6; ++row)
    for (int x = 0; x < 8; ++x) {
      const int y = 5 - row;  // from the top
      const bool inside = x >= rect.x0 && x < rect.x1 && y >= rect.y0 && y < rect.y1;
      const auto& p = pixels[std::size_t(row * 8 + x)];
      if (inside) {
        EXPECT_EQ(p[0], 62) << x << "," << y;
        EXPECT_EQ(p[1], 194) << x << "," << y;
        EXPECT_NEAR(p[2], 128, 1) << x << "," << y;
        EXPECT_EQ(p[3], 255);
      } else {
        EXPECT_EQ(p, (std::array<std::uint8_t, 4>{0, 0, 255, 255})) << x << "," << y;
      }
    }
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(GlContextTest, CopiedRectanglesCarryColourAndDepthAndNothingAroundThem) {
  FrameTargets targets;
  targets.ensure(8, 8, 1);
  targets.ensureSnapshot();
  const GLuint snapshot = targets.snapshotFbo;
  EXPECT_EQ(GLuint(targets.snapshotSamplesFbo), 0u);  // one sample: no samples to keep
  targets.ensureSnapshot();
  EXPECT_EQ(GLuint(targets.snapshotFbo), snapshot);
  clearTo(targets.sceneFbo, {1, 0, 0, 1}, 0.5f);
  clearTo(targets.snapshotFbo, {0, 0, 1, 1}, 1.0f);
  const DrawList list = sized(8, 8);
  FrameTargets::copyRects(list, targets.sceneFbo, targets.snapshotFbo, {PixelRect{0, 0, 2, 2}, PixelRect{6, 5, 8, 8}});
  std::vector<std::array<std::uint8_t, 4>> pixels(64);
  TEST_GL(glGetTextureImage)(targets.snapshotColor, 0, GL_RGBA, GL_UNSIGNED_BYTE, 64 * 4, pixels.data());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, targets.snapshotFbo);
  std::vector<float> depth(64);
  glReadPixels(0, 0, 8, 8, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
  int copied = 0;
  for (int row = 0; row < 8; ++row)
    for (int x = 0; x < 8; ++x) {
      const int y = 7 - row;
      const bool inside = (x < 2 && y < 2) || (x >= 6 && y >= 5);
      const std::size_t i = std::size_t(row * 8 + x);
      EXPECT_EQ(pixels[i][0], inside ? 255 : 0) << x << "," << y;
      EXPECT_NEAR(depth[i], inside ? 0.5f : 1.0f, 1e-6f) << x << "," << y;
      copied += inside ? 1 : 0;
    }
  EXPECT_EQ(copied, 4 + 6);

  // With samples, the layer keeps them too; a new size makes the snapshot anew.
  targets.ensure(16, 8, 4);
  targets.ensureSnapshot();
  EXPECT_NE(GLuint(targets.snapshotSamplesFbo), 0u);
  GLint width = 0;
  TEST_GL(glGetTextureLevelParameteriv)(targets.snapshotColor, 0, GL_TEXTURE_WIDTH, &width);
  EXPECT_EQ(width, 16);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace
}  // namespace rollspin::render
