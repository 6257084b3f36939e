// Text never covers the story: for every scene in scenes/ at 16:9, 4:3, 1:1
// and 9:16 (and 16:9 with the twin as an inset), with labels, facts, captions and titles on, at sampled frames of
// the clip, the screen-anchored text (each label's box from the font's
// advances) lies inside its view and clear of the ball's disc, the contact
// path and the trails, all projected from the DrawList itself, and not
// under an inset view. And the default camera keeps the ball's disc inside
// the frame and, outside a sphere, ≥ 90 % of it in sight by rays against the
// exact sphere (every surface kind is measured from pixels in
// ball_in_sight_test).
#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "draw/clip_layout.hpp"
#include "draw/draw_style.hpp"
#include "draw/scene_drawer.hpp"
#include "draw/text_blocks.hpp"
#include "jobs/render_jobs.hpp"
#include "model/rolling_model.hpp"
#include "support/cli_runner.hpp"
#include "support/sweep.hpp"

namespace rollspin::draw {
namespace {
using namespace rollspin::model;
using namespace rollspin::motion;

struct Box {
  glm::vec2 lo, hi;
};

struct Screen {
  const render::View& v;
  glm::mat4 clipFromWorld;
  explicit Screen(const render::View& view)
      : v(view), clipFromWorld(view.camera.clipFromView * view.camera.viewFromWorld) {}
  // View pixels (y down); w ≤ 0 behind the eye.
  glm::vec3 project(const glm::vec3& p) const {
    const glm::vec4 c = clipFromWorld * glm::vec4(p, 1.0f);
    return {(c.x / c.w * 0.5f + 0.5f) * float(v.width), (0.5f - c.y / c.w * 0.5f) * float(v.height), c.w};
  }
};

// The renderer puts the anchor at the middle of the capital height: the
// ascender reaches 0.45 em above it, the descender 0.62 em below.
Box labelBox(const render::LabelItem& l) {
  const float width = textWidthPx(l.text, l.sizePx, l.bold);
  float x = l.anchor.x + l.offsetPx.x;
  if (l.align == render::Align::Center) x -= 0.5f * width;
  if (l.align == render::Align::Right) x -= width;
  const float y = l.anchor.y + l.offsetPx.y;
  return {{x, y - 0.45f * l.sizePx}, {x + width, y + 0.62f * l.sizePx}};
}

bool inside(const Box& b, glm::vec2 p) { return p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y; }

float distanceTo(const Box& b, glm::vec2 p) {
  const glm::vec2 q = glm::clamp(p, b.lo, b.hi);
  return glm::length(p - q);
}

bool sameRgb(const glm::vec4& a, const glm::vec3& b) { return glm::length(glm::vec3(a) - b) < 1e-4f; }

// The polylines that carry the story: the contact path (whole and
// travelled), the marker's trail, the plate's trail, the twin's trails.
bool isStoryLine(const render::PolylineItem& p) {
  for (const glm::vec4& c :
       {kPathLineColor, kTravelledColor, kMarkerTrailColor, kPlateTrailColor, kBlochTrailColor, kFieldTrailColor})
    if (sameRgb(p.color, glm::vec3(c))) return true;
  return false;
}

struct Aspect {
  int width, height;
  const char* name;
  const char* layout = nullptr;  // else the scene's own
};

TEST(ClipLayout, NoTextOverTheBallThePathOrTheTrailsAndNoneCutByTheFrame) {
  const Aspect aspects[] = {
      {960, 540, "16:9"}, {720, 540, "4:3"}, {600, 600, "1:1"}, {540, 960, "9:16"}, {960, 540, "16:9 inset", "inset"}};
  ASSERT_GE(test::bundledSceneFiles().size(), 15u);
  int checkedLabels = 0, checkedBalls = 0;
  for (const auto& file : test::sweep(test::bundledSceneFiles())) {
    for (const Aspect& a : aspects) {
      std::vector<std::string> overrides{"render.width=" + std::to_string(a.width),
                                         "render.height=" + std::to_string(a.height), "render.labels=true"};
      if (a.layout) overrides.push_back(std::string("render.layout=\"") + a.layout + "\"");
      const scene::SceneSpec spec = loadScene(file.string(), overrides);
      const RollingModel model = buildSceneModel(spec);
      const SceneDrawer drawer(spec, model, nullptr, makeSceneFacts(spec, model));
      const double L = model.path->length();
      for (const double fraction : {0.0, 1.0 / 3.0, 0.5, 2.0 / 3.0, 1.0}) {
        const double s = L * fraction;
        FrameOrientations frame = solveFrame(spec, model, s);
        frame.story = storyPlaceAt(model, s);
        const render::DrawList list = drawer.draw(frame);
        const std::string where = file.stem().string() + " " + a.name + " s = " + std::to_string(s);
        for (const render::LabelItem& l : list.labels) {
          if (l.worldAnchored || l.text.empty()) continue;  // marks' numbers and axis names sit on what they name
          const Box box = labelBox(l);
          const int w = l.view < 0 ? list.width : list.views[std::size_t(l.view)].width;
          const int h = l.view < 0 ? list.height : list.views[std::size_t(l.view)].height;
          EXPECT_TRUE(box.lo.x >= -0.5f && box.lo.y >= -0.5f && box.hi.x <= float(w) + 0.5f &&
                      box.hi.y <= float(h) + 0.5f)
              << where << ": \"" << l.text << "\" cut by the frame (" << box.lo.x << ", " << box.lo.y << ")–("
              << box.hi.x << ", " << box.hi.y << ") in " << w << "×" << h;
          ++checkedLabels;
          if (l.view < 0) continue;
          const Screen screen(list.views[std::size_t(l.view)]);
          // Nor under an inset drawn over its view.
          for (std::size_t k = 0; k < list.views.size(); ++k) {
            const render::View& inset = list.views[k];
            if (int(k) == l.view || !inset.frame) continue;
            const glm::vec2 at(screen.v.x, screen.v.y);
            const bool overlaps = box.lo.x + at.x < float(inset.x + inset.width) && float(inset.x) < box.hi.x + at.x &&
                                  box.lo.y + at.y < float(inset.y + inset.height) && float(inset.y) < box.hi.y + at.y;
            EXPECT_FALSE(overlaps) << where << ": \"" << l.text << "\" under the inset";
          }
          for (const render::MeshItem& m : list.meshes) {
            if (m.view != l.view || m.material.pattern != render::Pattern::Texture) continue;  // the ball(s)
            const glm::vec3 c = screen.project(glm::vec3(m.worldFromModel[3]));
            const float R = glm::length(glm::vec3(m.worldFromModel[0]));
            if (c.z <= R) continue;
            const float radiusPx =
                R * 0.5f * float(screen.v.height) * screen.v.camera.clipFromView[1][1] / std::sqrt(c.z * c.z - R * R);
            EXPECT_GT(distanceTo(box, glm::vec2(c)), radiusPx) << where << ": \"" << l.text << "\" over the ball";
          }
          for (const render::PolylineItem& p : list.polylines) {
            if (p.view != l.view || !isStoryLine(p)) continue;
            int hits = 0;
            for (std::size_t i = 0; i + 1 < p.points.size(); ++i) {
              const glm::vec3 a0 = screen.project(p.points[i]), a1 = screen.project(p.points[i + 1]);
              if (a0.z <= 0.0f || a1.z <= 0.0f) continue;
              const int steps = std::max(1, int(glm::length(glm::vec2(a1) - glm::vec2(a0))));
              for (int k = 0; k <= steps && steps < 100000; ++k)
                if (inside(box, glm::mix(glm::vec2(a0), glm::vec2(a1), float(k) / float(steps)))) ++hits;
            }
            EXPECT_EQ(hits, 0) << where << ": \"" << l.text << "\" over a path or trail";
          }
        }
        // The ball's disc inside the frame (≥ 90 % of its extent on each axis).
        for (const render::MeshItem& m : list.meshes) {
          if (m.material.pattern != render::Pattern::Texture) continue;
          const Screen screen(list.views[std::size_t(m.view)]);
          const glm::vec3 c = screen.project(glm::vec3(m.worldFromModel[3]));
          const float R = glm::length(glm::vec3(m.worldFromModel[0]));
          ASSERT_GT(c.z, R) << where;
          const float r =
              R * 0.5f * float(screen.v.height) * screen.v.camera.clipFromView[1][1] / std::sqrt(c.z * c.z - R * R);
          EXPECT_TRUE(c.x - 0.8f * r >= 0.0f && c.x + 0.8f * r <= float(screen.v.width) && c.y - 0.8f * r >= 0.0f &&
                      c.y + 0.8f * r <= float(screen.v.height))
              << where << ": the ball leaves the frame";
          // Outside a sphere (and no camera set by the scene): ≥ 90 % of the
          // ball's disc seen past the sphere, by rays from the eye.
          const auto* sphere = dynamic_cast<const geometry::Sphere*>(model.surface.get());
          if (sphere && sphere->side() == geometry::Side::Outside && !spec.locations.contains("render.elevation_deg")) {
            const glm::vec3 eye = screen.v.camera.position, centre(m.worldFromModel[3]);
            const glm::vec3 view = glm::normalize(centre - eye);
            const glm::vec3 u = glm::normalize(glm::cross(view, glm::vec3(0, 0, 1))), w = glm::cross(view, u);
            int seen = 0, all = 0;
            for (int k = 0; k < 400; ++k, ++all) {  // points spread evenly over the disc
              const float rho = std::sqrt((float(k) + 0.5f) / 400.0f), phi = 2.39996323f * float(k);
              const glm::vec3 p =
                  centre + R * (rho * (std::cos(phi) * u + std::sin(phi) * w) - std::sqrt(1.0f - rho * rho) * view);
              const glm::vec3 d = p - eye;
              const float t = std::clamp(-glm::dot(eye, d) / glm::dot(d, d), 0.0f, 1.0f);
              if (glm::length(eye + t * d) >= float(sphere->radius()) * 0.9999f || t >= 1.0f) ++seen;
            }
            EXPECT_GE(double(seen) / all, 0.9) << where << ": the sphere hides the ball";
          }
          ++checkedBalls;
        }
      }
    }
  }
  const int share = test::sweepSampled() ? int(test::kSweepStride) : 1;
  EXPECT_GT(checkedLabels, 1000 / share);
  EXPECT_GE(checkedBalls, 300 / share);  // one per frame at least (a strobe: more)
}

// Type for a lecture hall: at 16:9, 4:3, 1:1 and 9:16 the body text's line
// (1.4 em) is at least 1/28 of the frame's height, and no screen line is
// shrunk below 80 % of the body size to fit its view.
TEST(ClipLayout, BodyLinesAreAtLeastOneTwentyEighthOfTheHeightAtEveryAspect) {
  const Aspect aspects[] = {{1920, 1080, "16:9"}, {1440, 1080, "4:3"}, {1080, 1080, "1:1"}, {1080, 1920, "9:16"}};
  for (const char* name : {"lollipop", "berry", "sphere-outside", "storyboard", "torus"}) {
    const auto file = test::sourceDir() / "scenes" / (std::string(name) + ".toml");
    for (const Aspect& a : aspects) {
      const scene::SceneSpec spec = loadScene(
          file.string(), {"render.width=" + std::to_string(a.width), "render.height=" + std::to_string(a.height)});
      const RollingModel model = buildSceneModel(spec);
      const SceneDrawer drawer(spec, model, nullptr, makeSceneFacts(spec, model));
      FrameOrientations frame = solveFrame(spec, model, 0.5 * model.path->length());
      frame.story = storyPlaceAt(model, frame.current.s);
      const render::DrawList list = drawer.draw(frame);
      std::vector<float> body;
      for (const render::LabelItem& l : list.labels)
        if (!l.worldAnchored && !l.bold && !l.text.empty()) body.push_back(l.sizePx);
      ASSERT_GE(body.size(), 3u) << name << " " << a.name;
      std::sort(body.begin(), body.end());
      const float bodyPx = body[body.size() / 2];
      EXPECT_GE(kLineStep * bodyPx, float(a.height) / 28.0f) << name << " " << a.name << ": body " << bodyPx << " px";
      EXPECT_GE(body.front(), 0.8f * bodyPx) << name << " " << a.name << ": a line shrunk to " << body.front() << " px";
    }
  }
}

// The words a live line keeps from frame to frame (a retained layer holds
// them): up to the last space before the first digit.
TEST(ClipLayout, ALiveLinesLeadingWordsEndBeforeItsFirstNumber) {
  EXPECT_EQ(wordsBeforeTheFirstNumber("s = 3.78 of 18.85"), 4u);
  EXPECT_EQ(wordsBeforeTheFirstNumber("lab rotation angle = 161.5°"), std::string("lab rotation angle = ").size());
  EXPECT_EQ(wordsBeforeTheFirstNumber("spinor angle ψ = −521.5°"), std::string("spinor angle ψ = ").size());
  EXPECT_EQ(wordsBeforeTheFirstNumber("solver at the end: …"), 0u);  // no number
  EXPECT_EQ(wordsBeforeTheFirstNumber("12 turns"), 0u);              // a number first
  EXPECT_EQ(wordsBeforeTheFirstNumber("x=1"), 0u);                   // no space before it
}

// The room a figure's Bloch sphere is framed into: of the rectangles
// between the view's edges and the plates, the one with the longest shorter
// side, in NDC (y up).
TEST(ClipLayout, TheClearWindowIsTheLargestSquareishRoomBetweenThePlates) {
  auto near = [](const NdcWindow& w, double x0, double x1, double y0, double y1) {
    return std::abs(w.x0 - x0) < 1e-6 && std::abs(w.x1 - x1) < 1e-6 && std::abs(w.y0 - y0) < 1e-6 &&
           std::abs(w.y1 - y1) < 1e-6;
  };
  const NdcWindow whole = clearWindow(400, 600, {}, 10.0f);
  EXPECT_TRUE(near(whole, -1.0, 1.0, -1.0, 1.0));
  // A legend along the bottom (y 450–580 px, padded by 10): the room above it.
  const NdcWindow above = clearWindow(400, 600, {{{20.0f, 450.0f}, {300.0f, 580.0f}}}, 10.0f);
  EXPECT_TRUE(near(above, -1.0, 1.0, 1.0 - 2.0 * 440.0 / 600.0, 1.0))
      << above.x0 << " " << above.x1 << " " << above.y0 << " " << above.y1;
  // A heading top left and a legend bottom left in a wide view: the right
  // part beside both is squarer than the band between them.
  const NdcWindow beside =
      clearWindow(800, 400, {{{0.0f, 0.0f}, {300.0f, 60.0f}}, {{0.0f, 340.0f}, {300.0f, 400.0f}}}, 0.0f);
  EXPECT_TRUE(near(beside, -1.0 + 2.0 * 300.0 / 800.0, 1.0, -1.0, 1.0))
      << beside.x0 << " " << beside.x1 << " " << beside.y0 << " " << beside.y1;
}

// A figure's title: bold at the body size (not 1.35 em) where one line
// holds it, in a band 2 lines tall (2.4 in a clip); one whose band would
// take over a fifth of the figure's height is left out.
TEST(ClipLayout, AFiguresTitleIsBodySizedAndLeftOutPastAFifthOfTheHeight) {
  const std::string title = "On a cylinder: a parallel, then a helix";
  const float text = 20.0f, width = 1280.0f, height = 720.0f;
  const TitleLines clip = titleLines(title, text, width, height, 0.0f);
  const TitleLines figure = titleLines(title, text, width, height, text, true);
  EXPECT_FLOAT_EQ(clip.sizePx, 1.35f * text);
  EXPECT_FLOAT_EQ(figure.sizePx, text);
  EXPECT_EQ(figure.lines.size(), 1u);
  EXPECT_EQ(titleBandHeight(1, text, true), 40);
  EXPECT_EQ(titleBandHeight(1, text), 48);
  EXPECT_TRUE(titleFitsFigure(title, text, width, height, text));
  // At a size where it breaks onto two lines, 3.4 lines tall: over a fifth.
  const float large = 1.05f * 0.94f * width / textWidthPx(title, 1.0f, true);
  ASSERT_EQ(titleLines(title, large, width, height, large, true).lines.size(), 2u);
  EXPECT_GT(3.4f * large, 0.2f * height);
  EXPECT_FALSE(titleFitsFigure(title, large, width, height, large));
}

// A line too wide for its view breaks at spaces at its own size (not
// shrunk), its pieces marked as one line (they give way together), and the
// lines a block keeps count the pieces; only a single word wider than the
// view shrinks, and not below the least size.
TEST(ClipLayout, ALineTooWideWrapsAtItsSizeAndOnlyALongWordShrinks) {
  const float size = 20.0f;
  const std::string fact = "dynamic (1/2)∫B·X ds = 50.494171 and more words after it";
  const float wide = textWidthPx(fact, size, false);
  TextBlock block;
  block.lines = {{"rolling ball", size * 1.1f, true, {}, false}, {fact, size, false, {}, false}};
  block.keep = 2;
  const float maxWidth = 0.45f * wide;
  wrapToWidth(block, maxWidth, 12.0f);
  ASSERT_GE(block.lines.size(), 4u);
  EXPECT_FALSE(block.lines[1].continued);
  std::string joined;
  for (std::size_t i = 1; i < block.lines.size(); ++i) {
    EXPECT_EQ(block.lines[i].sizePx, size) << block.lines[i].text;
    EXPECT_EQ(block.lines[i].continued, i > 1) << block.lines[i].text;
    joined += (i > 1 ? " " : "") + block.lines[i].text;
  }
  EXPECT_EQ(joined, fact);
  EXPECT_EQ(block.keep, block.lines.size());
  EXPECT_LE(blockSize(block).x, maxWidth + 0.5f);

  // One word wider than the view: smaller, to the least size at most.
  TextBlock word;
  word.lines = {{"Sehr_langes_Wort_ohne_Leerzeichen", size, false, {}, false}};
  const float wordWidth = textWidthPx(word.lines[0].text, size, false);
  wrapToWidth(word, 0.8f * wordWidth, 12.0f);
  ASSERT_EQ(word.lines.size(), 1u);
  EXPECT_LT(word.lines[0].sizePx, size);
  EXPECT_GT(word.lines[0].sizePx, 12.0f);
  TextBlock tooLong;
  tooLong.lines = word.lines;
  tooLong.lines[0].sizePx = size;
  wrapToWidth(tooLong, 0.2f * wordWidth, 12.0f);
  EXPECT_EQ(tooLong.lines[0].sizePx, 12.0f);

  // A running value breaks where its widest digits would not fit either,
  // so the break holds from frame to frame.
  const std::string live = "lab rotation angle = 1.0°";
  TextBlock running;
  running.lines = {{live, size, false, {}, true}};
  const float room = textWidthPx(live, size, false) + 2.0f * kBlockPad * size + 1.0f;  // fits as written
  wrapToWidth(running, room, 12.0f);
  EXPECT_GT(running.lines.size(), 1u) << "a line that fits only with its digits as they are now";
}

// A view's edge inside the frame (the seam to the twin view) does not cut a
// big sphere in the middle of the frame where panning or a slightly wider
// framing holds it: for a small ball on a large sphere (berry) at 16:9, at
// five places along the clip, the sphere's outline (dense points over it,
// projected with the ball view's camera) on the rows the view shows stays
// left of the seam.
TEST(ClipLayout, ALargeSpheresOutlineIsNotCutByTheSeamToTheTwinView) {
  for (const auto& [width, height] : {std::pair{1920, 1080}, std::pair{960, 540}, std::pair{640, 360}}) {
    const auto file = test::sourceDir() / "scenes/berry.toml";
    const scene::SceneSpec spec =
        loadScene(file.string(), {"render.width=" + std::to_string(width), "render.height=" + std::to_string(height)});
    const RollingModel model = buildSceneModel(spec);
    const auto* sphere = dynamic_cast<const geometry::Sphere*>(model.surface.get());
    ASSERT_NE(sphere, nullptr);
    const SceneDrawer drawer(spec, model, nullptr, makeSceneFacts(spec, model));
    const double L = model.path->length();
    for (const double fraction : {0.0, 0.25, 0.5, 0.75, 1.0}) {
      const double s = L * fraction;
      const render::View v = drawer.ballCamera(storyPlaceAt(model, s), s);
      ASSERT_LT(v.x + v.width, width) << "the ball view ends at a seam";
      const Screen screen(v);
      const glm::vec3 eye = v.camera.position;
      float rightmost = -1e9f;
      for (int i = 0; i <= 360; ++i)
        for (int k = 0; k < 720; ++k) {
          const double th = M_PI * i / 360, phi = 2.0 * M_PI * k / 720;
          const glm::vec3 d(float(std::sin(th) * std::cos(phi)), float(std::sin(th) * std::sin(phi)),
                            float(std::cos(th)));
          const glm::vec3 p = float(sphere->radius()) * d;
          if (glm::dot(p - eye, d) > 0.0f) continue;  // the far side: inside the outline anyway
          const glm::vec3 q = screen.project(p);
          if (q.z > 0.0f && q.y >= 0.0f && q.y <= float(v.height)) rightmost = std::max(rightmost, q.x);
        }
      EXPECT_LE(rightmost, float(v.width))
          << width << "x" << height << " s = " << s << ": the seam cuts the sphere at x = " << v.width
          << " (its outline reaches " << rightmost << ")";
    }
  }
}

}  // namespace
}  // namespace rollspin::draw
