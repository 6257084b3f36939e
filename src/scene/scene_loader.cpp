#include "scene/scene_loader.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <fstream>
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
  const toml::node* get(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<double> number(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<long long> integer(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<std::string> text(const toml::table* t, const std::string& section, const std::string& key,
                                  const std::set<std::string>& choices);
  std::optional<Vec3> vector(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<bool> boolean(const toml::table* t, const std::string& section, const std::string& key);
  std::optional<std::string> anyText(const toml::table* t, const std::string& section, const std::string& key);
  void readRender();
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
  const toml::node* node = root_.get(name);
  if (node == nullptr) return nullptr;
  const toml::table* t = node->as_table();
  if (t == nullptr) fail(name, locOf(name, *node), "a table [" + name + "]", describeNode(*node));
  spec_.locations[name] = locOf(name, *node);
  for (auto&& [k, v] : *t) {
    const std::string key = name + "." + std::string(k.str());
    if (!allowed.contains(std::string(k.str()))) {
      throw badInput(locOf(key, v), "{}: unknown key; [{}] accepts: {}", key, name, joinKeys(allowed));
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

// [render] — image size, layout, strobe, text, camera (render issue).
void Reader::readRender() {
  const toml::table* render = section(
      "render", {"width", "height", "layout", "strobe", "title", "labels", "transparent", "msaa", "azimuth_deg",
                 "elevation_deg", "distance", "target", "follow", "fov_deg"});
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
  if (auto a = number(render, "render", "azimuth_deg")) r.azimuthDeg = *a;
  if (auto e = number(render, "render", "elevation_deg")) {
    if (!(*e > -90.0 && *e < 90.0))
      failAt("render.elevation_deg", fmt::format("expected an elevation in (-90, 90) degrees, got {}", *e));
    r.elevationDeg = *e;
  }
  if (auto d = number(render, "render", "distance")) {
    if (*d <= 0.0) failAt("render.distance", fmt::format("expected a camera distance > 0, got {}", *d));
    r.distance = *d;
  }
  if (auto t = vector(render, "render", "target")) r.target = *t;
  if (auto f = boolean(render, "render", "follow")) r.follow = *f;
  if (auto f = number(render, "render", "fov_deg")) {
    if (!(*f >= 5.0 && *f <= 120.0))
      failAt("render.fov_deg", fmt::format("expected a vertical field of view in [5, 120] degrees, got {}", *f));
    r.fovDeg = *f;
  }
  if (r.follow && spec_.locations.contains("render.target"))
    failAt("render.target", "conflicts with render.follow = true (the camera then targets the ball)");
}

void Reader::forbid(const toml::table* t, const std::string& section, const std::string& key,
                    const std::string& why) {
  if (t == nullptr) return;
  if (const toml::node* node = t->get(key)) {
    const std::string full = section + "." + key;
    throw badInput(locOf(full, *node), "{}: {}", full, why);
  }
}

double norm3(const Vec3& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

SceneSpec Reader::read() {
  spec_.sourceFile = file_;
  static const std::set<std::string> kSections{"ball", "surface", "path", "plate", "solver", "timeline", "render"};
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
    spec_.ball.marker = Vec3{(*m)[0] / len, (*m)[1] / len, (*m)[2] / len};
  }
  const double R = spec_.ball.radius;

  // [surface]
  const toml::table* surface = section("surface", {"kind", "normal", "radius", "side"});
  if (auto kind = text(surface, "surface", "kind", {"plane", "sphere"}))
    spec_.surface.kind = *kind == "plane" ? SurfaceKind::Plane : SurfaceKind::Sphere;
  if (spec_.surface.kind == SurfaceKind::Plane) {
    forbid(surface, "surface", "radius", "applies to kind = \"sphere\" only; this surface is a plane");
    forbid(surface, "surface", "side", "applies to kind = \"sphere\" only; this surface is a plane");
    if (auto n = vector(surface, "surface", "normal")) {
      const double len = norm3(*n);
      if (len < 1e-12) failAt("surface.normal", "expected a non-zero vector, got [0, 0, 0]");
      spec_.surface.normal = {(*n)[0] / len, (*n)[1] / len, (*n)[2] / len};
    }
  } else {
    forbid(surface, "surface", "normal", "applies to kind = \"plane\" only; this surface is a sphere");
    if (auto r = number(surface, "surface", "radius")) {
      if (*r <= 0.0) failAt("surface.radius", fmt::format("expected a radius > 0, got {}", *r));
      spec_.surface.radius = *r;
    }
    if (auto side = text(surface, "surface", "side", {"outside", "inside"}))
      spec_.surface.side = *side == "outside" ? SurfaceSide::Outside : SurfaceSide::Inside;
    if (spec_.surface.side == SurfaceSide::Inside && !(R < spec_.surface.radius)) {
      const std::string key = spec_.locations.contains("ball.radius") ? "ball.radius" : "surface.radius";
      failAt(key, fmt::format("a ball of radius {} does not fit inside a sphere of radius {} "
                              "(inside rolling needs ball.radius < surface.radius)",
                              R, spec_.surface.radius));
    }
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
  const toml::table* path = section(
      "path", {"kind", "turns", "direction", "length", "direction_vector", "radius", "colatitude_deg"});
  const bool pathKindGiven = path != nullptr && path->get("kind") != nullptr;
  if (auto kind = text(path, "path", "kind", {"line", "circle", "parallel"})) {
    spec_.path.kind = *kind == "line" ? PathKind::Line : *kind == "circle" ? PathKind::Circle : PathKind::Parallel;
  } else if (spec_.surface.kind == SurfaceKind::Sphere) {
    spec_.path.kind = PathKind::Parallel;  // the one path a sphere offers
  }
  const PathKind pk = spec_.path.kind;
  const std::string pkName = toString(pk);
  const std::string needs = pk == PathKind::Parallel ? "sphere" : "plane";
  if (toString(spec_.surface.kind) != needs) {
    const std::string key = pathKindGiven ? "path.kind" : "surface.kind";
    failAt(key, fmt::format("a {} path lies on a {}, but surface.kind is \"{}\" (the path would leave the surface)",
                            pkName, needs, toString(spec_.surface.kind)));
  }
  auto only = [&](const std::string& key, bool applies, const std::string& kinds) {
    if (!applies) forbid(path, "path", key, "applies to path kind " + kinds + " only; this path is a " + pkName);
  };
  only("turns", pk != PathKind::Line, "circle or parallel");
  only("length", pk == PathKind::Line, "line");
  only("direction_vector", pk == PathKind::Line, "line");
  only("radius", pk == PathKind::Circle, "circle");
  only("colatitude_deg", pk == PathKind::Parallel, "parallel");
  if (auto t = number(path, "path", "turns")) {
    if (*t <= 0.0) failAt("path.turns", fmt::format("expected a number of turns > 0, got {}", *t));
    spec_.path.turns = *t;
  }
  if (auto d = text(path, "path", "direction", {"ccw", "cw"})) spec_.path.counterClockwise = *d == "ccw";
  if (auto len = number(path, "path", "length")) {
    if (*len <= 0.0) failAt("path.length", fmt::format("expected a length > 0, got {}", *len));
    spec_.path.length = *len;
  }
  if (auto dv = vector(path, "path", "direction_vector")) {
    const double len = norm3(*dv);
    if (len < 1e-12) failAt("path.direction_vector", "expected a non-zero vector, got [0, 0, 0]");
    const Vec3 d{(*dv)[0] / len, (*dv)[1] / len, (*dv)[2] / len};
    const Vec3& n = spec_.surface.normal;
    const double along = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    if (std::abs(along) > 1e-9) {
      failAt("path.direction_vector",
             fmt::format("the line leaves the surface: its direction has a component {:.6g} along the plane "
                         "normal [{}, {}, {}]; expected a vector in the plane",
                         along, n[0], n[1], n[2]));
    }
    spec_.path.directionVector = d;
  }
  if (auto r = number(path, "path", "radius")) {
    if (*r <= 0.0) failAt("path.radius", fmt::format("expected a radius > 0, got {}", *r));
    spec_.path.radius = *r;
  }
  if (auto th = number(path, "path", "colatitude_deg")) {
    if (!(*th > 0.0 && *th < 180.0))
      failAt("path.colatitude_deg", fmt::format("expected a colatitude in (0, 180) degrees, got {}", *th));
    spec_.path.colatitudeDeg = *th;
  }
  if (spec_.plate) {
    if (pk != PathKind::Circle)
      failAt(pathKindGiven ? "path.kind" : "surface.kind",
             "with [plate] the contact path is the circle the plate drives; expected path.kind = \"circle\"");
    if (spec_.locations.contains("path.radius"))
      failAt("path.radius", "conflicts with [plate]: the contact circle's radius follows from plate.radius "
                            "(R1/2); remove path.radius");
  }

  // [solver]
  const toml::table* solver = section("solver", {"method", "steps"});
  if (auto m = text(solver, "solver", "method", {"exact", "magnus2", "magnus4", "rk4"})) spec_.solver.method = *m;
  if (auto n = integer(solver, "solver", "steps")) {
    if (*n < 1 || *n > kMaxSolverSteps)
      failAt("solver.steps", fmt::format("expected an integer in [1, 1e11], got {}", *n));
    spec_.solver.steps = *n;
  }

  // [timeline]
  const toml::table* timeline = section("timeline", {"samples"});
  if (auto n = integer(timeline, "timeline", "samples")) {
    if (*n < 2 || *n > kMaxTimelineSamples)
      failAt("timeline.samples", fmt::format("expected an integer in [2, 1e8], got {}", *n));
    spec_.timeline.samples = *n;
  }

  readRender();
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
  for (const auto& p : parts) {
    const bool bare = !p.empty() && std::all_of(p.begin(), p.end(), [](char c) {
      return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-';
    });
    if (!bare) throw badInput(loc, "'{}' is not a key path like section.key", key);
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
    if (child == nullptr) {
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
