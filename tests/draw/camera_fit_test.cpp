// CameraFraming remembers each framing it fits (fitPoints, holdOutline,
// keepOffViewEdges) by the exact bits of its inputs: a camera asked again,
// after any other windows, inner edges, view sizes and places, must frame
// exactly as a fresh CameraFraming that computes it for the first time.
// No GL.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "draw/camera_framing.hpp"
#include "model/rolling_model.hpp"
#include "support/test_files.hpp"

namespace rollspin::draw {
namespace {

using geometry::Vec3;

// The path's ball centres, and an outline beside them (so that holdOutline
// has something to hold where the view has an inner edge).
FrameExtent extentOf(const model::RollingModel &model) {
  FrameExtent extent;
  const double L = model.path->length(), R = model.ballRadius;
  for (int i = 0; i <= 64; ++i) extent.points.push_back(model.path->at(L * i / 64).centre(R));
  for (int i = 0; i <= 16; ++i)
    extent.outline.push_back(extent.points[std::size_t(i) * 4] + Vec3(4.0 * R, -3.0 * R, -R));
  extent.centre = extent.points[32];
  extent.radius = L;
  return extent;
}

bool sameBits(const CameraFraming::Aim &a, const CameraFraming::Aim &b) {
  const double x[] = {a.target.x(), a.target.y(), a.target.z(), a.distance, a.azimuth, a.elevation, a.fovDeg};
  const double y[] = {b.target.x(), b.target.y(), b.target.z(), b.distance, b.azimuth, b.elevation, b.fovDeg};
  return std::memcmp(x, y, sizeof x) == 0;
}

TEST(CameraFit, AFramingAskedAgainIsTheOneComputedAfresh) {
  // (Pairs of one size in different places: the same lens, a different
  // window, which holdOutline and keepOffViewEdges depend on.)
  const NdcWindow windows[] = {{},
                               {-0.55, 1.0, -1.0, 1.0},
                               {-1.0, 0.55, -1.0, 1.0},
                               {-1.0, 1.0, -1.0, 0.35},
                               {-1.0, 1.0, -0.35, 1.0},
                               {-1.0, 0.7, -0.6, 1.0}};
  const CameraFraming::InnerEdges edges[] = {{}, {true, false, false, false}, {false, false, true, true}};
  const std::pair<int, int> sizes[] = {{480, 270}, {160, 90}, {270, 480}};
  for (const std::string name : {"lollipop", "sphere-outside", "storyboard", "cornu"}) {
    const scene::SceneSpec spec = model::loadScene((test::sourceDir() / "scenes" / (name + ".toml")).string(),
                                                   {"render.width=480", "render.height=270"});
    const model::RollingModel model = model::buildSceneModel(spec);
    const FrameExtent extent = extentOf(model);
    const double L = model.path->length();
    CameraFraming asked(spec, model, extent);  // asked everything, twice over
    int compared = 0;
    for (int round = 0; round < 2; ++round)
      for (const NdcWindow &window : windows)
        for (const CameraFraming::InnerEdges &edge : edges)
          for (const auto &[w, h] : sizes) {
            CameraFraming fresh(spec, model, extent);
            fresh.setWindow(window);
            fresh.setInnerEdges(edge);
            asked.setWindow(window);
            asked.setInnerEdges(edge);
            for (const double s : {0.0, 0.37 * L, L}) {
              motion::StoryPlace place;
              place.segment = spec.segments.empty() ? 0 : spec.segments.size() - 1;
              place.seconds = 5.0;
              place.duration = 10.0;
              ASSERT_TRUE(sameBits(asked.aimAt(place, w, h, s), fresh.aimAt(place, w, h, s)))
                  << name << " round " << round << " window " << window.x0 << " " << window.x1 << " " << window.y0
                  << " " << window.y1 << " view " << w << "x" << h << " s " << s;
              ++compared;
            }
          }
    EXPECT_EQ(compared, 2 * 6 * 3 * 3 * 3);
  }
}

}  // namespace
}  // namespace rollspin::draw
