// The presentation sections of a scene: [render], [labels], [animation],
// the storyboard's [[segment]] entries and their cameras.
#include "scene/schema_reader.hpp"

#include "media/output_format.hpp"
#include "render/gl_context.hpp"
#include "scene/scene_keys.hpp"

#include <algorithm>
#include <cmath>

namespace rollspin::scene::schema {

CameraSpec Reader::readCamera(const toml::table* t, const std::string& section) {
  CameraSpec c;
  readKeys(t, section, segmentCameraKeys(), c);
  return c;
}

// [[segment]] — a storyboard (docs/scenes.md#storyboards). Each entry moves along
// its own path (the [path] keys, validated the same way) or holds; timing,
// caption, title and camera are per segment. Keys are named segment[k].…
// with k counted from 1.
void Reader::readSegments() {
  const toml::node* node = root_.get("segment");
  if (node == nullptr) return;
  const toml::array* entries = node->as_array();
  if (entries == nullptr || entries->empty() || !entries->is_array_of_tables())
    fail("segment", locOf("segment", *node), "[[segment]] tables (an array of tables)", describeNode(*node));
  spec_.locations["segment"] = locOf("segment", *node);
  if (spec_.plate)
    failAt("plate",
           "a storyboard's segments have their own paths; [plate] drives one circle, so it cannot be "
           "combined with [[segment]]");
  if (entries->size() > kMaxSegments)
    throw badInput(where("segment"), "segment: expected at most {} segments, got {}", kMaxSegments, entries->size());
  for (std::size_t i = 0; i < entries->size(); ++i) {
    const std::string prefix = SceneSpec::segmentKey(i);
    const toml::node& entry = *entries->get(i);
    spec_.locations[prefix] = locOf(prefix, entry);
    const toml::table& table = *entry.as_table();
    for (auto&& [k, v] : table) {
      static const std::set<std::string> kSegmentKeys = namesOf(segmentKeys());
      if (!kSegmentKeys.contains(std::string(k.str())))
        throw unknownKey(locOf(prefix + "." + std::string(k.str()), v), prefix + "." + std::string(k.str()),
                         std::string(k.str()), "a segment", kSegmentKeys);
    }
    SegmentSpec seg;
    const toml::table* path = subTable(table, std::string(key::kPath), dotted(prefix, key::kPath), pathTableKeys());
    readSegmentSurface(table, prefix, path != nullptr, seg);
    spec_.segments.push_back(seg);  // surfaceOf(i) below reads it
    const SurfaceSpec& surface = spec_.surfaceOf(i);
    const bool onPlane = surface.kind == SurfaceKind::Plane;
    // The first motion on a new surface starts where its own keys say.
    const bool newSurface = i == 0 || seg.surface.has_value();
    const std::string holdKey = dotted(prefix, key::kHold);
    const std::optional<double> hold = number(&table, prefix, std::string(key::kHold));
    if (path == nullptr && !hold)
      throw badInput(where(prefix), "{}: expected path = {{ kind = ..., ... }} (a motion) or hold = SECONDS (a rest)",
                     prefix);
    if (path != nullptr && hold)
      failAt(holdKey, "a segment either moves (path) or holds (hold), not both; split it into two segments");
    if (path != nullptr) {
      seg.path = PathSpec{};
      const PathKind pk = readPath(path, dotted(prefix, key::kPath), *seg.path, surface, spec_.surfaceKeyOf(i));
      // On a plane, segments after the first continue from the previous end
      // point along its end heading (tangent-continuous).
      const bool placedByPrevious = pk == PathKind::Line || pk == PathKind::Circle || pk == PathKind::Clothoid;
      if (!newSurface && onPlane && placedByPrevious && seg.path->directionVector)
        failAt(prefix + ".path.direction_vector",
               "a segment after the first starts where the previous one ended, along its end heading "
               "(tangent-continuous); remove direction_vector");
    } else {
      checkRow(rowOf(segmentKeys(), key::kHold), holdKey, *hold);
      seg.hold = *hold;
    }
    const std::string durationKey = dotted(prefix, key::kDuration), speedKey = dotted(prefix, key::kSpeed);
    if ((seg.duration = number(&table, prefix, std::string(key::kDuration)))) {
      if (!path) failAt(durationKey, "applies to a motion (a segment with a path); a hold's length is hold");
      checkRow(rowOf(segmentKeys(), key::kDuration), durationKey, *seg.duration);
    }
    if ((seg.speed = number(&table, prefix, std::string(key::kSpeed)))) {
      if (!path) failAt(speedKey, "applies to a motion (a segment with a path); a hold's length is hold");
      checkRow(rowOf(segmentKeys(), key::kSpeed), speedKey, *seg.speed);
      if (seg.duration)
        failAt(speedKey, fmt::format("conflicts with {}: give the duration or the speed, not both", durationKey));
    }
    readRow(&table, prefix, rowOf(segmentKeys(), key::kCaption), seg);
    readRow(&table, prefix, rowOf(segmentKeys(), key::kTitle), seg);
    const std::string cameraKey = dotted(prefix, key::kCamera);
    seg.camera =
        readCamera(subTable(table, std::string(key::kCamera), cameraKey, namesOf(segmentCameraKeys())), cameraKey);
    spec_.segments.back() = std::move(seg);
  }
  // A segment's camera target stops a follow, and follow = true drops a
  // target (docs/scenes.md#storyboards); one table giving both is contradictory.
  for (std::size_t i = 0; i < spec_.segments.size(); ++i) {
    const CameraSpec& c = spec_.segments[i].camera;
    if (c.target && c.follow && *c.follow)
      failAt(
          dotted(dotted(SceneSpec::segmentKey(i), key::kCamera), key::kTarget),
          fmt::format("conflicts with {} = true in the same camera (the camera then targets the ball)", key::kFollow));
  }
}

// A segment's surface = { ... } and its transition keys. A surface belongs
// to a motion (a hold rests where the ball is); transition and
// fade_seconds apply only where the surface changes.
void Reader::readSegmentSurface(const toml::table& table, const std::string& prefix, bool moves, SegmentSpec& seg) {
  const std::string surfaceKey = dotted(prefix, key::kSurface);
  if (const toml::table* surface = subTable(table, std::string(key::kSurface), surfaceKey, keysOf("surface"))) {
    if (!moves)
      failAt(surfaceKey,
             "a hold rests where the previous motion ended, on its surface; give the surface "
             "to the next segment with a path");
    seg.surface = SurfaceSpec{};
    readSurface(surface, surfaceKey, *seg.surface);
  }
  const bool changes = seg.surface && prefix != SceneSpec::segmentKey(0);
  auto onlyAtChange = [&](std::string_view name) {
    if (!changes && spec_.locations.contains(dotted(prefix, name)))
      failAt(dotted(prefix, name),
             prefix == SceneSpec::segmentKey(0)
                 ? "applies where the surface changes; the first segment has nothing to change from"
                 : "applies where the surface changes; this segment keeps the previous segment's surface (give it "
                   "surface = { kind = ..., ... })");
  };
  readRow(&table, prefix, rowOf(segmentKeys(), key::kTransition), seg);
  onlyAtChange(key::kTransition);
  const std::string fadeKey = dotted(prefix, key::kFadeSeconds);
  if (auto f = number(&table, prefix, std::string(key::kFadeSeconds))) {
    checkRow(rowOf(segmentKeys(), key::kFadeSeconds), fadeKey, *f);
    if (seg.transition != SegmentSpec::Transition::Fade)
      failAt(fadeKey, fmt::format("applies to {} = \"fade\"; this segment cuts", key::kTransition));
    seg.fadeSeconds = *f;
  }
  onlyAtChange(key::kFadeSeconds);
}

// [render] — image size, layout, strobe, text, camera (render issue): the
// table's rows, then the rule that a followed camera has no target.
void Reader::readRender() {
  const toml::table* render = section("render", namesOf(renderKeys()));
  readKeys(render, "render", renderKeys(), spec_.render);
  if (spec_.render.follow && spec_.locations.contains(dotted("render", key::kTarget)))
    failAt(dotted("render", key::kTarget),
           fmt::format("conflicts with render.{} = true (the camera then targets the ball)", key::kFollow));
  readGlContext(render);
}

// render.backend and render.device: the GL context. The names are render's
// table (gl_backends.cpp); the scene keeps the text.
void Reader::readGlContext(const toml::table* table) {
  const std::string device = dotted("render", key::kDevice);
  if (const toml::node* node = get(table, "render", std::string(key::kDevice))) {
    const SourceLoc at = locOf(device, *node);
    const std::string expected = "an EGL device index (0, 1, …) or a DRM device path (\"/dev/dri/renderD128\")";
    if (node->is_integer() && node->as_integer()->get() >= 0)
      spec_.render.device = std::to_string(node->as_integer()->get());
    else if (node->is_string() && node->as_string()->get().rfind('/', 0) == 0)
      spec_.render.device = node->as_string()->get();
    else fail(device, at, expected, describeNode(*node));
    if (spec_.render.backend && !render::backendTakesDevice(*spec_.render.backend))
      failAt(device, fmt::format("applies to a backend that renders on a device (\"egl\" or \"auto\"), but "
                                 "render.{} is \"{}\"",
                                 key::kBackend, *spec_.render.backend));
  }
}

// [figure] — a still as a PDF/SVG figure (docs/figures.md). The width is
// given once, by one of three keys; the other keys are the table's.
void Reader::readFigure() {
  const toml::table* figure = section("figure", namesOf(figureKeys()));
  FigureSpec& f = spec_.figure;
  const std::string widthMm = dotted("figure", key::kWidthMm), widthIn = dotted("figure", key::kWidthIn);
  const auto mm = number(figure, "figure", std::string(key::kWidthMm));
  const auto in = number(figure, "figure", std::string(key::kWidthIn));
  if (mm && in) failAt(widthIn, fmt::format("conflicts with {}: give the width once", widthMm));
  // The journals' two widths by name: a column (85 mm) or the page's text
  // block (175 mm).
  const KeyRow<FigureSpec>& preset = figureKeys().front();
  if (auto named = text(figure, "figure", std::string(preset.name), {preset.choices.begin(), preset.choices.end()})) {
    if (mm || in)
      failAt(dotted("figure", preset.name),
             fmt::format("conflicts with figure.{}: give the width once", mm ? key::kWidthMm : key::kWidthIn));
    f.widthMm = *named == preset.choices.front() ? 85.0 : 175.0;
  }
  if (mm || in) {
    const double width = mm ? *mm : *in * 25.4;
    if (!(width >= kMinFigureWidthMm && width <= kMaxFigureWidthMm))
      failAt(mm ? widthMm : widthIn,
             fmt::format("expected a figure width in [{}, {}] mm ([{:.2f}, {:.1f}] in), got {} mm", kMinFigureWidthMm,
                         kMaxFigureWidthMm, kMinFigureWidthMm / 25.4, kMaxFigureWidthMm / 25.4, width));
    f.widthMm = width;
  }
  readKeys(figure, "figure", figureKeys(), f);
}

// [labels] — which facts of the scene are printed (after [surface] and
// [path]: a fact must apply to their kinds).
void Reader::readLabels() {
  const std::string labelsSection(key::kLabels);
  const toml::table* labels = section(labelsSection, namesOf(labelsKeys()));
  const toml::node* node = get(labels, labelsSection, std::string(key::kFacts));
  if (node == nullptr) return;
  const std::string key = dotted(labelsSection, key::kFacts);
  std::string names;
  for (const auto& n : kFactNames) names += (names.empty() ? "" : ", ") + ("\"" + n + "\"");
  const std::string expected = "\"auto\", \"none\" or a list of facts from " + names;
  if (const auto* word = node->as_string()) {
    if (word->get() == "auto") return;
    if (word->get() == "none") {
      spec_.labels.facts = std::vector<Fact>{};
      return;
    }
    // One fact is still a list: show the syntax, the shell's quotes too
    // when it came from --set (a bare word there reads as a string).
    const SourceLoc where = locOf(key, *node);
    if (std::find(kFactNames.begin(), kFactNames.end(), word->get()) != kFactNames.end())
      fail(key, where,
           fmt::format("{}; a list even for one fact: {}", expected,
                       where.file.starts_with("--set") ? fmt::format("--set '{}=[\"{}\"]'", key, word->get())
                                                       : fmt::format("{} = [\"{}\"]", key::kFacts, word->get())),
           describeNode(*node));
    fail(key, where, expected, describeNode(*node));
  }
  const toml::array* list = node->as_array();
  if (list == nullptr) fail(key, locOf(key, *node), expected, describeNode(*node));
  std::vector<Fact> facts;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& e = *list->get(i);
    const auto it =
        e.is_string() ? std::find(kFactNames.begin(), kFactNames.end(), e.as_string()->get()) : kFactNames.end();
    if (it == kFactNames.end())
      fail(key, locOf(key, *node), expected, "element " + std::to_string(i) + " = " + describeNode(e));
    const Fact f = static_cast<Fact>(it - kFactNames.begin());
    if (std::find(facts.begin(), facts.end(), f) != facts.end())
      failAt(key, fmt::format("\"{}\" is listed twice", *it));
    const KeyRule rule = factRule(f, spec_);
    if (!rule.applies) failAt(key, fmt::format("\"{}\" applies to {} only", *it, rule.kinds));
    facts.push_back(f);
  }
  spec_.labels.facts = facts;
}

// [animation] — frame time → arc length, and the H.264 settings (video
// issue): the frame rate's forms, the table's rows, then the rule that the
// speed replaces the duration.
void Reader::readAnimation() {
  const toml::table* animation = section("animation", namesOf(animationKeys()));
  AnimationSpec& a = spec_.animation;
  const std::string fps = dotted("animation", key::kFps);
  if (const toml::node* node = get(animation, "animation", std::string(key::kFps))) {
    const std::string expected = fmt::format(
        "frames per second in [{}, {}]: an integer, an NTSC rate 23.976 | 29.97 | 59.94 (exactly 24000/1001 …), a "
        "decimal with at most 3 places, or a string \"num/den\" such as \"30000/1001\"",
        kMinFps, kMaxFps);
    std::optional<FrameRate> rate;
    if (node->is_integer()) {
      const long long n = node->as_integer()->get();
      if (n >= kMinFps && n <= kMaxFps) rate = FrameRate{n, 1};
    } else if (node->is_floating_point()) {
      rate = frameRateFromDecimal(node->as_floating_point()->get());
    } else if (node->is_string()) {
      rate = frameRateFromText(node->as_string()->get());
    }
    if (!rate || !(rate->value() >= kMinFps && rate->value() <= kMaxFps))
      fail(fps, locOf(fps, *node), expected, describeNode(*node));
    a.fps = *rate;
  }
  readKeys(animation, "animation", animationKeys(), a);
  const std::string duration = dotted("animation", key::kDuration);
  if (a.speed && spec_.locations.contains(duration))
    failAt(dotted("animation", key::kSpeed),
           fmt::format("conflicts with {}: give the duration or the speed, not both", duration));
}


}  // namespace rollspin::scene::schema
