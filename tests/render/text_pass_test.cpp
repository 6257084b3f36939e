// The text pass (text_pass.cpp): a label's glyph quads placed by its anchor
// and alignment, the pixels it can change (for a dynamic label over a
// layer, only those after its static words), and its draws: quads in a
// viewport, image labels scissored to their clip, a label left out where
// it reaches none of an island's rectangles.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <vector>

#include "gl_queries.hpp"
#include "render/text_pass.hpp"
#include "renderer_fixture.hpp"

namespace rollspin::render {
namespace {

class TextPassTest : public GlContextTest {
 protected:
  void SetUp() override {
    programs_.emplace(ShaderLibrary{});
    streams_.emplace();
    colour_ = GlObject::createTexture(GL_TEXTURE_2D);
    glTextureStorage2D(colour_, 1, GL_RGBA8, kWidth, kHeight);
    fbo_ = makeFramebuffer({{GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colour_}}, kWidth, kHeight, "test target");
    const float white[4] = {1, 1, 1, 1};
    glClearBufferfv(GL_COLOR, 0, white);
    glViewport(0, 0, kWidth, kHeight);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
  }
  void TearDown() override { glBindFramebuffer(GL_FRAMEBUFFER, 0); }
  TextDrawing drawing() { return TextDrawing{programs_->text, *streams_, caches_}; }
  // The image's pixels, top row first, and how many of them are not white.
  std::vector<std::array<std::uint8_t, 4>> pixels() const {
    std::vector<std::array<std::uint8_t, 4>> bottomUp(std::size_t(kWidth * kHeight)), topDown;
    TEST_GL(glGetTextureImage)(colour_, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(bottomUp.size() * 4), bottomUp.data());
    for (int row = kHeight - 1; row >= 0; --row)
      topDown.insert(topDown.end(), bottomUp.begin() + row * kWidth, bottomUp.begin() + (row + 1) * kWidth);
    return topDown;
  }
  // The inked pixels' bounds (image pixels, top-left origin); empty: none.
  PixelRect inked() const {
    PixelRect r{kWidth, kHeight, 0, 0};
    const auto p = pixels();
    for (int y = 0; y < kHeight; ++y)
      for (int x = 0; x < kWidth; ++x)
        if (const auto& c = p[std::size_t(y * kWidth + x)]; std::min({c[0], c[1], c[2]}) < 250)
          r = PixelRect{std::min(r.x0, x), std::min(r.y0, y), std::max(r.x1, x + 1), std::max(r.y1, y + 1)};
    return r.empty() ? PixelRect{} : r;
  }
  static LabelItem label(const char* text, glm::vec2 anchor) {
    LabelItem l;
    l.text = text;
    l.anchor = glm::vec3(anchor, 0.0f);
    l.sizePx = 16.0f;
    return l;
  }
  static constexpr int kWidth = 160, kHeight = 64;
  std::optional<Programs> programs_;
  std::optional<VertexStreams> streams_;
  GpuCaches caches_;
  GlObject colour_, fbo_;
};

TEST_F(TextPassTest, ALabelsAlignmentPutsItsAnchorAtItsStartMiddleOrEnd) {
  std::vector<GlyphQuad> left, centred, right;
  LabelItem l = label("s = 3.78", {80, 32});
  GpuFont* font = labelQuads(l, glm::vec2(kWidth, kHeight), nullptr, left, caches_);
  ASSERT_NE(font, nullptr);
  ASSERT_EQ(left.size(), 6u);  // one quad a glyph, none for the spaces
  l.align = Align::Center;
  (void)labelQuads(l, glm::vec2(kWidth, kHeight), nullptr, centred, caches_);
  l.align = Align::Right;
  (void)labelQuads(l, glm::vec2(kWidth, kHeight), nullptr, right, caches_);
  const float width = font->atlas->layout(l.text, 0.0f, 0.0f, nullptr);
  EXPECT_GT(width, 30.0f);
  // Pens start on whole pixels: each alignment moves every quad alike.
  EXPECT_NEAR(left[0].x0 - centred[0].x0, 0.5f * width, 0.51f);
  EXPECT_NEAR(left[0].x0 - right[0].x0, width, 0.51f);
  for (std::size_t i = 0; i < left.size(); ++i) {
    EXPECT_NEAR(left[i].x1 - left[i].x0, right[i].x1 - right[i].x0, 1e-4f);
    EXPECT_EQ(left[i].y0, right[i].y0);
  }
  // The anchor is the middle of the capital height: a capital straddles it.
  std::vector<GlyphQuad> capital;
  (void)labelQuads(label("H", {80, 32}), glm::vec2(kWidth, kHeight), nullptr, capital, caches_);
  ASSERT_EQ(capital.size(), 1u);
  EXPECT_NEAR(0.5f * (capital[0].y0 + capital[0].y1), 32.0f, 2.0f);
}

TEST_F(TextPassTest, AWorldAnchoredLabelSitsWhereItsAnchorProjectsAndNotBehindTheCamera) {
  const View v = cameraView(kWidth, kHeight);
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  LabelItem l = label("H", {0, 0});
  l.worldAnchored = true;
  l.align = Align::Center;
  l.offsetPx = {10.0f, -4.0f};  // after projection, +y down
  std::vector<GlyphQuad> quads;
  ASSERT_NE(labelQuads(l, glm::vec2(kWidth, kHeight), &clipFromWorld, quads, caches_), nullptr);
  ASSERT_EQ(quads.size(), 1u);
  EXPECT_NEAR(0.5f * (quads[0].x0 + quads[0].x1), 80.0f + 10.0f, 1.5f);
  EXPECT_NEAR(0.5f * (quads[0].y0 + quads[0].y1), 32.0f - 4.0f, 2.0f);
  l.anchor = {0, 0, 6};  // the camera is at z = 5, looking down −z
  EXPECT_EQ(labelQuads(l, glm::vec2(kWidth, kHeight), &clipFromWorld, quads, caches_), nullptr);
}

TEST_F(TextPassTest, SolidQuadsFillTheirPixelsWithTheirColour) {
  const std::vector<GlyphQuad> quads{{10, 8, 30, 20, 0, 0, 1, 1}, {100, 40, 104, 60, 0, 0, 1, 1}};
  drawQuads(quads, glm::vec2(kWidth, kHeight), glm::vec4(1.0f, 0.0f, 0.0f, 1.0f), 0, true, drawing());
  const auto p = pixels();
  EXPECT_EQ(p[std::size_t(14 * kWidth + 20)], (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
  EXPECT_EQ(p[std::size_t(50 * kWidth + 101)], (std::array<std::uint8_t, 4>{255, 0, 0, 255}));
  EXPECT_EQ(p[std::size_t(30 * kWidth + 60)], (std::array<std::uint8_t, 4>{255, 255, 255, 255}));
  EXPECT_EQ(inked(), (PixelRect{10, 8, 104, 60}));
}

// A label inks only within the pixels labelBounds gives it; an image-level
// label draws only inside its clip.
TEST_F(TextPassTest, ImageLabelsInkWithinTheirBoundsAndTheirClip) {
  DrawList list;
  list.width = kWidth;
  list.height = kHeight;
  list.labels = {label("Rolling sphere", {12, 30})};
  const PixelRect bounds = labelBounds(list.labels[0], list, nullptr, glm::mat4(1.0f), caches_);
  drawImageLabels(list, Items::All, PixelRect{0, 0, kWidth, kHeight}, fbo_, drawing());
  const PixelRect whole = inked();
  ASSERT_FALSE(whole.empty());
  EXPECT_GE(whole.x0, bounds.x0);
  EXPECT_GE(whole.y0, bounds.y0);
  EXPECT_LE(whole.x1, bounds.x1);
  EXPECT_LE(whole.y1, bounds.y1);
  EXPECT_LE(whole.x0, 14);
  EXPECT_GT(whole.x1 - whole.x0, 60);

  const float white[4] = {1, 1, 1, 1};
  glDisable(GL_SCISSOR_TEST);
  glClearBufferfv(GL_COLOR, 0, white);
  drawImageLabels(list, Items::All, PixelRect{40, 0, 60, kHeight}, fbo_, drawing());
  const PixelRect clipped = inked();
  EXPECT_GE(clipped.x0, 40);
  EXPECT_LE(clipped.x1, 60);
  EXPECT_FALSE(clipped.empty());
  // A label of a view is not an image label.
  glDisable(GL_SCISSOR_TEST);
  glClearBufferfv(GL_COLOR, 0, white);
  list.labels[0].view = 0;
  drawImageLabels(list, Items::All, PixelRect{0, 0, kWidth, kHeight}, fbo_, drawing());
  EXPECT_TRUE(inked().empty());
}

// Over a layer, a dynamic label "s = 3.78" keeps "s =" in the layer: it
// changes only the pixels after them; the layer's static items draw that
// part alone, a frame's dynamic items the whole label.
TEST_F(TextPassTest, ADynamicLabelsStaticWordsStayInTheLayer) {
  DrawList list;
  list.width = kWidth;
  list.height = kHeight;
  LabelItem l = label("s = 3.78", {10, 30});
  l.dynamic = true;
  l.staticPrefixBytes = 4;
  list.labels = {l};
  const PixelRect changing = labelBounds(l, list, nullptr, glm::mat4(1.0f), caches_);
  LabelItem whole = l;
  whole.dynamic = false;
  const PixelRect all = labelBounds(whole, list, nullptr, glm::mat4(1.0f), caches_);
  EXPECT_GT(changing.x0, all.x0 + 10);
  EXPECT_EQ(changing.x1, all.x1);

  drawImageLabels(list, Items::StaticOnly, PixelRect{0, 0, kWidth, kHeight}, fbo_, drawing());
  const PixelRect staticInk = inked();
  ASSERT_FALSE(staticInk.empty());
  EXPECT_LT(staticInk.x1, changing.x0 + 3);  // "s =" only
  const float white[4] = {1, 1, 1, 1};
  glDisable(GL_SCISSOR_TEST);
  glClearBufferfv(GL_COLOR, 0, white);
  drawImageLabels(list, Items::DynamicOnly, PixelRect{0, 0, kWidth, kHeight}, fbo_, drawing());
  EXPECT_GT(inked().x1, changing.x0 + 10);
}

TEST_F(TextPassTest, OverALayerALabelThatReachesNoRedrawnRectangleIsNotDrawn) {
  View v = cameraView(kWidth, kHeight);
  const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
  LabelItem l = label("far away", {8, 12});
  l.view = 0;
  const std::vector<PixelRect> elsewhere{{120, 40, 150, 60}}, here{{0, 0, 40, 30}};
  DrawScope scope;
  scope.view = &v;
  scope.clipFromWorld = clipFromWorld;
  scope.clips = &elsewhere;
  drawLabelAs(l, Items::All, glm::vec2(kWidth, kHeight), &clipFromWorld, scope, drawing());
  EXPECT_TRUE(inked().empty());
  scope.clips = &here;  // the pass draws it whole: the composite keeps only the rectangles
  drawLabelAs(l, Items::All, glm::vec2(kWidth, kHeight), &clipFromWorld, scope, drawing());
  EXPECT_GT(inked().x1, 40);
}

}  // namespace
}  // namespace rollspin::render
