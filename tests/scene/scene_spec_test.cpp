// scene/scene_spec: what a SceneSpec answers of itself, on specs built in
// code: which surface each storyboard segment rolls on (its own, else the
// last one given before it), where a key was set, which kind-specific keys
// apply to which kinds (and the message's list of kinds), and which facts
// a scene shows (each fact's rule and the "auto" choice of the header).
#include "scene/scene_spec.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace rollspin::scene::scene_spec_tests {
namespace {

SurfaceSpec surfaceOfKind(SurfaceKind kind) {
  SurfaceSpec s;
  s.kind = kind;
  s.params = ParamSet(surfaceKeyDecls(kind));
  return s;
}

SegmentSpec motionOn(std::optional<SurfaceKind> kind) {
  SegmentSpec seg;
  seg.path = PathSpec{};
  if (kind) seg.surface = surfaceOfKind(*kind);
  return seg;
}

TEST(SceneSpec, OneSurfaceWithoutAStoryboard) {
  SceneSpec spec;
  spec.surface = surfaceOfKind(SurfaceKind::Sphere);
  EXPECT_EQ(spec.surfaceCount(), 1u);
  EXPECT_EQ(spec.surfaceOf(0).kind, SurfaceKind::Sphere);
  EXPECT_EQ(spec.surfaceIndexOf(0), 0u);
  EXPECT_EQ(spec.surfaceKeyOf(0), "surface");
}

TEST(SceneSpec, ASegmentRollsOnTheLastSurfaceGivenAtOrBeforeIt) {
  SceneSpec spec;
  spec.surface = surfaceOfKind(SurfaceKind::Plane);
  // Segments 1 … 5: none, sphere, none (a hold), cylinder, none.
  spec.segments = {motionOn(std::nullopt), motionOn(SurfaceKind::Sphere), SegmentSpec{},
                   motionOn(SurfaceKind::Cylinder), motionOn(std::nullopt)};
  const std::vector<SurfaceKind> kinds{SurfaceKind::Plane, SurfaceKind::Sphere, SurfaceKind::Sphere,
                                       SurfaceKind::Cylinder, SurfaceKind::Cylinder};
  const std::vector<std::string> keys{"surface", "segment[2].surface", "segment[2].surface", "segment[4].surface",
                                      "segment[4].surface"};
  const std::vector<std::size_t> indices{0, 1, 1, 2, 2};
  for (std::size_t k = 0; k < spec.segments.size(); ++k) {
    EXPECT_EQ(spec.surfaceOf(k).kind, kinds[k]) << k;
    EXPECT_EQ(spec.surfaceKeyOf(k), keys[k]) << k;
    EXPECT_EQ(spec.surfaceIndexOf(k), indices[k]) << k;
  }
  EXPECT_EQ(spec.surfaceCount(), 3u);
  // Its own surface is the very table the segment gave.
  EXPECT_EQ(&spec.surfaceOf(2), &*spec.segments[1].surface);
  EXPECT_EQ(&spec.surfaceOf(0), &spec.surface);
}

TEST(SceneSpec, AFirstSegmentsOwnSurfaceIsSurfaceZero) {
  SceneSpec spec;
  spec.surface = surfaceOfKind(SurfaceKind::Plane);  // unused: the first segment gives its own
  spec.segments = {motionOn(SurfaceKind::Torus), motionOn(std::nullopt), motionOn(SurfaceKind::Plane)};
  EXPECT_EQ(spec.surfaceOf(0).kind, SurfaceKind::Torus);
  EXPECT_EQ(spec.surfaceOf(1).kind, SurfaceKind::Torus);
  EXPECT_EQ(spec.surfaceKeyOf(1), "segment[1].surface");
  EXPECT_EQ(spec.surfaceIndexOf(0), 0u);
  EXPECT_EQ(spec.surfaceIndexOf(1), 0u);
  EXPECT_EQ(spec.surfaceIndexOf(2), 1u);
  EXPECT_EQ(spec.surfaceCount(), 2u);
}

TEST(SceneSpec, SegmentKeysCountFromOne) {
  EXPECT_EQ(SceneSpec::segmentKey(0), "segment[1]");
  EXPECT_EQ(SceneSpec::segmentKey(11), "segment[12]");
}

TEST(SceneSpec, WhereAKeyWasSetElseTheFileWithNoLine) {
  SceneSpec spec;
  spec.sourceFile = "scenes/x.toml";
  spec.locations["ball.radius"] = SourceLoc{"scenes/x.toml", 4, 10};
  spec.locations["path.turns"] = SourceLoc{"--set path.turns=2"};
  EXPECT_EQ(spec.where("ball.radius").str(), "scenes/x.toml:4:10");
  EXPECT_EQ(spec.where("path.turns").str(), "--set path.turns=2");
  const SourceLoc defaulted = spec.where("path.radius");
  EXPECT_EQ(defaulted.file, "scenes/x.toml");
  EXPECT_EQ(defaulted.line, 0);
  SceneSpec inCode;
  EXPECT_FALSE(inCode.where("ball.radius").empty()) << "a spec built in code still names something";
}

// Every kind a [surface] can be, by its constant.
const SurfaceKind kSceneSpecTestKinds[] = {SurfaceKind::Plane, SurfaceKind::Sphere,     SurfaceKind::Cylinder,
                                           SurfaceKind::Torus, SurfaceKind::Paraboloid, SurfaceKind::Saddle,
                                           SurfaceKind::Height};

TEST(SceneSpec, ASurfaceKeyAppliesToTheKindsThatHaveIt) {
  // Not a kind-specific key: it applies everywhere and names no kinds.
  const KeyRule free = surfaceKeyRule("kind", SurfaceKind::Sphere);
  EXPECT_TRUE(free.applies);
  EXPECT_EQ(free.kinds, "");
  for (const std::string& key : allSurfaceKeys()) {
    std::vector<std::string> having;
    for (const SurfaceKind kind : kSceneSpecTestKinds) {
      const std::vector<std::string>& own = sceneSurfaceKind(kind).keys;
      const bool has = std::find(own.begin(), own.end(), key) != own.end();
      if (has) having.push_back(std::string(kind.name()));
      EXPECT_EQ(surfaceKeyRule(key, kind).applies, has) << key << " on " << kind.name();
    }
    // "\"sphere\" or \"cylinder\"": each kind that has it, quoted, and none other.
    const std::string kinds = surfaceKeyRule(key, SurfaceKind::Plane).kinds;
    for (const SurfaceKind kind : kSceneSpecTestKinds) {
      // Built by appends: gcc 12's -Wrestrict misfires on "\"" + std::string(…) + "\"".
      const bool named = kinds.find(std::string(1, '"').append(kind.name()).append(1, '"')) != std::string::npos;
      EXPECT_EQ(named, std::find(having.begin(), having.end(), kind.name()) != having.end()) << key << ": " << kinds;
    }
    // Joined "a, b or c": one "or" before the last of two or more.
    const auto count = [&](const std::string& what) {
      std::size_t n = 0;
      for (std::size_t at = kinds.find(what); at != std::string::npos; at = kinds.find(what, at + 1)) ++n;
      return n;
    };
    EXPECT_EQ(count(" or "), having.size() >= 2 ? 1u : 0u) << kinds;
    EXPECT_EQ(count(", "), having.size() >= 2 ? having.size() - 2 : 0u) << kinds;
  }
}

TEST(SceneSpec, APathKeyAppliesToItsKindOnItsSurfaces) {
  // The path table: colatitude_deg is a parallel's on a sphere only; radius
  // a circle's, and a parallel's on a paraboloid; turns a meridian's on a
  // torus only (a closed loop there).
  EXPECT_TRUE(pathKeyRule("colatitude_deg", PathKind::Parallel, SurfaceKind::Sphere).applies);
  EXPECT_FALSE(pathKeyRule("colatitude_deg", PathKind::Parallel, SurfaceKind::Torus).applies);
  EXPECT_FALSE(pathKeyRule("colatitude_deg", PathKind::Circle, SurfaceKind::Plane).applies);
  EXPECT_TRUE(pathKeyRule("radius", PathKind::Circle, SurfaceKind::Plane).applies);
  EXPECT_TRUE(pathKeyRule("radius", PathKind::Parallel, SurfaceKind::Paraboloid).applies);
  EXPECT_FALSE(pathKeyRule("radius", PathKind::Parallel, SurfaceKind::Sphere).applies);
  EXPECT_TRUE(pathKeyRule("turns", PathKind::Meridian, SurfaceKind::Torus).applies);
  EXPECT_FALSE(pathKeyRule("turns", PathKind::Meridian, SurfaceKind::Sphere).applies);
  EXPECT_FALSE(pathKeyRule("turns", PathKind::Line, SurfaceKind::Plane).applies);
  // Not a path key: applies, names nothing.
  const KeyRule kind = pathKeyRule("kind", PathKind::Line, SurfaceKind::Plane);
  EXPECT_TRUE(kind.applies);
  EXPECT_EQ(kind.kinds, "");
}

TEST(SceneSpec, APathKeysKindsListThoseWhereItAlwaysAppliesFirst) {
  // turns: always on a circle, a parallel and a helix; on a meridian only on a torus.
  EXPECT_EQ(pathKeyRule("turns", PathKind::Line, SurfaceKind::Plane).kinds,
            "circle or parallel (or helix, or meridian on a torus)");
  // colatitude_deg: one kind, on one surface.
  EXPECT_EQ(pathKeyRule("colatitude_deg", PathKind::Circle, SurfaceKind::Plane).kinds, "parallel on a sphere");
  // pitch_angle_deg: a helix's alone.
  EXPECT_EQ(pathKeyRule("pitch_angle_deg", PathKind::Circle, SurfaceKind::Plane).kinds, "helix");
}

SceneSpec factSceneOf(SurfaceKind surface, PathKind path) {
  SceneSpec spec;
  spec.surface = surfaceOfKind(surface);
  spec.path.kind = path;
  return spec;
}

TEST(SceneSpec, EachFactAppliesToTheKindsItHasAClosedFormFor) {
  SceneSpec planeCircle = factSceneOf(SurfaceKind::Plane, PathKind::Circle);
  SceneSpec equator = factSceneOf(SurfaceKind::Sphere, PathKind::Parallel);
  equator.path.colatitudeDeg = 90.0;
  SceneSpec parallel = factSceneOf(SurfaceKind::Sphere, PathKind::Parallel);
  parallel.path.colatitudeDeg = 60.0;
  const SceneSpec torusParallel = factSceneOf(SurfaceKind::Torus, PathKind::Parallel);
  const SceneSpec line = factSceneOf(SurfaceKind::Plane, PathKind::Line);

  EXPECT_TRUE(factRule(Fact::Delta, planeCircle).applies);
  EXPECT_TRUE(factRule(Fact::Delta, parallel).applies);
  EXPECT_FALSE(factRule(Fact::Delta, torusParallel).applies);
  EXPECT_FALSE(factRule(Fact::Delta, line).applies);
  EXPECT_TRUE(factRule(Fact::Marks, planeCircle).applies);
  EXPECT_FALSE(factRule(Fact::Marks, parallel).applies);
  EXPECT_TRUE(factRule(Fact::Turns, equator).applies);
  EXPECT_FALSE(factRule(Fact::Turns, parallel).applies);
  EXPECT_FALSE(factRule(Fact::Turns, planeCircle).applies);
  // The phase split needs B's loop closed: whole turns.
  EXPECT_TRUE(factRule(Fact::PhaseSplit, parallel).applies);
  planeCircle.path.turns = 2.0;
  EXPECT_TRUE(factRule(Fact::PhaseSplit, planeCircle).applies);
  planeCircle.path.turns = 1.5;
  EXPECT_FALSE(factRule(Fact::PhaseSplit, planeCircle).applies);
  EXPECT_TRUE(factRule(Fact::Delta, planeCircle).applies) << "δ needs no closed loop";
  // A storyboard's facts are its captions: none applies, and the message says why.
  SceneSpec storyboard = factSceneOf(SurfaceKind::Plane, PathKind::Circle);
  storyboard.segments = {motionOn(std::nullopt)};
  for (const Fact f : {Fact::Delta, Fact::Marks, Fact::Turns, Fact::PhaseSplit}) {
    EXPECT_FALSE(factRule(f, storyboard).applies) << toString(f);
    EXPECT_NE(factRule(f, storyboard).kinds.find("storyboard"), std::string::npos);
  }
}

TEST(SceneSpec, AutoFactsFollowTheScenesKinds) {
  SceneSpec given = factSceneOf(SurfaceKind::Plane, PathKind::Line);
  given.labels.facts = std::vector<Fact>{Fact::Turns, Fact::Delta};
  EXPECT_EQ(resolveFacts(given), (std::vector<Fact>{Fact::Turns, Fact::Delta})) << "as given, even where none applies";
  given.labels.facts = std::vector<Fact>{};
  EXPECT_TRUE(resolveFacts(given).empty()) << "\"none\"";

  SceneSpec plate = factSceneOf(SurfaceKind::Plane, PathKind::Circle);
  plate.plate = PlateSpec{2.0};
  EXPECT_EQ(resolveFacts(plate), std::vector<Fact>{Fact::Marks});
  EXPECT_EQ(resolveFacts(factSceneOf(SurfaceKind::Plane, PathKind::Circle)), std::vector<Fact>{Fact::Delta});
  EXPECT_TRUE(resolveFacts(factSceneOf(SurfaceKind::Plane, PathKind::Line)).empty());
  EXPECT_TRUE(resolveFacts(factSceneOf(SurfaceKind::Cylinder, PathKind::Helix)).empty());
  SceneSpec storyboard = factSceneOf(SurfaceKind::Plane, PathKind::Circle);
  storyboard.segments = {motionOn(std::nullopt)};
  EXPECT_TRUE(resolveFacts(storyboard).empty());

  // A parallel on a sphere of radius 10.
  SceneSpec sphere = factSceneOf(SurfaceKind::Sphere, PathKind::Parallel);
  sphere.surface.params.set("radius", 10.0);
  sphere.path.colatitudeDeg = 90.0;
  sphere.ball.radius = 5.0;
  EXPECT_EQ(resolveFacts(sphere), std::vector<Fact>{Fact::Turns}) << "at the equator, whatever the ball";
  sphere.path.colatitudeDeg = 60.0;
  EXPECT_EQ(resolveFacts(sphere), std::vector<Fact>{Fact::Delta}) << "a large ball";
  sphere.ball.radius = 1.0;  // R = r/10 exactly: small
  EXPECT_EQ(resolveFacts(sphere), std::vector<Fact>{Fact::PhaseSplit});
  sphere.ball.radius = 1.001;
  EXPECT_EQ(resolveFacts(sphere), std::vector<Fact>{Fact::Delta});
  sphere.ball.radius = 0.5;
  sphere.path.turns = 1.5;  // no whole circuit: no closed loop to split
  EXPECT_EQ(resolveFacts(sphere), std::vector<Fact>{Fact::Delta});
}

TEST(SceneSpec, NamesAreTheOnesTheTablesUse) {
  for (const SurfaceKind kind : kSceneSpecTestKinds) EXPECT_EQ(toString(kind), kind.name());
  for (const PathKindRow& row : pathKinds()) EXPECT_EQ(toString(row.kind), row.name);
  for (std::size_t i = 0; i < kFactNames.size(); ++i) EXPECT_EQ(toString(Fact(i)), kFactNames[i]);
  // The layouts by the names render.layout accepts (docs/scene-reference.md).
  EXPECT_EQ(toString(RenderLayout::SideBySide), "side-by-side");
  EXPECT_EQ(toString(RenderLayout::Inset), "inset");
  EXPECT_EQ(toString(RenderLayout::Ball), "ball");
  EXPECT_EQ(toString(RenderLayout::Twin), "twin");
}

}  // namespace
}  // namespace rollspin::scene::scene_spec_tests
