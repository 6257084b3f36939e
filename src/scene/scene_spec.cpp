#include "scene/scene_spec.hpp"

#include <algorithm>
#include <cmath>

namespace rollspin::scene {

namespace {
bool contains(const std::vector<std::string>& keys, const std::string& key) {
  return std::find(keys.begin(), keys.end(), key) != keys.end();
}
std::string orList(const std::vector<std::string>& items) {
  std::string out;
  for (std::size_t i = 0; i < items.size(); ++i)
    out += (i == 0 ? "" : i + 1 == items.size() ? " or " : ", ") + items[i];
  return out;
}
}  // namespace

KeyRule surfaceKeyRule(const std::string& key, SurfaceKind sk) {
  if (!contains(allSurfaceKeys(), key)) return {true, ""};
  std::vector<std::string> kinds;
  for (const auto& row : surfaceKinds())
    // Built by appends: gcc 12's -Wrestrict misfires on "\"" + std::string(…) + "\"".
    if (contains(row.keys, key)) kinds.push_back(std::string(1, '"').append(row.name).append(1, '"'));
  return {contains(sceneSurfaceKind(sk).keys, key), orList(kinds)};
}

KeyRule pathKeyRule(const std::string& key, PathKind pk, SurfaceKind sk) {
  if (!contains(allPathKeys(), key)) return {true, ""};
  bool applies = false;
  // "circle or parallel (or helix, or meridian on a torus)": the kinds where
  // the key always applies first, those where it applies on some surfaces after.
  std::vector<std::string> everywhere, somewhere;
  for (const auto& row : pathKinds()) {
    for (const auto& k : row.keys) {
      if (k.key != key) continue;
      std::vector<std::string> on;
      for (SurfaceKind s : k.on) on.emplace_back(sceneSurfaceKind(s).name);
      (on.empty() ? everywhere : somewhere)
          .push_back(std::string(row.name) + (on.empty() ? "" : " on a " + orList(on)));
      if (row.kind == pk && (k.on.empty() || std::find(k.on.begin(), k.on.end(), sk) != k.on.end())) applies = true;
    }
  }
  everywhere.insert(everywhere.end(), somewhere.begin(), somewhere.end());
  std::string kinds;
  for (std::size_t i = 0; i < everywhere.size(); ++i)
    kinds += i == 0 ? everywhere[i] : i == 1 ? " or " + everywhere[i] : (i == 2 ? " (or " : ", or ") + everywhere[i];
  if (everywhere.size() > 2) kinds += ")";
  return {applies, kinds};
}

SourceLoc SceneSpec::where(const std::string& key) const {
  if (auto it = locations.find(key); it != locations.end()) return it->second;
  return SourceLoc{sourceFile.empty() ? std::string("<scene>") : sourceFile};
}

const SurfaceSpec& SceneSpec::surfaceOf(std::size_t index) const {
  for (std::size_t k = std::min(index + 1, segments.size()); k-- > 0;)
    if (segments[k].surface) return *segments[k].surface;
  return surface;
}

std::size_t SceneSpec::surfaceIndexOf(std::size_t index) const {
  std::size_t n = 0;
  for (std::size_t k = 1; k <= index && k < segments.size(); ++k)
    if (segments[k].surface) ++n;
  return n;
}

std::size_t SceneSpec::surfaceCount() const { return segments.empty() ? 1 : surfaceIndexOf(segments.size() - 1) + 1; }

std::string SceneSpec::surfaceKeyOf(std::size_t index) const {
  for (std::size_t k = std::min(index + 1, segments.size()); k-- > 0;)
    if (segments[k].surface) return segmentKey(k) + ".surface";
  return "surface";
}

std::string toString(SurfaceKind k) { return std::string(sceneSurfaceKind(k).name); }

std::string toString(PathKind k) { return std::string(pathKindRow(k).name); }

std::string toString(RenderLayout l) {
  switch (l) {
    case RenderLayout::SideBySide: return "side-by-side";
    case RenderLayout::Inset: return "inset";
    case RenderLayout::Ball: return "ball";
    case RenderLayout::Twin: return "twin";
  }
  return "?";
}

std::string toString(Fact f) { return kFactNames[static_cast<std::size_t>(f)]; }

namespace {
bool wholeTurns(double turns) { return std::abs(turns - std::round(turns)) < 1e-9; }
bool planeCircle(const SceneSpec& s) { return s.surface.kind == SurfaceKind::Plane && s.path.kind == PathKind::Circle; }
bool sphereParallel(const SceneSpec& s) {
  return s.surface.kind == SurfaceKind::Sphere && s.path.kind == PathKind::Parallel;
}
bool onEquator(const SceneSpec& s) { return std::abs(s.path.colatitudeDeg - 90.0) < 1e-9; }
}  // namespace

KeyRule factRule(Fact f, const SceneSpec& spec) {
  // A storyboard's facts are its captions: the closed forms are about one path.
  if (spec.isStoryboard()) return {false, "a scene with one [path] (a storyboard's segments have captions)"};
  switch (f) {
    case Fact::Delta:
      return {planeCircle(spec) || sphereParallel(spec), "a circle on a plane or a parallel on a sphere"};
    case Fact::Marks: return {planeCircle(spec), "a circle on a plane"};
    case Fact::Turns: return {sphereParallel(spec) && onEquator(spec), "a parallel on a sphere at colatitude_deg = 90"};
    case Fact::PhaseSplit:
      return {(planeCircle(spec) || sphereParallel(spec)) && wholeTurns(spec.path.turns),
              "a circle on a plane or a parallel on a sphere, with whole path.turns (B's loop must close)"};
  }
  return {false, ""};
}

std::vector<Fact> resolveFacts(const SceneSpec& spec) {
  if (spec.labels.facts) return *spec.labels.facts;
  if (spec.isStoryboard()) return {};
  if (spec.plate) return {Fact::Marks};
  if (planeCircle(spec)) return {Fact::Delta};
  if (sphereParallel(spec)) {
    if (onEquator(spec)) return {Fact::Turns};
    if (spec.ball.radius <= 0.1 * spec.surface.number("radius") && wholeTurns(spec.path.turns))
      return {Fact::PhaseSplit};
    return {Fact::Delta};
  }
  return {};
}

}  // namespace rollspin::scene
