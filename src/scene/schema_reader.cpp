#include "scene/schema_reader.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>

#include "core/text.hpp"
#include "scene/scene_keys.hpp"
#include "spin/propagator.hpp"

namespace rollspin::scene::schema {

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

namespace {

// The unit suffixes of the schema's key names (scene_keys.cpp: angles in
// degrees, a figure's size in millimetres and its font in points), with what
// a user may type instead ("_rad", "_degrees") or leave off.
struct UnitSuffix {
  std::string_view suffix;
  std::string_view unit;
};
constexpr std::array<UnitSuffix, 3> kUnitSuffixes{{{"_deg", "degrees"}, {"_mm", "millimetres"}, {"_pt", "points"}}};
constexpr std::array<std::string_view, 7> kTypedUnitSuffixes{"_degrees", "_deg", "_radians", "_rad",
                                                             "_mm",      "_cm",  "_pt"};

std::string_view withoutUnit(std::string_view key) {
  for (const std::string_view suffix : kTypedUnitSuffixes)
    if (key.size() > suffix.size() && key.ends_with(suffix)) return key.substr(0, key.size() - suffix.size());
  return key;
}

// `colatitude` or `colatitude_rad` for `colatitude_deg`: the accepted key
// that is the typed one with the schema's unit; nullopt when there is none.
std::optional<std::pair<std::string, std::string_view>> sameKeyInItsUnit(const std::string& typed,
                                                                         const std::set<std::string>& allowed) {
  for (const std::string& key : allowed)
    for (const UnitSuffix& u : kUnitSuffixes)
      if (key != typed && key.ends_with(u.suffix) && withoutUnit(key) == withoutUnit(typed))
        return std::pair{key, u.unit};
  return std::nullopt;
}

}  // namespace

Error unknownKey(const SourceLoc& loc, const std::string& fullKey, const std::string& typed, const std::string& table,
                 const std::set<std::string>& allowed) {
  // The same key in the schema's unit is the answer; the whole list would bury it.
  if (const auto inUnit = sameKeyInItsUnit(typed, allowed))
    return badInput(loc, "{}: unknown key; did you mean `{}` (in {})?", fullKey, inUnit->first, inUnit->second);
  const std::string guess = nearestName(typed, std::vector<std::string>(allowed.begin(), allowed.end()));
  const std::string accepts = table.ends_with(":") ? table : table + " accepts:";
  if (guess.empty()) return badInput(loc, "{}: unknown key; {} {}", fullKey, accepts, joinKeys(allowed));
  return badInput(loc, "{}: unknown key; did you mean `{}`? {} {}", fullKey, guess, accepts, joinKeys(allowed));
}

std::set<std::string> pathTableKeys() { return keysOf("path"); }

namespace {

// A bound as messages write it: 1e11 and 1e8 (the step and sample limits)
// as powers of ten, anything else in the shortest round-trip form.
std::string boundNumber(double v) {
  if (std::abs(v) >= 1e7) {
    const double exponent = std::round(std::log10(std::abs(v)));
    if (std::pow(10.0, exponent) == std::abs(v)) return fmt::format("{}1e{}", v < 0 ? "-" : "", exponent);
  }
  return fmt::format("{}", v);
}

std::string boundsPhrase(const Bounds& b) {
  if (b.lo && b.hi)
    return fmt::format("in {}{}, {}{}", b.loOpen ? "(" : "[", boundNumber(*b.lo), boundNumber(*b.hi),
                       b.hiOpen ? ")" : "]");
  if (b.lo) return fmt::format("{} {}", b.loOpen ? ">" : ">=", boundNumber(*b.lo));
  if (b.hi) return fmt::format("{} {}", b.hiOpen ? "<" : "<=", boundNumber(*b.hi));
  return "";
}

}  // namespace

std::string expectation(std::string_view noun, std::string_view unitWord, std::string_view expected,
                        const std::optional<Bounds>& bounds) {
  if (!expected.empty()) return std::string(expected);
  std::string out(noun);
  if (bounds) out += " " + boundsPhrase(*bounds);
  if (!unitWord.empty()) out += " " + std::string(unitWord);
  return out;
}

bool withinBounds(const Bounds& b, double v) {
  if (b.lo && !(b.loOpen ? v > *b.lo : v >= *b.lo)) return false;
  if (b.hi && !(b.hiOpen ? v < *b.hi : v <= *b.hi)) return false;
  return true;
}

namespace {

// "\"frame6a\", \"rk45\"": the adaptive methods of spin's table, for messages.
std::string adaptiveNames() {
  std::set<std::string> names;
  for (spin::Method m : spin::allMethods())
    if (spin::isAdaptive(m)) names.emplace(fmt::format("\"{}\"", spin::methodName(m)));
  return joinKeys(names);
}

// A TOML number as a double; nullopt for anything else. An integer above
// 2^53 takes the nearest double: toml++'s value<double>() refuses (returns
// nullopt for) an integer a double cannot hold exactly, and `t_end =
// 60283185307179586` is a number however it is rounded (found by fuzz_scene).
std::optional<double> numberOf(const toml::node& node) {
  if (const auto* f = node.as_floating_point()) return f->get();
  if (const auto* i = node.as_integer()) return static_cast<double>(i->get());
  return std::nullopt;
}

// The same, and nullopt for inf and nan too: a vector's element or a point's
// coordinate, which has no key of its own for the "finite" message.
std::optional<double> finiteNumberOf(const toml::node& node) {
  const std::optional<double> v = numberOf(node);
  if (v && std::isfinite(*v)) return v;
  return std::nullopt;
}

}  // namespace

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
    if (!allowed.contains(std::string(k.str())))
      throw unknownKey(locOf(key, v), key, std::string(k.str()), what, allowed);
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
  const double v = *numberOf(*node);
  if (!std::isfinite(v)) fail(full, locOf(full, *node), "a finite number", describeNode(*node));
  return v;
}

std::optional<long long> Reader::integer(const toml::table* t, const std::string& section, const std::string& key) {
  const toml::node* node = get(t, section, key);
  if (node == nullptr) return std::nullopt;
  const std::string full = section + "." + key;
  // 1e5 is how docs/getting-started.md#limits-and-errors writes limits: a float that is exactly an integer counts as
  // one.
  if (const auto* f = node->as_floating_point()) {
    const double v = f->get();
    if (std::isfinite(v) && v == std::trunc(v) && std::fabs(v) < 9.2e18) return static_cast<long long>(v);
  }
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
    const std::optional<double> x = finiteNumberOf(e);
    if (!x) fail(full, locOf(full, *node), expected, "element " + std::to_string(i) + " = " + describeNode(e));
    v[i] = *x;
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

std::optional<std::string> Reader::expression(const toml::table* t, const std::string& section,
                                              const std::string& key) {
  const toml::node* node = get(t, section, key);
  if (node == nullptr) return std::nullopt;
  const std::string full = section + "." + key;
  if (!node->is_string())
    fail(full, locOf(full, *node), "an expression string such as \"0.3*sin(x)\"", describeNode(*node));
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
      const std::optional<double> x = finiteNumberOf(e);
      if (!x) fail(full, locOf(full, *node), expected, "point " + std::to_string(i + 1) + " has " + describeNode(e));
      xs.push_back(*x);
    }
    if (!points.empty() && xs.size() != points.front().size())
      fail(full, locOf(full, *node), "all points with the same number of coordinates",
           "point " + std::to_string(i + 1) + " with " + std::to_string(xs.size()));
    points.push_back(std::move(xs));
  }
  return points;
}

void Reader::forbid(const toml::table* t, const std::string& section, const std::string& key, const std::string& why) {
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

// A kind names its keys under "surface."; a segment's surface table has
// its own prefix ("segment[3].surface").
static geometry::SurfaceProblem underTable(geometry::SurfaceProblem problem, const std::string& table) {
  for (std::string& key : problem.keys)
    if (key.rfind("surface.", 0) == 0) key = table + key.substr(7);
  return problem;
}

// A surface table ([surface], or a segment's surface = { ... }): its kind
// and the kind's own keys, each read and checked as its declaration says.
// `prefix` names the table in messages and locations.
void Reader::readSurface(const toml::table* surface, const std::string& prefix, SurfaceSpec& target) {
  std::set<std::string> surfaceNames;
  for (const auto& row : surfaceKinds()) surfaceNames.emplace(row.name);
  if (auto kind = text(surface, prefix, "kind", surfaceNames))
    for (const auto& row : surfaceKinds())
      if (row.name == *kind) target.kind = row.kind;
  const SurfaceKind sk = target.kind;
  const std::string skName = toString(sk);
  auto surfaceOnly = [&](const std::string& key, bool applies, const std::string& kinds) {
    if (!applies) forbid(surface, prefix, key, "applies to kind = " + kinds + " only; this surface is a " + skName);
  };
  for (const auto& key : allSurfaceKeys()) {
    const KeyRule rule = surfaceKeyRule(key, sk);
    surfaceOnly(key, rule.applies, rule.kinds);
  }
  const SceneSurfaceKind& kindRow = sceneSurfaceKind(sk);
  target.params = ParamSet(kindRow.geometry->params);
  for (const ParamDecl& decl : kindRow.geometry->params) {
    const std::string full = prefix + "." + decl.key;
    switch (decl.type) {
      case ParamType::Number:
        if (auto v = number(surface, prefix, decl.key)) {
          if (!(*v > decl.lowerBound))
            failAt(full, fmt::format("expected {} > {}, got {}", decl.noun, decl.lowerBound, *v));
          target.params.set(decl.key, *v);
        }
        break;
      case ParamType::Direction:
        if (auto v = vector(surface, prefix, decl.key)) {
          const double len = norm3(*v);
          if (len < 1e-12) failAt(full, "expected a non-zero vector, got [0, 0, 0]");
          target.params.set(decl.key, unitVector(*v, len));
        }
        break;
      case ParamType::Choice:
        if (auto v = text(surface, prefix, decl.key, {decl.choices.begin(), decl.choices.end()}))
          target.params.set(decl.key, *v);
        break;
      case ParamType::Expression:
        if (auto v = expression(surface, prefix, decl.key)) target.params.set(decl.key, *v);
        break;
    }
  }
  // Values the kind refuses (a ball that does not fit inside, a torus that
  // is not a ring); along the path, jobs/ checks the curvature everywhere.
  if (kindRow.geometry->check)
    if (auto problem = kindRow.geometry->check(target.params, spec_.ball.radius)) {
      failAt(blamedKey(underTable(*problem, prefix)), problem->message);
    }
}

// The keys of a path table ([path], or a segment's path): kind and the
// kind-specific keys, validated against the surface. `prefix` names the
// table in messages and locations ("path", "segment[2].path").
PathKind Reader::readPath(const toml::table* path, const std::string& prefix, PathSpec& target,
                          const SurfaceSpec& surface, const std::string& surfaceKey) {
  const SurfaceKind sk = surface.kind;
  const std::string skName = toString(sk);
  const bool pathKindGiven = path != nullptr && path->get("kind") != nullptr;
  std::set<std::string> pathNames;
  for (const auto& row : pathKinds()) pathNames.emplace(row.name);
  if (auto kind = text(path, prefix, "kind", pathNames)) {
    for (const auto& row : pathKinds())
      if (row.name == *kind) target.kind = row.kind;
  } else if (sk != SurfaceKind::Plane) {
    target.kind = sceneSurfaceKind(sk).defaultPath;  // a curved surface's natural path (e.g. a parallel)
  }
  const PathKind pk = target.kind;
  const std::string pkName = toString(pk);
  const bool lies = liesOn(pk, sk);
  const std::string needs = describe(pathKindRow(pk).liesOn);
  if (!lies) {
    const std::string key = pathKindGiven ? (prefix + ".kind") : surfaceKey + ".kind";
    failAt(key, fmt::format("a {} path lies on a {}, but {}.kind is \"{}\" (the path would leave the surface)", pkName,
                            needs, surfaceKey, skName));
  }
  auto only = [&](const std::string& key, bool applies, const std::string& kinds) {
    if (!applies)
      forbid(path, prefix, key,
             "applies to path kind " + kinds + " only; this path is a " + pkName + " on a " + skName);
  };
  for (const auto& key : allPathKeys()) {
    const KeyRule rule = pathKeyRule(key, pk, sk);
    only(key, rule.applies, rule.kinds);
  }
  const bool onSphere = sk == SurfaceKind::Sphere;
  const bool meridian = pk == PathKind::Meridian;
  auto dottedKey = [&](std::string_view name) { return dotted(prefix, name); };

  // A geodesic's own default length; the table's rows (only the kind's keys
  // are present: the others were refused above), then the rules between keys.
  if (pk == PathKind::Geodesic && !spec_.locations.contains(dottedKey(key::kLength))) target.length = 6.0;
  readKeys(path, prefix, pathKeys(), target);
  readRow(path, prefix, rowOf(pathKeys(), key::kDirectionVector), target);
  if (target.directionVector && sk == SurfaceKind::Plane) {
    const Vec3& d = *target.directionVector;
    const Vec3& n = surface.params.vector("normal");
    const double along = d[0] * n[0] + d[1] * n[1] + d[2] * n[2];
    if (std::abs(along) > 1e-9)
      failAt(dottedKey(key::kDirectionVector),
             fmt::format("the {} leaves the surface: its direction has a component {:.6g} along the plane "
                         "normal [{}, {}, {}]; expected a vector in the plane",
                         pkName, along, n[0], n[1], n[2]));
  }
  if (pk == PathKind::Parallel) {
    const geometry::SurfaceKindRow& surfaceRow = *sceneSurfaceKind(sk).geometry;
    if (surfaceRow.revolutionProblem)
      if (auto problem = surfaceRow.revolutionProblem(surface.params))
        failAt(pathKindGiven ? (prefix + ".kind") : blamedKey(underTable(*problem, surfaceKey)), problem->message);
    if (surfaceRow.parallelRadius && !spec_.locations.contains(dottedKey(key::kRadius)))
      target.radius = *surfaceRow.parallelRadius;
  }
  if ((meridian && onSphere) || pk == PathKind::Loxodrome) {
    if (target.colatitudeStartDeg == target.colatitudeEndDeg)
      failAt(dottedKey(key::kColatitudeEndDeg),
             fmt::format("expected {} != {} (an empty path)", key::kColatitudeEndDeg, key::kColatitudeStartDeg));
  }
  if (auto e = expression(path, prefix, std::string(key::kU))) target.u = *e;
  if (auto e = expression(path, prefix, std::string(key::kV))) target.v = *e;
  if (pk == PathKind::Uv && !(target.tEnd > target.tStart))
    failAt(spec_.locations.contains(dottedKey(key::kTEnd)) ? dottedKey(key::kTEnd) : dottedKey(key::kTStart),
           fmt::format("expected {} > {}, got [{}, {}]", key::kTEnd, key::kTStart, target.tStart, target.tEnd));
  if (auto pts = pointList(path, prefix, std::string(key::kPoints))) target.points = *pts;
  if (pk == PathKind::Points) {
    const std::size_t need = target.closed ? 3 : 2;
    const std::string points = dottedKey(key::kPoints);
    if (target.points.size() < need)
      throw badInput(spec_.locations.contains(points) ? where(points) : where(prefix),
                     "{}: expected at least {} points for {} path, got {}", points, need,
                     target.closed ? "a closed" : "an open", target.points.size());
  }
  return pk;
}

SceneSpec Reader::read() {
  spec_.sourceFile = file_;
  // The tables are the registry's (scene_keys.cpp); `extends` was resolved before.
  std::set<std::string> kSections;
  for (const std::string& s : keySections())
    if (!s.empty() && s.find('.') == std::string::npos) kSections.insert(s);
  for (auto&& [k, v] : root_) {
    const std::string key(k.str());
    if (!kSections.contains(key)) throw unknownKey(locOf(key, v), key, key, "a scene has the tables:", kSections);
  }

  // [ball]
  readKeys(section("ball", namesOf(ballKeys())), "ball", ballKeys(), spec_.ball);
  // [surface]
  readSurface(section("surface", keysOf("surface")), "surface", spec_.surface);

  // [plate] — Brockett's upper plate; the contact path is then derived.
  const toml::table* plate = section("plate", namesOf(plateKeys()));
  if (plate != nullptr) {
    PlateSpec p;
    const KeyRow<PlateSpec>& radius = rowOf(plateKeys(), key::kRadius);
    const std::string radiusKey = dotted("plate", radius.name);
    auto r1 = number(plate, "plate", std::string(radius.name));
    if (!r1)
      throw badInput(where("plate"),
                     "{}: missing; [plate] needs the radius R1 of the circle each plate point describes", radiusKey);
    checkRow(radius, radiusKey, *r1);
    p.radius = *r1;
    spec_.plate = p;
  }

  // [path]
  const toml::table* path = section("path", pathTableKeys());
  if (path != nullptr && root_.get("segment") != nullptr)
    throw badInput(where("path"),
                   "path: a scene has either one [path] or a storyboard of [[segment]] entries, "
                   "not both; move the [path] keys into a segment's path = {{ ... }}");
  const PathKind pk = readPath(path, "path", spec_.path, spec_.surface, "surface");
  const bool pathKindGiven = path != nullptr && path->get("kind") != nullptr;
  if (spec_.plate) {
    if (pk != PathKind::Circle)
      failAt(pathKindGiven ? "path.kind" : "surface.kind",
             "with [plate] the contact path is the circle the plate drives; expected path.kind = \"circle\"");
    if (spec_.locations.contains("path.radius"))
      failAt("path.radius",
             "conflicts with [plate]: the contact circle's radius follows from plate.radius "
             "(R1/2); remove path.radius");
  }

  readSegments();

  // [solver]
  const toml::table* solver = section("solver", namesOf(solverKeys()));
  // The method names are spin's (one table there); the scene keeps the text.
  readKeys(solver, "solver", solverKeys(), spec_.solver);
  // A tolerance and no step count: the adaptive geometric method by default.
  // Steps and tolerance each belong to one kind of method.
  const bool methodGiven = spec_.locations.contains(dotted("solver", key::kMethod));
  const bool adaptive = spin::isAdaptive(*spin::parseMethod(spec_.solver.method));  // a name from the table
  if (!methodGiven && spec_.solver.tolerance && !spec_.solver.steps)
    spec_.solver.method = spin::methodName(spin::Method::Frame6a);
  else if (spec_.solver.tolerance && !adaptive)
    failAt(dotted("solver", key::kTolerance),
           fmt::format("applies to the adaptive methods ({}), but solver.{} is \"{}\"; remove solver.{} or solver.{}",
                       adaptiveNames(), key::kMethod, spec_.solver.method, key::kTolerance, key::kSteps));
  if (adaptive && spec_.solver.steps)
    failAt(dotted("solver", key::kSteps), fmt::format("method \"{}\" chooses its own steps; set solver.{} instead",
                                                      spec_.solver.method, key::kTolerance));

  // [timeline]
  readKeys(section("timeline", namesOf(timelineKeys())), "timeline", timelineKeys(), spec_.timeline);

  readRender();
  readFigure();
  readLabels();
  readAnimation();
  return spec_;
}

// "a.b=value" → (["a","b"], toml node). Bare strings need no quotes.

}  // namespace rollspin::scene::schema
