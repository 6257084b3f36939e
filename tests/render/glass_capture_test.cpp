// The glass capture (glass_capture.cpp): a translucent ray-cast sphere's
// fragments captured once over its rectangle, kept while its inputs stay
// the same (the newest four), and the GL state around it left as it was.
#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <array>
#include <optional>
#include <vector>

#include "gl_queries.hpp"
#include "render/glass_capture.hpp"
#include "renderer_fixture.hpp"

namespace rollspin::render {
namespace {

class GlassCaptureTest : public GlContextTest {
 protected:
  void SetUp() override {
    view_ = cameraView(kWidth, kHeight);
    scope_.view = &view_;
    scope_.clipFromWorld = view_.camera.clipFromView * view_.camera.viewFromWorld;
    glass_.opacity = 0.35f;
    glass_.color = {0.3f, 0.6f, 0.9f};
    programs_.emplace(ShaderLibrary{});
    streams_.emplace();
    glBindVertexArray(streams_->empty);  // as SpherePass::draw leaves it: the impostor's triangle is made in its shader
  }
  void TearDown() override { glBindVertexArray(0); }
  Drawable sphereAt(const glm::vec3& centre, float radius) const {
    return Drawable{uvSphere(16, 8), glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(radius)), &glass_};
  }
  const SphereCapture& capture(const Drawable& d) {
    const std::optional<PixelRect> rect = sphereBounds(view_, glm::vec3(d.worldFromModel[3]),
                                                       glm::length(glm::vec3(d.worldFromModel[0])), kImpostorMarginPx);
    EXPECT_TRUE(rect.has_value());
    return captures_.of(d, *rect, 0, glm::inverse(scope_.clipFromWorld), glm::vec4(0, 0, kWidth, kHeight), scope_,
                        kHeight, *programs_, stats_);
  }
  static constexpr int kWidth = 96, kHeight = 64;
  View view_;
  DrawScope scope_;
  Material glass_;
  std::optional<Programs> programs_;
  std::optional<VertexStreams> streams_;
  SphereCaptures captures_;
  RenderStats stats_;
};

TEST_F(GlassCaptureTest, ASphereIsCapturedOnceWhileItsInputsStayTheSame) {
  const Drawable d = sphereAt({0.2f, -0.1f, 0.0f}, 0.8f);
  const SphereCapture& first = capture(d);
  EXPECT_EQ(stats_.sphereCaptures, 1);
  EXPECT_EQ(&capture(d), &first);
  EXPECT_EQ(stats_.sphereCaptures, 1);
  // Texel (0, 0) lies on an even pixel: the capture's 2×2 quads are the frame's.
  EXPECT_EQ(first.originX % 2, 0);
  EXPECT_EQ(first.originY % 2, 0);
  // Anything its fragments read changes it: the light, the material, the place.
  view_.light.towardLight = glm::vec3(0.0f, 1.0f, 0.2f);
  (void)capture(d);
  EXPECT_EQ(stats_.sphereCaptures, 2);
  glass_.opacity = 0.5f;
  (void)capture(d);
  EXPECT_EQ(stats_.sphereCaptures, 3);
  (void)capture(sphereAt({0.0f, 0.0f, 0.0f}, 0.8f));
  EXPECT_EQ(stats_.sphereCaptures, 4);
}

TEST_F(GlassCaptureTest, TheNewestFourAreKept) {
  std::vector<Drawable> spheres;
  for (int i = 0; i < 5; ++i) spheres.push_back(sphereAt({0.1f * float(i), 0.0f, 0.0f}, 0.6f));
  for (int i = 0; i < 4; ++i) (void)capture(spheres[std::size_t(i)]);
  (void)capture(spheres[0]);
  EXPECT_EQ(stats_.sphereCaptures, 4);  // all four still there
  (void)capture(spheres[4]);            // the fifth pushes out the oldest
  (void)capture(spheres[1]);
  EXPECT_EQ(stats_.sphereCaptures, 5);
  (void)capture(spheres[0]);
  EXPECT_EQ(stats_.sphereCaptures, 6);
  captures_.clear();
  (void)capture(spheres[4]);
  EXPECT_EQ(stats_.sphereCaptures, 7);
}

// The colour mesh.frag gives each pixel before blending (alpha: the glass's
// opacity) and its depth, and outside the silhouette nothing (depth −1).
TEST_F(GlassCaptureTest, TheCaptureHoldsTheSpheresFragmentsAndNothingOutsideIt) {
  const Drawable d = sphereAt({0.0f, 0.0f, 0.0f}, 0.9f);
  const SphereCapture& c = capture(d);
  GLint width = 0, height = 0;
  TEST_GL(glGetTextureLevelParameteriv)(c.color, 0, GL_TEXTURE_WIDTH, &width);
  TEST_GL(glGetTextureLevelParameteriv)(c.color, 0, GL_TEXTURE_HEIGHT, &height);
  ASSERT_GT(width, 0);
  ASSERT_GT(height, 0);
  std::vector<glm::vec4> colour(std::size_t(width * height));
  std::vector<float> depth(std::size_t(width * height));
  TEST_GL(glGetTextureImage)(c.color, 0, GL_RGBA, GL_FLOAT, GLsizei(colour.size() * sizeof(glm::vec4)), colour.data());
  TEST_GL(glGetTextureImage)(c.depth, 0, GL_RED, GL_FLOAT, GLsizei(depth.size() * sizeof(float)), depth.data());
  // The sphere's centre is the view's centre pixel.
  const int cx = kWidth / 2 - c.originX, cy = kHeight / 2 - c.originY;
  ASSERT_TRUE(cx >= 0 && cx < width && cy >= 0 && cy < height);
  const std::size_t centre = std::size_t(cy * width + cx);
  EXPECT_NEAR(colour[centre].a, 0.35f, 1e-3f);
  EXPECT_GT(colour[centre].b, colour[centre].r);  // bluish glass
  EXPECT_GT(depth[centre], 0.0f);
  EXPECT_LT(depth[centre], 1.0f);
  EXPECT_EQ(depth[0], -1.0f);  // a corner of its rectangle
  EXPECT_EQ(colour[0], glm::vec4(0.0f));
  int inside = 0;
  for (const float z : depth) inside += z >= 0.0f ? 1 : 0;
  // The silhouette: a disc of the projected radius, here about 13 pixels.
  const float projected = 0.9f / 5.0f / std::tan(glm::radians(20.0f)) * 0.5f * float(kHeight);
  EXPECT_NEAR(double(inside), 3.14159 * projected * projected, 0.15 * 3.14159 * projected * projected);
}

TEST_F(GlassCaptureTest, TheGlStateAroundACaptureIsLeftAsItWas) {
  GlObject target = GlObject::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(target, 1, GL_RGBA8, kWidth, kHeight);
  const GlObject fbo = makeFramebuffer({{GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target}}, kWidth, kHeight, "test target");
  glViewport(3, 5, 40, 30);
  glScissor(1, 2, 7, 9);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_BLEND);
  glDisable(GL_DEPTH_TEST);
  (void)capture(sphereAt({0.0f, 0.0f, 0.0f}, 0.5f));
  GLint bound = 0;
  std::array<GLint, 4> viewport{}, scissor{};
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &bound);
  glGetIntegerv(GL_VIEWPORT, viewport.data());
  glGetIntegerv(GL_SCISSOR_BOX, scissor.data());
  EXPECT_EQ(GLuint(bound), GLuint(fbo));
  EXPECT_EQ(viewport, (std::array<GLint, 4>{3, 5, 40, 30}));
  EXPECT_EQ(scissor, (std::array<GLint, 4>{1, 2, 7, 9}));
  EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
  EXPECT_TRUE(glIsEnabled(GL_BLEND));
  EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
  // And the other way round.
  glDisable(GL_SCISSOR_TEST);
  glDisable(GL_BLEND);
  glEnable(GL_DEPTH_TEST);
  (void)capture(sphereAt({0.1f, 0.0f, 0.0f}, 0.5f));
  EXPECT_FALSE(glIsEnabled(GL_SCISSOR_TEST));
  EXPECT_FALSE(glIsEnabled(GL_BLEND));
  EXPECT_TRUE(glIsEnabled(GL_DEPTH_TEST));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

}  // namespace
}  // namespace rollspin::render
