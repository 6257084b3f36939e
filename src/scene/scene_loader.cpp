#include "scene/scene_loader.hpp"

#include <toml++/toml.h>

#include "render/gl_context.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

namespace rollspin::scene {

namespace {

std::string describeNode(const toml::node& node) {
  std::ostringstream os;
  switch (node.type()) {
    case toml::node_type::string: os << "string \"" << node.as_string()->get() << "\""; break;
    case toml::node_type::integer: os << "integer " << node.as_integer()->get(); break;
    case toml::node_type::floating_point: os << "number " << node.as_floating_point()->get(); break;
    case toml::node_type::boolean: os << "boolean " << (node.as_boolean()->get() ? "true" : "false"); break;
    case toml::node_type::array: os << "an array"; break;
    case toml::node_type::table: os << "a table"; break;
    default: os << "a date/time"; break;
  }
  return os.str();
}

std::string joinKeys(const std::set<std::string>& keys) {
  std::string out;
  for (const auto& k : keys) out += (out.empty() ? "" : ", ") + k;
  return out;
}

std::set<std::string> pathTableKeys() {
  std::set<std::string> keys(kPathKeys.begin(), kPathKeys.end());
  keys.insert("kind");
  return keys;
}

// Reads one document into a SceneSpec, remembering where every key came from.
class Reader {
 public:
  Reader(const toml::table& root, std::string file, std::map<std::string, SourceLoc> overrideLocs)
      : root_(root), file_(std::move(file)), overrides_(std::move(overrideLocs)) {}

  SceneSpec read();

 private:
  SourceLoc locOf(const std::string& key, const toml::node& node) const {
    if (auto it = overrides_.find(key); it != overrides_.end()) return it->second;
    // A value inherited through `extends` remembers its own file.
    const auto& src = node.source();
    const std::string& file = src.path ? *src.path : file_;
    if (src.begin.line == 0) return SourceLoc{file};
    return SourceLoc{file, static_cast<int>(src.begin.line), static_cast<int>(src.begin.column)};
  }
  SourceLoc fileLoc() const { return SourceLoc{file_}; }

  // Section [name]: returns nullptr when absent; checks its keys.
  const toml::table* section(const std::string& name, const std::set<std::string>& allowed);
  const toml::table* subTable(const toml::table& parent, const std::string& name, const std::string& full,
                              const std::set<std::string>& allowed);
  CameraSpec readCamera(const toml::table* t, const std::string& section);
  void readSegments();
  const toml::node* get(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<double> number(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<long long> integer(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<std::string> text(const toml::table* t, const std::string& section, const std::string& key,
                                  const std::set<std::string>& choices);
  std::optional<Vec3> vector(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<std::string> expression(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<std::vector<std::vector<double>>> pointList(const toml::table* t, const std::string& section,
                                                            const std::string& key);
  std::optional<bool> boolean(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<std::string> anyText(const toml::table* t, const std::string& section, const std::string& key);
  PathKind readPath(const toml::table* path, const std::string& prefix, PathSpec& target);
  void readRender();
  void readGlContext(const toml::table* table);
  void readAnimation();
  void readLabels();
  void forbid(const toml::table* t, const std::string& section, const std::string& key, const std::string& why);

  [[noreturn]] void fail(const std::string& key, const SourceLoc& loc, const std::string& expected,
                         const std::string& got) const {
    throw badInput(loc, "{}: expected {}, got {}", key, expected, got);
  }
  [[noreturn]] void failAt(const std::string& key, const std::string& message) const {
    throw badInput(where(key), "{}: {}", key, message);
  }
  SourceLoc where(const std::string& key) const {
    if (auto it = spec_.locations.find(key); it != spec_.locations.end()) return it->second;
    return fileLoc();
  }

  const toml::table& root_;
  std::string file_;
  std::map<std::string, SourceLoc> overrides_;
  SceneSpec spec_;
};

const toml::table* Reader::section(const std::string& name, const std::set<std::string>& allowed) {
  return subTable(root_, name, name, allowed);
}

// `parent`'s key `name` as a table whose keys are all in `allowed`; `full`
// names it in messages and locations ("render", "segment[2].camera").
const toml::table* Reader::subTable(const toml::table& parent, const std::string& name, const std::string& full,
                                   const std::set<std::string>& allowed) {
  const toml::node* node = parent.get(name);
  if (node == nullptr) return nullptr;
  const toml::table* t = node->as_table();
  const std::string what = full == name ? "[" + name + "]" : full;
  if (t == nullptr) fail(full, locOf(full, *node), "a table " + what, describeNode(*node));
  spec_.locations[full] = locOf(full, *node);
  for (auto&& [k, v] : *t) {
    const std::string key = full + "." + std::string(k.str());
    if (!allowed.contains(std::string(k.str()))) {
      throw badInput(locOf(key, v), "{}: unknown key; {} accepts: {}", key, what, joinKeys(allowed));
    }
  }
  return t;
}

const toml::node* Reader::get(const toml::table* t, const std::string& section, const std::string& key) {
  if (t == nullptr) return nullptr;
  const toml::node* node = t->get(key);
  if (node != nullptr) spec_.locations[section + "." + key] = locOf(section + "." + key, *node);
  return node;
}

std::optional<double> Reader::number(const toml::table* t, const std::string& section, const std::string& key) {
  const toml::node* node = get(t, section, key);
  if (node == nullptr) return std::nullopt;
  const std::string full = section + "." + key;
  if (!node->is_number()) fail(full, locOf(full, *node), "a number", describeNode(*node));
  const double v = node->value<double>().value();
  if (!std::isfinite(v)) fail(full, locOf(full, *node), "a finite number", describeNode(*node));
  return v;
}

std::optional<long long> Reader::integer(const toml::table* t, const std::string& section, const std::string& key) {
  const toml::node* node = get(t, section, key);
  if (node == nullptr) return std::nullopt;
  const std::string full = section + "." + key;
  if (!node->is_integer()) fail(full, locOf(full, *node), "an integer", describeNode(*node));
  return node->as_integer()->get();
}

std::optional<std::string> Reader::text(const toml::table* t, const std::string& section, const std::string& key,
                                        const std::set<std::string>& choices) {
  const toml::node* node = get(t, section, key);
  if (node == nullptr) return std::nullopt;
  const std::string full = section + "." + key;
  std::string quoted;
  for (const auto& c : choices) quoted += (quoted.empty() ? "" : " | ") + ("\"" + c + "\"");
  if (!node->is_string()) fail(full, locOf(full, *node), quoted, describeNode(*node));
  std::string v = node->as_string()->get();
  if (!choices.contains(v)) fail(full, locOf(full, *node), quoted, describeNode(*node));
  return v;
}

std::optional<Vec3> Reader::vector(const toml::table* t, const std::string& section, const std::string& key) {
  const toml::node* node = get(t, section, key);
  if (node == nullptr) return std::nullopt;
  const std::string full = section + "." + key;
  const toml::array* a = node->as_array();
  const std::string expected = "an array of 3 finite numbers [x, y, z]";
  if (a == nullptr || a->size() != 3) fail(full, locOf(full, *node), expected, describeNode(*node));
  Vec3 v{};
  for (std::size_t i = 0; i < 3; ++i) {
    const toml::node& e = *a->get(i);
    if (!e.is_number() || !std::isfinite(e.value<double>().value())) {
      fail(full, locOf(full, *node), expected, "element " + std::to_string(i) + " = " + describeNode(e));
    }
    v[i] = e.value<double>().value();
  }
  return v;
}

std::optional<bool> Reader::boolean(const toml::table* t, const std::string& section, const std::string& key) {
  const toml::node* node = get(t, section, key);
  if (node == nullptr) return std::nullopt;
  const std::string full = section + "." + key;
  if (!node->is_boolean()) fail(full, locOf(full, *node), "true or false", describeNode(*node));
  return node->as_boolean()->get();
}

std::optional<std::string> Reader::anyText(const toml::table* t, const std::string& section, const std::string& key) {
  const toml::node* node = get(t, section, key);
  if (node == nullptr) return std::nullopt;
  const std::string full = section + "." + key;
  if (!node->is_string()) fail(full, locOf(full, *node), "a string", describeNode(*node));
  return node->as_string()->get();
}

// The camera keys of [render] or of a segment's camera table.
CameraSpec Reader::readCamera(const toml::table* t, const std::string& section) {
  CameraSpec c;
  c.azimuthDeg = number(t, section, "azimuth_deg");
  if ((c.elevationDeg = number(t, section, "elevation_deg")) && !(*c.elevationDeg > -90.0 && *c.elevationDeg < 90.0))
    failAt(section + ".elevation_deg",
           fmt::format("expected an elevation in (-90, 90) degrees, got {}", *c.elevationDeg));
  if ((c.distance = number(t, section, "distance")) && *c.distance <= 0.0)
    failAt(section + ".distance", fmt::format("expected a camera distance > 0, got {}", *c.distance));
  c.target = vector(t, section, "target");
  c.follow = boolean(t, section, "follow");
  if ((c.fovDeg = number(t, section, "fov_deg")) && !(*c.fovDeg >= 5.0 && *c.fovDeg <= 120.0))
    failAt(section + ".fov_deg",
           fmt::format("expected a vertical field of view in [5, 120] degrees, got {}", *c.fovDeg));
  return c;
}

// [[segment]] — a storyboard (README "Storyboards"). Each entry moves along
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
    failAt("plate", "a storyboard's segments have their own paths; [plate] drives one circle, so it cannot be "
                    "combined with [[segment]]");
  if (entries->size() > kMaxSegments)
    throw badInput(where("segment"), "segment: expected at most {} segments, got {}", kMaxSegments, entries->size());
  const bool onPlane = spec_.surface.kind == SurfaceKind::Plane;
  for (std::size_t i = 0; i < entries->size(); ++i) {
    const std::string prefix = SceneSpec::segmentKey(i);
    const toml::node& entry = *entries->get(i);
    spec_.locations[prefix] = locOf(prefix, entry);
    const toml::table& table = *entry.as_table();
    for (auto&& [k, v] : table) {
      static const std::set<std::string> kSegmentKeys{"path", "hold", "duration", "speed", "caption", "title", "camera"};
      if (!kSegmentKeys.contains(std::string(k.str())))
        throw badInput(locOf(prefix + "." + std::string(k.str()), v), "{}.{}: unknown key; a segment accepts: {}",
                       prefix, k.str(), joinKeys(kSegmentKeys));
    }
    SegmentSpec seg;
    const toml::table* path = subTable(table, "path", prefix + ".path", pathTableKeys());
    const std::optional<double> hold = number(&table, prefix, "hold");
    if (path == nullptr && !hold)
      throw badInput(where(prefix), "{}: expected path = {{ kind = ..., ... }} (a motion) or hold = SECONDS (a rest)",
                     prefix);
    if (path != nullptr && hold)
      failAt(prefix + ".hold", "a segment either moves (path) or holds (hold), not both; split it into two segments");
    if (path != nullptr) {
      seg.path = PathSpec{};
      const PathKind pk = readPath(path, prefix + ".path", *seg.path);
      // On a plane, segments after the first continue from the previous end
      // point along its end heading (tangent-continuous).
      const bool placedByPrevious = pk == PathKind::Line || pk == PathKind::Circle || pk == PathKind::Clothoid;
      if (i > 0 && onPlane && placedByPrevious && seg.path->directionVector)
        failAt(prefix + ".path.direction_vector",
               "a segment after the first starts where the previous one ended, along its end heading "
               "(tangent-continuous); remove direction_vector");
    } else {
      if (!(*hold > 0.0 && *hold <= 3600.0))
        failAt(prefix + ".hold", fmt::format("expected a hold in (0, 3600] seconds, got {}", *hold));
      seg.hold = *hold;
    }
    if ((seg.duration = number(&table, prefix, "duration"))) {
      if (!path) failAt(prefix + ".duration", "applies to a motion (a segment with a path); a hold's length is hold");
      if (!(*seg.duration > 0.0 && *seg.duration <= 36000.0))
        failAt(prefix + ".duration", fmt::format("expected a duration in (0, 36000] seconds, got {}", *seg.duration));
    }
    if ((seg.speed = number(&table, prefix, "speed"))) {
      if (!path) failAt(prefix + ".speed", "applies to a motion (a segment with a path); a hold's length is hold");
      if (!(*seg.speed > 0.0)) failAt(prefix + ".speed", fmt::format("expected an arc length per second > 0, got {}", *seg.speed));
      if (seg.duration)
        failAt(prefix + ".speed", fmt::format("conflicts with {}.duration: give the duration or the speed, not both", prefix));
    }
    if (auto c = anyText(&table, prefix, "caption")) seg.caption = *c;
    seg.title = anyText(&table, prefix, "title");
    const std::set<std::string> cameraKeys(kCameraKeys.begin(), kCameraKeys.end());
    seg.camera = readCamera(subTable(table, "camera", prefix + ".camera", cameraKeys), prefix + ".camera");
    spec_.segments.push_back(std::move(seg));
  }
  // A segment's camera target stops a follow, and follow = true drops a
  // target (README "Storyboards"); one table giving both is contradictory.
  for (std::size_t i = 0; i < spec_.segments.size(); ++i) {
    const CameraSpec& c = spec_.segments[i].camera;
    if (c.target && c.follow && *c.follow)
      failAt(SceneSpec::segmentKey(i) + ".camera.target",
             "conflicts with follow = true in the same camera (the camera then targets the ball)");
  }
}

// [render] — image size, layout, strobe, text, camera (render issue).
void Reader::readRender() {
  const toml::table* render = section(
      "render", {"width", "height", "layout", "strobe", "title", "labels", "transparent", "msaa", "azimuth_deg",
                 "elevation_deg", "distance", "target", "follow", "fov_deg", "format", "trails", "shadow", "backend",
                 "device"});
  RenderSpec& r = spec_.render;
  constexpr long long kMaxSide = 8192;  // "8K": the renderer's size limit
  for (const char* key : {"width", "height"}) {
    if (auto n = integer(render, "render", key)) {
      if (*n < 1 || *n > kMaxSide)
        failAt(std::string("render.") + key, fmt::format("expected an image size in [1, {}] pixels, got {}", kMaxSide, *n));
      (std::string(key) == "width" ? r.width : r.height) = *n;
    }
  }
  if (auto l = text(render, "render", "layout", {"side-by-side", "inset", "ball", "twin"}))
    r.layout = *l == "side-by-side" ? RenderLayout::SideBySide
             : *l == "inset"        ? RenderLayout::Inset
             : *l == "ball"         ? RenderLayout::Ball
                                    : RenderLayout::Twin;
  if (auto n = integer(render, "render", "strobe")) {
    if (*n < 0 || *n == 1 || *n > 200)
      failAt("render.strobe", fmt::format("expected 0 (off) or a number of positions in [2, 200], got {}", *n));
    r.strobe = *n;
  }
  if (auto t = anyText(render, "render", "title")) r.title = *t;
  if (auto b = boolean(render, "render", "labels")) r.labels = *b;
  if (auto b = boolean(render, "render", "transparent")) r.transparent = *b;
  if (auto n = integer(render, "render", "msaa")) {
    if (*n != 1 && *n != 2 && *n != 4) failAt("render.msaa", fmt::format("expected 1, 2 or 4 samples, got {}", *n));
    r.msaa = *n;
  }
  const CameraSpec camera = readCamera(render, "render");
  if (camera.azimuthDeg) r.azimuthDeg = *camera.azimuthDeg;
  if (camera.elevationDeg) r.elevationDeg = *camera.elevationDeg;
  if (camera.distance) r.distance = *camera.distance;
  if (camera.target) r.target = *camera.target;
  if (camera.follow) r.follow = *camera.follow;
  if (camera.fovDeg) r.fovDeg = *camera.fovDeg;
  if (auto t = boolean(render, "render", "trails")) r.trails = *t;
  if (auto sh = boolean(render, "render", "shadow")) r.shadow = *sh;
  if (r.follow && spec_.locations.contains("render.target"))
    failAt("render.target", "conflicts with render.follow = true (the camera then targets the ball)");
  if (auto f = text(render, "render", "format", {"mp4", "png"}))
    r.format = *f == "mp4" ? VideoFormat::Mp4 : VideoFormat::Png;
  readGlContext(render);
}

// render.backend and render.device: the GL context. The names are render's
// table (gl_backends.cpp); the scene keeps the text.
void Reader::readGlContext(const toml::table* table) {
  const std::vector<std::string> names = render::backendNames();
  if (auto b = text(table, "render", "backend", std::set<std::string>(names.begin(), names.end())))
    spec_.render.backend = *b;
  if (const toml::node* node = get(table, "render", "device")) {
    const SourceLoc at = locOf("render.device", *node);
    const std::string expected = "an EGL device index (0, 1, …) or a DRM device path (\"/dev/dri/renderD128\")";
    if (node->is_integer() && node->as_integer()->get() >= 0) spec_.render.device = std::to_string(node->as_integer()->get());
    else if (node->is_string() && node->as_string()->get().rfind('/', 0) == 0) spec_.render.device = node->as_string()->get();
    else fail("render.device", at, expected, describeNode(*node));
    if (spec_.render.backend && !render::backendTakesDevice(*spec_.render.backend))
      failAt("render.device", fmt::format("applies to a backend that renders on a device (\"egl\" or \"auto\"), but "
                                          "render.backend is \"{}\"", *spec_.render.backend));
  }
}

// [labels] — which facts of the scene are printed (after [surface] and
// [path]: a fact must apply to their kinds).
void Reader::readLabels() {
  const toml::table* labels = section("labels", {"facts"});
  const toml::node* node = get(labels, "labels", "facts");
  if (node == nullptr) return;
  const std::string key = "labels.facts";
  std::string names;
  for (const auto& n : kFactNames) names += (names.empty() ? "" : ", ") + ("\"" + n + "\"");
  const std::string expected = "\"auto\", \"none\" or a list of facts from " + names;
  if (const auto* word = node->as_string()) {
    if (word->get() == "auto") return;
    if (word->get() == "none") {
      spec_.labels.facts = std::vector<Fact>{};
      return;
    }
    fail(key, locOf(key, *node), expected, describeNode(*node));
  }
  const toml::array* list = node->as_array();
  if (list == nullptr) fail(key, locOf(key, *node), expected, describeNode(*node));
  std::vector<Fact> facts;
  for (std::size_t i = 0; i < list->size(); ++i) {
    const toml::node& e = *list->get(i);
    const auto it = e.is_string() ? std::find(kFactNames.begin(), kFactNames.end(), e.as_string()->get()) : kFactNames.end();
    if (it == kFactNames.end()) fail(key, locOf(key, *node), expected, "element " + std::to_string(i) + " = " + describeNode(e));
    const Fact f = static_cast<Fact>(it - kFactNames.begin());
    if (std::find(facts.begin(), facts.end(), f) != facts.end())
      failAt(key, fmt::format("\"{}\" is listed twice", *it));
    const KeyRule rule = factRule(f, spec_);
    if (!rule.applies) failAt(key, fmt::format("\"{}\" applies to {} only", *it, rule.kinds));
    facts.push_back(f);
  }
  spec_.labels.facts = facts;
}

// [animation] — frame time → arc length, and the H.264 settings (video issue).
void Reader::readAnimation() {
  const toml::table* animation =
      section("animation", {"fps", "duration", "speed", "easing", "hold", "crf", "preset"});
  AnimationSpec& a = spec_.animation;
  if (const toml::node* node = get(animation, "animation", "fps")) {
    const std::string expected =
        "frames per second in [1, 240]: an integer, an NTSC rate 23.976 | 29.97 | 59.94 (exactly 24000/1001 …), a "
        "decimal with at most 3 places, or a string \"num/den\" such as \"30000/1001\"";
    std::optional<FrameRate> rate;
    if (node->is_integer()) {
      const long long n = node->as_integer()->get();
      if (n >= 1 && n <= 240) rate = FrameRate{n, 1};
    } else if (node->is_floating_point()) {
      rate = frameRateFromDecimal(node->as_floating_point()->get());
    } else if (node->is_string()) {
      rate = frameRateFromText(node->as_string()->get());
    }
    if (!rate || !(rate->value() >= 1.0 && rate->value() <= 240.0))
      fail("animation.fps", locOf("animation.fps", *node), expected, describeNode(*node));
    a.fps = *rate;
  }
  if (auto d = number(animation, "animation", "duration")) {
    if (!(*d > 0.0 && *d <= 36000.0))
      failAt("animation.duration", fmt::format("expected a duration in (0, 36000] seconds, got {}", *d));
    a.duration = *d;
  }
  if (auto v = number(animation, "animation", "speed")) {
    if (!(*v > 0.0)) failAt("animation.speed", fmt::format("expected an arc length per second > 0, got {}", *v));
    if (spec_.locations.contains("animation.duration"))
      failAt("animation.speed", "conflicts with animation.duration: give the duration or the speed, not both");
    a.speed = *v;
  }
  if (auto e = text(animation, "animation", "easing", {"linear", "smooth"}))
    a.easing = *e == "linear" ? Easing::Linear : Easing::Smooth;
  if (auto h = number(animation, "animation", "hold")) {
    if (!(*h >= 0.0 && *h <= 3600.0))
      failAt("animation.hold", fmt::format("expected a hold in [0, 3600] seconds, got {}", *h));
    a.hold = *h;
  }
  if (auto c = number(animation, "animation", "crf")) {
    if (!(*c >= 0.0 && *c <= 51.0)) failAt("animation.crf", fmt::format("expected a CRF in [0, 51], got {}", *c));
    a.crf = *c;
  }
  if (auto p = text(animation, "animation", "preset",
                    {"ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower", "veryslow"}))
    a.preset = *p;
}

std::optional<std::string> Reader::expression(const toml::table* t, const std::string& section,
                                              const std::string& key) {
  const toml::node* node = get(t, section, key);
  if (node == nullptr) return std::nullopt;
  const std::string full = section + "." + key;
  if (!node->is_string()) fail(full, locOf(full, *node), "an expression string such as \"0.3*sin(x)\"", describeNode(*node));
  std::string v = node->as_string()->get();
  if (v.find_first_not_of(" \t") == std::string::npos) fail(full, locOf(full, *node), "a non-empty expression", "\"\"");
  return v;
}

std::optional<std::vector<std::vector<double>>> Reader::pointList(const toml::table* t, const std::string& section,
                                                                  const std::string& key) {
  const toml::node* node = get(t, section, key);
  if (node == nullptr) return std::nullopt;
  const std::string full = section + "." + key;
  const std::string expected = "an array of points, each [u, v] (surface parameters) or [x, y, z]";
  const toml::array* a = node->as_array();
  if (a == nullptr) fail(full, locOf(full, *node), expected, describeNode(*node));
  std::vector<std::vector<double>> points;
  for (std::size_t i = 0; i < a->size(); ++i) {
    const toml::array* p = a->get(i)->as_array();
    if (p == nullptr || (p->size() != 2 && p->size() != 3))
      fail(full, locOf(full, *node), expected, "point " + std::to_string(i + 1) + " = " + describeNode(*a->get(i)));
    std::vector<double> xs;
    for (std::size_t k = 0; k < p->size(); ++k) {
      const toml::node& e = *p->get(k);
      if (!e.is_number() || !std::isfinite(e.value<double>().value()))
        fail(full, locOf(full, *node), expected, "point " + std::to_string(i + 1) + " has " + describeNode(e));
      xs.push_back(e.value<double>().value());
    }
    if (!points.empty() && xs.size() != points.front().size())
      fail(full, locOf(full, *node), "all points with the same number of coordinates",
           "point " + std::to_string(i + 1) + " with " + std::to_string(xs.size()));
    points.push_back(std::move(xs));
  }
  return points;
}

void Reader::forbid(const toml::table* t, const std::string& section, const std::string& key,
                    const std::string& why) {
  if (t == nullptr) return;
  if (const toml::node* node = t->get(key)) {
    const std::string full = section + "." + key;
    throw badInput(locOf(full, *node), "{}: {}", full, why);
  }
}

// v / len, except that a vector already unit to round-off is kept as given,
// so that a printed (normalised) scene reads back bit for bit.
Vec3 unitVector(const Vec3& v, double len) {
  if (std::abs(len - 1.0) <= 1e-15) return v;
  return {v[0] / len, v[1] / len, v[2] / len};
}

double norm3(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// The keys of a path table ([path], or a segment's path): kind and the
// kind-specific keys, validated against the surface. `prefix` names the
// table in messages and locations ("path", "segment[2].path").
PathKind Reader::readPath(const toml::table* path, const std::string& prefix, PathSpec& target) {
  const SurfaceKind sk = spec_.surface.kind;
  const std::string skName = toString(sk);
  const bool pathKindGiven = path != nullptr && path->get("kind") != nullptr;
  static const std::map<std::string, PathKind> kPathKinds{
      {"line", PathKind::Line},           {"circle", PathKind::Circle},       {"parallel", PathKind::Parallel},
      {"meridian", PathKind::Meridian},   {"helix", PathKind::Helix},         {"loxodrome", PathKind::Loxodrome},
      {"geodesic", PathKind::Geodesic},   {"uv", PathKind::Uv},               {"points", PathKind::Points},
      {"clothoid", PathKind::Clothoid}};
  if (auto kind = text(path, prefix, "kind",
                       {"line", "circle", "parallel", "meridian", "helix", "loxodrome", "geodesic", "uv", "points",
                        "clothoid"})) {
    target.kind = kPathKinds.at(*kind);
  } else if (sk == SurfaceKind::Sphere || sk == SurfaceKind::Cylinder || sk == SurfaceKind::Torus ||
             sk == SurfaceKind::Paraboloid) {
    target.kind = PathKind::Parallel;  // the natural closed path of a surface of revolution
  } else if (sk == SurfaceKind::Saddle || sk == SurfaceKind::Height) {
    target.kind = PathKind::Meridian;
  }
  const PathKind pk = target.kind;
  const std::string pkName = toString(pk);
  // Which surfaces each path kind lies on.
  const bool revolution = sk == SurfaceKind::Sphere || sk == SurfaceKind::Cylinder || sk == SurfaceKind::Torus ||
                          sk == SurfaceKind::Paraboloid;
  std::string needs;
  bool lies = true;
  switch (pk) {
    case PathKind::Line:
    case PathKind::Circle:
    case PathKind::Clothoid: lies = sk == SurfaceKind::Plane; needs = "plane"; break;
    case PathKind::Parallel: lies = revolution; needs = "sphere, cylinder, torus or paraboloid"; break;
    case PathKind::Meridian: lies = sk != SurfaceKind::Plane; needs = "curved surface"; break;
    case PathKind::Helix: lies = sk == SurfaceKind::Cylinder; needs = "cylinder"; break;
    case PathKind::Loxodrome: lies = sk == SurfaceKind::Sphere; needs = "sphere"; break;
    case PathKind::Geodesic:
    case PathKind::Uv:
    case PathKind::Points: break;
  }
  if (!lies) {
    const std::string key = pathKindGiven ? (prefix + ".kind") : "surface.kind";
    failAt(key, fmt::format("a {} path lies on a {}, but surface.kind is \"{}\" (the path would leave the surface)",
                            pkName, needs, skName));
  }
  auto only = [&](const std::string& key, bool applies, const std::string& kinds) {
    if (!applies) forbid(path, prefix, key, "applies to path kind " + kinds + " only; this path is a " + pkName +
                                                " on a " + skName);
  };
  for (const auto& key : kPathKeys) {
    const KeyRule rule = pathKeyRule(key, pk, sk);
    only(key, rule.applies, rule.kinds);
  }
  const bool onSphere = sk == SurfaceKind::Sphere;
  const bool meridian = pk == PathKind::Meridian;

  if (auto t = number(path, prefix, "turns")) {
    if (*t <= 0.0) failAt(prefix + ".turns", fmt::format("expected a number of turns > 0, got {}", *t));
    target.turns = *t;
  }
  if (auto d = text(path, prefix, "direction", {"ccw", "cw"})) target.counterClockwise = *d == "ccw";
  if (pk == PathKind::Geodesic && !spec_.locations.contains(prefix + ".length")) target.length = 6.0;
  if (auto len = number(path, prefix, "length")) {
    if (*len <= 0.0) failAt(prefix + ".length", fmt::format("expected a length > 0, got {}", *len));
    target.length = *len;
  }
  if (auto dv = vector(path, prefix, "direction_vector")) {
    const double len = norm3(*dv);
    if (len < 1e-12) failAt(prefix + ".direction_vector", "expected a non-zero vector, got [0, 0, 0]");
    const Vec3 d = unitVector(*dv, len);
    const Vec3& n = spec_.surface.normal;
    const double along = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    if (sk == SurfaceKind::Plane && std::abs(along) > 1e-9) {
      failAt(prefix + ".direction_vector",
             fmt::format("the {} leaves the surface: its direction has a component {:.6g} along the plane "
                         "normal [{}, {}, {}]; expected a vector in the plane",
                         pkName, along, n[0], n[1], n[2]));
    }
    target.directionVector = d;
  }
  if (auto r = number(path, prefix, "radius")) {
    if (*r <= 0.0) failAt(prefix + ".radius", fmt::format("expected a radius > 0, got {}", *r));
    target.radius = *r;
  }
  if (pk == PathKind::Parallel && sk == SurfaceKind::Paraboloid) {
    if (spec_.surface.a != spec_.surface.b)
      failAt(pathKindGiven ? (prefix + ".kind") : "surface.a",
             fmt::format("a parallel needs a surface of revolution; this paraboloid has a = {} != b = {}",
                         spec_.surface.a, spec_.surface.b));
    if (!spec_.locations.contains(prefix + ".radius")) target.radius = 2.0;
  }
  auto colatitude = [&](const std::string& key, double& out) {
    if (auto th = number(path, prefix, key)) {
      if (!(*th > 0.0 && *th < 180.0))
        failAt(prefix + "." + key, fmt::format("expected a colatitude in (0, 180) degrees, got {}", *th));
      out = *th;
    }
  };
  colatitude("colatitude_deg", target.colatitudeDeg);
  colatitude("colatitude_start_deg", target.colatitudeStartDeg);
  colatitude("colatitude_end_deg", target.colatitudeEndDeg);
  if ((meridian && onSphere) || pk == PathKind::Loxodrome) {
    if (target.colatitudeStartDeg == target.colatitudeEndDeg)
      failAt(prefix + ".colatitude_end_deg", "expected colatitude_end_deg != colatitude_start_deg (an empty path)");
  }
  if (auto v = number(path, prefix, "tube_angle_deg")) target.tubeAngleDeg = *v;
  if (auto v = number(path, prefix, "height")) target.height = *v;
  if (auto v = number(path, prefix, "azimuth_deg")) target.azimuthDeg = *v;
  if (auto v = number(path, prefix, "pitch_angle_deg")) {
    if (!(std::abs(*v) < 90.0))
      failAt(prefix + ".pitch_angle_deg", fmt::format("expected a pitch angle in (-90, 90) degrees, got {}", *v));
    target.pitchAngleDeg = *v;
  }
  if (auto v = number(path, prefix, "heading_deg")) {
    if (!(std::abs(*v) < 90.0))
      failAt(prefix + ".heading_deg", fmt::format("expected a heading in (-90, 90) degrees from the meridians "
                                             "(90 is a parallel: use kind = \"parallel\"), got {}", *v));
    target.headingDeg = *v;
  }
  if (auto p = vector(path, prefix, "start_point")) target.startPoint = *p;
  if (auto e = expression(path, prefix, "u")) target.u = *e;
  if (auto e = expression(path, prefix, "v")) target.v = *e;
  if (auto v = number(path, prefix, "t_start")) target.tStart = *v;
  if (auto v = number(path, prefix, "t_end")) target.tEnd = *v;
  if (pk == PathKind::Uv && !(target.tEnd > target.tStart))
    failAt(spec_.locations.contains(prefix + ".t_end") ? (prefix + ".t_end") : (prefix + ".t_start"),
           fmt::format("expected t_end > t_start, got [{}, {}]", target.tStart, target.tEnd));
  if (auto pts = pointList(path, prefix, "points")) target.points = *pts;
  if (auto c = boolean(path, prefix, "closed")) target.closed = *c;
  if (auto i = text(path, prefix, "interpolation", {"spline", "polyline"})) target.interpolation = *i;
  if (auto r = number(path, prefix, "corner_radius")) {
    if (*r < 0.0) failAt(prefix + ".corner_radius", fmt::format("expected a radius >= 0, got {}", *r));
    target.cornerRadius = *r;
  }
  for (const char* key : {"curvature_start", "curvature_rate"}) {
    if (auto v = number(path, prefix, key)) {
      if (std::abs(*v) > 1e6) failAt(prefix + "." + key, fmt::format("expected |value| <= 1e6, got {}", *v));
      (std::string(key) == "curvature_start" ? target.curvatureStart : target.curvatureRate) = *v;
    }
  }
  if (pk == PathKind::Points) {
    const std::size_t need = target.closed ? 3 : 2;
    if (target.points.size() < need)
      throw badInput(spec_.locations.contains(prefix + ".points") ? where(prefix + ".points") : where(prefix),
                     "{}.points: expected at least {} points for {} path, got {}", prefix, need,
                     target.closed ? "a closed" : "an open", target.points.size());
  }
  return pk;
}

SceneSpec Reader::read() {
  spec_.sourceFile = file_;
  static const std::set<std::string> kSections{"ball",     "surface", "path",   "plate",     "solver",
                                               "timeline", "render",  "labels", "animation", "segment"};
  for (auto&& [k, v] : root_) {
    const std::string key(k.str());
    if (!kSections.contains(key)) {
      throw badInput(locOf(key, v), "{}: unknown key; a scene has the tables: {}", key, joinKeys(kSections));
    }
  }

  // [ball]
  const toml::table* ball = section("ball", {"radius", "texture", "marker"});
  if (auto r = number(ball, "ball", "radius")) {
    if (*r <= 0.0) failAt("ball.radius", fmt::format("expected a radius > 0, got {}", *r));
    spec_.ball.radius = *r;
  }
  if (auto t = anyText(ball, "ball", "texture")) {
    if (t->empty()) failAt("ball.texture", "expected a PNG or JPG file name, got an empty string");
    spec_.ball.texture = *t;
  }
  if (auto m = vector(ball, "ball", "marker")) {
    const double len = norm3(*m);
    if (len < 1e-12) failAt("ball.marker", "expected a non-zero vector (a direction in the ball), got [0, 0, 0]");
    spec_.ball.marker = unitVector(*m, len);
  }
  const double R = spec_.ball.radius;

  // [surface]
  const toml::table* surface = section(
      "surface", {"kind", "normal", "radius", "side", "axis", "major_radius", "minor_radius", "a", "b", "z"});
  static const std::map<std::string, SurfaceKind> kSurfaceKinds{
      {"plane", SurfaceKind::Plane},       {"sphere", SurfaceKind::Sphere}, {"cylinder", SurfaceKind::Cylinder},
      {"torus", SurfaceKind::Torus},       {"paraboloid", SurfaceKind::Paraboloid},
      {"saddle", SurfaceKind::Saddle},     {"height", SurfaceKind::Height}};
  if (auto kind = text(surface, "surface", "kind",
                       {"plane", "sphere", "cylinder", "torus", "paraboloid", "saddle", "height"}))
    spec_.surface.kind = kSurfaceKinds.at(*kind);
  const SurfaceKind sk = spec_.surface.kind;
  const std::string skName = toString(sk);
  const bool heightField = sk == SurfaceKind::Paraboloid || sk == SurfaceKind::Saddle || sk == SurfaceKind::Height;
  auto surfaceOnly = [&](const std::string& key, bool applies, const std::string& kinds) {
    if (!applies) forbid(surface, "surface", key, "applies to kind = " + kinds + " only; this surface is a " + skName);
  };
  for (const auto& key : kSurfaceKeys) {
    const KeyRule rule = surfaceKeyRule(key, sk);
    surfaceOnly(key, rule.applies, rule.kinds);
  }
  auto positive = [&](const std::string& key, double& target) {
    if (auto r = number(surface, "surface", key)) {
      if (*r <= 0.0) failAt("surface." + key, fmt::format("expected a value > 0, got {}", *r));
      target = *r;
    }
  };
  if (auto n = vector(surface, "surface", "normal")) {
    const double len = norm3(*n);
    if (len < 1e-12) failAt("surface.normal", "expected a non-zero vector, got [0, 0, 0]");
    spec_.surface.normal = unitVector(*n, len);
  }
  if (auto r = number(surface, "surface", "radius")) {
    if (*r <= 0.0) failAt("surface.radius", fmt::format("expected a radius > 0, got {}", *r));
    spec_.surface.radius = *r;
  }
  if (heightField) {
    if (auto side = text(surface, "surface", "side", {"above", "below"}))
      spec_.surface.side = *side == "above" ? SurfaceSide::Outside : SurfaceSide::Inside;
  } else if (auto side = text(surface, "surface", "side", {"outside", "inside"})) {
    spec_.surface.side = *side == "outside" ? SurfaceSide::Outside : SurfaceSide::Inside;
  }
  if (auto ax = vector(surface, "surface", "axis")) {
    const double len = norm3(*ax);
    if (len < 1e-12) failAt("surface.axis", "expected a non-zero vector, got [0, 0, 0]");
    spec_.surface.axis = unitVector(*ax, len);
  }
  positive("major_radius", spec_.surface.majorRadius);
  positive("minor_radius", spec_.surface.minorRadius);
  positive("a", spec_.surface.a);
  positive("b", spec_.surface.b);
  if (auto z = expression(surface, "surface", "z")) spec_.surface.z = *z;

  // Does the ball fit? (Along the path, app/ checks the curvature everywhere.)
  const bool inside = spec_.surface.side == SurfaceSide::Inside;
  auto mustFit = [&](double limit, const std::string& what, const std::string& surfaceKey) {
    if (R < limit) return;
    const std::string key = spec_.locations.contains("ball.radius") ? "ball.radius" : surfaceKey;
    failAt(key, fmt::format("a ball of radius {} does not fit inside {} (needs ball.radius < {})", R, what, limit));
  };
  if (sk == SurfaceKind::Sphere && inside)
    mustFit(spec_.surface.radius, fmt::format("a sphere of radius {}", spec_.surface.radius), "surface.radius");
  if (sk == SurfaceKind::Cylinder && inside)
    mustFit(spec_.surface.radius, fmt::format("a cylinder of radius {}", spec_.surface.radius), "surface.radius");
  if (sk == SurfaceKind::Torus) {
    if (!(spec_.surface.minorRadius < spec_.surface.majorRadius))
      failAt(spec_.locations.contains("surface.minor_radius") ? "surface.minor_radius" : "surface.major_radius",
             fmt::format("expected minor_radius < major_radius (a ring torus), got {} and {}",
                         spec_.surface.minorRadius, spec_.surface.majorRadius));
    if (inside)
      mustFit(spec_.surface.minorRadius, fmt::format("a torus tube of radius {}", spec_.surface.minorRadius),
              "surface.minor_radius");
  }

  // [plate] — Brockett's upper plate; the contact path is then derived.
  const toml::table* plate = section("plate", {"radius"});
  if (plate != nullptr) {
    PlateSpec p;
    auto r1 = number(plate, "plate", "radius");
    if (!r1) throw badInput(where("plate"), "plate.radius: missing; [plate] needs the radius R1 of the circle each plate point describes");
    if (*r1 <= 0.0) failAt("plate.radius", fmt::format("expected a radius > 0, got {}", *r1));
    p.radius = *r1;
    spec_.plate = p;
  }

  // [path]
  const toml::table* path = section("path", pathTableKeys());
  if (path != nullptr && root_.get("segment") != nullptr)
    throw badInput(where("path"), "path: a scene has either one [path] or a storyboard of [[segment]] entries, "
                                  "not both; move the [path] keys into a segment's path = {{ ... }}");
  const PathKind pk = readPath(path, "path", spec_.path);
  const bool pathKindGiven = path != nullptr && path->get("kind") != nullptr;
  if (spec_.plate) {
    if (pk != PathKind::Circle)
      failAt(pathKindGiven ? "path.kind" : "surface.kind",
             "with [plate] the contact path is the circle the plate drives; expected path.kind = \"circle\"");
    if (spec_.locations.contains("path.radius"))
      failAt("path.radius", "conflicts with [plate]: the contact circle's radius follows from plate.radius "
                            "(R1/2); remove path.radius");
  }

  readSegments();

  // [solver]
  const toml::table* solver = section("solver", {"method", "steps", "tolerance"});
  if (auto m = text(solver, "solver", "method",
                    {"exact", "magnus2", "magnus4", "rk4", "frame4", "cf4", "magnus6", "rk45", "frame6a"}))
    spec_.solver.method = *m;
  if (auto n = integer(solver, "solver", "steps")) {
    if (*n < 1 || *n > kMaxSolverSteps)
      failAt("solver.steps", fmt::format("expected an integer in [1, 1e11], got {}", *n));
    spec_.solver.steps = *n;
  }
  if (auto tol = number(solver, "solver", "tolerance")) {
    if (!(*tol >= 1e-15 && *tol <= 1.0))
      failAt("solver.tolerance", fmt::format("expected a tolerance in [1e-15, 1], got {}", *tol));
    spec_.solver.tolerance = *tol;
  }
  // A tolerance and no step count: the adaptive geometric method by default.
  // Steps and tolerance each belong to one kind of method.
  const bool methodGiven = spec_.locations.contains("solver.method");
  const bool adaptive = spec_.solver.method == "rk45" || spec_.solver.method == "frame6a";
  if (!methodGiven && spec_.solver.tolerance && !spec_.solver.steps) spec_.solver.method = "frame6a";
  else if (spec_.solver.tolerance && !adaptive)
    failAt("solver.tolerance", fmt::format("applies to the adaptive methods (\"frame6a\", \"rk45\"), but "
                                           "solver.method is \"{}\"; remove solver.tolerance or solver.steps",
                                           spec_.solver.method));
  if (adaptive && spec_.solver.steps)
    failAt("solver.steps", fmt::format("method \"{}\" chooses its own steps; set solver.tolerance instead",
                                       spec_.solver.method));

  // [timeline]
  const toml::table* timeline = section("timeline", {"samples"});
  if (auto n = integer(timeline, "timeline", "samples")) {
    if (*n < 2 || *n > kMaxTimelineSamples)
      failAt("timeline.samples", fmt::format("expected an integer in [2, 1e8], got {}", *n));
    spec_.timeline.samples = *n;
  }

  readRender();
  readLabels();
  readAnimation();
  return spec_;
}

// "a.b=value" → (["a","b"], toml node). Bare strings need no quotes.
void applyOverride(toml::table& root, const std::string& arg, std::map<std::string, SourceLoc>& locs) {
  const SourceLoc loc{"--set " + arg};
  const auto eq = arg.find('=');
  if (eq == std::string::npos || eq == 0)
    throw badInput(loc, "expected --set key.sub=value (e.g. --set ball.radius=2)");
  const std::string key = arg.substr(0, eq), value = arg.substr(eq + 1);
  std::vector<std::string> parts;
  std::size_t start = 0;
  while (true) {
    const auto dot = key.find('.', start);
    parts.push_back(key.substr(start, dot - start));
    if (dot == std::string::npos) break;
    start = dot + 1;
  }
  // A part may name an entry of an array of tables, counted from 1:
  // segment[2].path.radius (README "Storyboards").
  std::vector<std::size_t> index(parts.size(), 0);  // 0: not an array entry
  for (std::size_t i = 0; i < parts.size(); ++i) {
    std::string& p = parts[i];
    const auto open = p.find('[');
    if (open != std::string::npos && i + 1 < parts.size() && p.back() == ']' && open + 2 < p.size()) {
      const std::string digits = p.substr(open + 1, p.size() - open - 2);
      if (digits.size() <= 6 && std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; })) {
        index[i] = std::stoul(digits);
        if (index[i] == 0) throw badInput(loc, "'{}': entries are counted from 1", p);
        p.resize(open);
      }
    }
    const bool bare = !p.empty() && std::all_of(p.begin(), p.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
    if (!bare) throw badInput(loc, "'{}' is not a key path like section.key (or segment[k].key)", key);
  }
  toml::table parsed;
  try {
    parsed = toml::parse(std::string_view("v = " + value), std::string_view("--set"));
  } catch (const toml::parse_error&) {
    parsed = toml::table{};
    parsed.insert("v", value);  // a bare word: take it as a string
  }
  toml::table* t = &root;
  for (std::size_t i = 0; i + 1 < parts.size(); ++i) {
    toml::node* child = t->get(parts[i]);
    if (index[i] > 0) {
      toml::array* entries = child != nullptr ? child->as_array() : nullptr;
      const std::size_t count = entries != nullptr ? entries->size() : 0;
      if (index[i] > count)
        throw badInput(loc, "'{}[{}]': the scene has {} {} entr{}", parts[i], index[i], count, parts[i],
                       count == 1 ? "y" : "ies");
      child = entries->get(index[i] - 1);
    } else if (child == nullptr) {
      t->insert(parts[i], toml::table{});
      child = t->get(parts[i]);
    }
    if (!child->is_table()) throw badInput(loc, "'{}' is not a table, cannot set '{}'", parts[i], key);
    t = child->as_table();
  }
  t->insert_or_assign(parts.back(), std::move(*parsed.get("v")));
  locs[key] = loc;
}

}  // namespace

namespace {

toml::table parseText(std::string_view text, const std::string& sourceName) {
  try {
    return toml::parse(text, sourceName);
  } catch (const toml::parse_error& e) {
    throw badInput(SourceLoc{sourceName, static_cast<int>(e.source().begin.line),
                             static_cast<int>(e.source().begin.column)},
                   "TOML syntax error: {}", e.description());
  }
}

std::string readSceneFile(const std::filesystem::path& file, const SourceLoc& askedBy, const std::string& what) {
  std::ifstream in(file, std::ios::binary);
  std::error_code ec;
  if (!in || std::filesystem::is_directory(file, ec)) {
    if (askedBy.empty()) throw badInput(SourceLoc{file.string()}, "cannot read the scene file");
    throw badInput(askedBy, "{}: cannot read the scene file '{}'", what, file.string());
  }
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

// Tables merge key by key, anything else in `derived` replaces `base`'s.
void mergeInto(toml::table& base, const toml::table& derived) {
  for (auto&& [key, node] : derived) {
    toml::node* existing = base.get(key.str());
    if (existing != nullptr && existing->is_table() && node.is_table()) {
      mergeInto(*existing->as_table(), *node.as_table());
    } else {
      base.insert_or_assign(key, node);
    }
  }
}

// Records where every key of a parsed file is (toml++ does not carry source
// positions through node copies, and merging copies).
void collectLocations(const toml::table& t, const std::string& prefix, const std::string& file,
                      std::map<std::string, SourceLoc>& out) {
  for (auto&& [key, node] : t) {
    const std::string path = prefix.empty() ? std::string(key.str()) : prefix + "." + std::string(key.str());
    const auto& src = node.source();
    out[path] = src.begin.line == 0
                    ? SourceLoc{file}
                    : SourceLoc{file, static_cast<int>(src.begin.line), static_cast<int>(src.begin.column)};
    if (const toml::table* sub = node.as_table()) collectLocations(*sub, path, file, out);
    // [[segment]] entries: segment[1], segment[2], … (counted from 1).
    if (const toml::array* entries = node.as_array()) {
      for (std::size_t i = 0; i < entries->size(); ++i) {
        const toml::node& entry = *entries->get(i);
        const std::string item = path + "[" + std::to_string(i + 1) + "]";
        const auto& at = entry.source();
        if (at.begin.line != 0)
          out[item] = SourceLoc{file, static_cast<int>(at.begin.line), static_cast<int>(at.begin.column)};
        if (const toml::table* sub = entry.as_table()) collectLocations(*sub, item, file, out);
      }
    }
  }
}

// `extends = "other.toml"` (relative to the extending file): the other scene
// is loaded first, recursively, and this file's keys are laid over it; each
// key keeps the location of the file that set it.
toml::table resolveExtends(toml::table root, const std::filesystem::path& file,
                           std::vector<std::filesystem::path>& chain, std::map<std::string, SourceLoc>& locations) {
  const toml::node* extends = root.get("extends");
  if (extends == nullptr) {
    collectLocations(root, "", file.string(), locations);
    return root;
  }
  const auto& src = extends->source();
  const SourceLoc loc{file.string(), static_cast<int>(src.begin.line), static_cast<int>(src.begin.column)};
  if (!extends->is_string()) throw badInput(loc, "extends: expected the path of a scene file (a string)");
  const std::filesystem::path base =
      ((file.has_parent_path() ? file.parent_path() : std::filesystem::path(".")) / extends->as_string()->get())
          .lexically_normal();
  std::error_code ec;
  const std::filesystem::path canonical = std::filesystem::weakly_canonical(base, ec);
  for (const auto& seen : chain) {
    if (seen == canonical) {
      std::string cycle;
      for (const auto& c : chain) cycle += c.filename().string() + " -> ";
      throw badInput(loc, "extends: cycle: {}{}", cycle, canonical.filename().string());
    }
  }
  if (chain.size() >= 32) throw badInput(loc, "extends: more than 32 levels");
  chain.push_back(canonical);
  toml::table merged =
      resolveExtends(parseText(readSceneFile(base, loc, "extends"), base.string()), base, chain, locations);
  chain.pop_back();
  root.erase("extends");
  collectLocations(root, "", file.string(), locations);
  // A storyboard replaces the scene's motion as a whole: a child's
  // [[segment]] array replaces the parent's (arrays are not merged) and any
  // [path] it had, and a child's [path] replaces the parent's segments.
  if (root.contains("segment")) merged.erase("path");
  if (root.contains("path")) merged.erase("segment");
  mergeInto(merged, root);
  return merged;
}

}  // namespace

SceneSpec loadSceneText(std::string_view text, const std::string& sourceName, std::span<const std::string> overrides) {
  std::error_code ec;
  std::vector<std::filesystem::path> chain{std::filesystem::weakly_canonical(sourceName, ec)};
  std::map<std::string, SourceLoc> locations;  // file:line:col per key; --set arguments win
  toml::table root = resolveExtends(parseText(text, sourceName), sourceName, chain, locations);
  for (const auto& arg : overrides) applyOverride(root, arg, locations);
  SceneSpec spec = Reader(root, sourceName, std::move(locations)).read();
  return spec;
}

SceneSpec loadSceneFile(const std::filesystem::path& file, std::span<const std::string> overrides) {
  SceneSpec spec = loadSceneText(readSceneFile(file, {}, ""), file.string(), overrides);
  spec.name = file.stem().string();
  return spec;
}

}  // namespace rollspin::scene
