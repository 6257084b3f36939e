// The scene schema: one TOML document (its `extends` resolved, its --set
// overrides laid in) → a validated SceneSpec, every key remembering where it
// came from. Internal to scene/: scene_loader.cpp composes it with the
// sources (scene_sources.hpp).
#pragma once

#include <toml++/toml.h>

#include <algorithm>
#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "scene/scene_spec.hpp"
#include "scene/scene_tables.hpp"

namespace rollspin::scene::schema {

// For messages: "string \"x\"", "integer 3", …
std::string describeNode(const toml::node& node);
std::string joinKeys(const std::set<std::string>& keys);
// "KEY: unknown key; did you mean `NEAR`? TABLE accepts: …" (the nearest
// accepted key when the typed one is a likely typo); "did you mean
// `colatitude_deg` (in degrees)?" alone for the key without its unit suffix.
Error unknownKey(const SourceLoc& loc, const std::string& fullKey, const std::string& typed, const std::string& table,
                 const std::set<std::string>& allowed);
// "an image size in [1, 8192] pixels": what a row's messages say it expects.
std::string expectation(std::string_view noun, std::string_view unitWord, std::string_view expected,
                        const std::optional<Bounds>& bounds);
// Whether v lies within the bounds (an absent end is unbounded).
bool withinBounds(const Bounds& b, double v);
// The names of a table's keys (the keys its section accepts).
template <class S>
std::set<std::string> namesOf(const KeyTable<S>& rows) {
  std::set<std::string> out;
  for (const KeyRow<S>& row : rows) out.emplace(row.name);
  return out;
}

// The keys a path table accepts: kind and every kind-specific path key.
std::set<std::string> pathTableKeys();

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
  void readSegmentSurface(const toml::table& table, const std::string& prefix, bool moves, SegmentSpec& seg);
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
  PathKind readPath(const toml::table* path, const std::string& prefix, PathSpec& target, const SurfaceSpec& surface,
                    const std::string& surfaceKey);
  void readSurface(const toml::table* surface, const std::string& prefix, SurfaceSpec& target);
  void readRender();
  void readGlContext(const toml::table* table);
  void readAnimation();
  void readLabels();
  void readFigure();
  // Every row of `rows` that is not read by rule code: read, checked
  // (bounds, non-empty text, non-zero direction) and stored in `target`.
  template <class S>
  void readKeys(const toml::table* t, const std::string& section, const KeyTable<S>& rows, S& target);
  // One row, whatever its byRule says: rule code reads a key where its rules allow.
  template <class S>
  void readRow(const toml::table* t, const std::string& section, const KeyRow<S>& row, S& target) {
    std::visit([&](auto field) { readField(t, section, row, target, field); }, row.field);
  }
  // A value rule code read, against its row's bounds.
  template <class S>
  void checkRow(const KeyRow<S>& row, const std::string& full, double v) const {
    checkValue(full, row.noun, row.unitWord, row.expected, row.accepts, row.bounds, v, fmt::format("{}", v));
  }
  template <class S, class F>
  void readField(const toml::table* t, const std::string& section, const KeyRow<S>& row, S& target, F field);
  void checkValue(const std::string& full, std::string_view noun, std::string_view unitWord, std::string_view expected,
                  bool (*accepts)(double), const std::optional<Bounds>& bounds, double v,
                  const std::string& shown) const {
    if (accepts != nullptr ? accepts(v) : (!bounds || withinBounds(*bounds, v))) return;
    failAt(full, fmt::format("expected {}, got {}", expectation(noun, unitWord, expected, bounds), shown));
  }
  void forbid(const toml::table* t, const std::string& section, const std::string& key, const std::string& why);

  [[noreturn]] void fail(const std::string& key, const SourceLoc& loc, const std::string& expected,
                         const std::string& got) const {
    throw badInput(loc, "{}: expected {}, got {}", key, expected, got);
  }
  [[noreturn]] void failAt(const std::string& key, const std::string& message) const {
    throw badInput(where(key), "{}: {}", key, message);
  }
  // The first of a kind's blamed keys that the scene gave, else the last.
  std::string blamedKey(const geometry::SurfaceProblem& problem) const {
    for (std::size_t i = 0; i + 1 < problem.keys.size(); ++i)
      if (spec_.locations.contains(problem.keys[i])) return problem.keys[i];
    return problem.keys.back();
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

template <class S>
void Reader::readKeys(const toml::table* t, const std::string& section, const KeyTable<S>& rows, S& target) {
  for (const KeyRow<S>& row : rows)
    if (!row.byRule) readRow(t, section, row, target);
}

Vec3 unitVector(const Vec3& v, double len);
double norm3(const Vec3& v);

template <class S, class F>
void Reader::readField(const toml::table* t, const std::string& section, const KeyRow<S>& row, S& target, F field) {
  const std::string key(row.name);
  const std::string full = dotted(section, key);
  auto check = [&](double v, const std::string& shown) {
    checkValue(full, row.noun, row.unitWord, row.expected, row.accepts, row.bounds, v, shown);
  };
  if constexpr (std::is_same_v<F, double S::*> || std::is_same_v<F, std::optional<double> S::*>) {
    if (auto v = number(t, section, key)) {
      check(*v, fmt::format("{}", *v));
      target.*field = *v;
    }
  } else if constexpr (std::is_same_v<F, long long S::*> || std::is_same_v<F, std::optional<long long> S::*>) {
    if (auto n = integer(t, section, key)) {
      check(double(*n), fmt::format("{}", *n));
      target.*field = *n;
    }
  } else if constexpr (std::is_same_v<F, bool S::*> || std::is_same_v<F, std::optional<bool> S::*>) {
    if (auto b = boolean(t, section, key)) target.*field = *b;
  } else if constexpr (std::is_same_v<F, std::string S::*> || std::is_same_v<F, std::optional<std::string> S::*>) {
    if (!row.choices.empty()) {
      if (auto v = text(t, section, key, {row.choices.begin(), row.choices.end()})) target.*field = *v;
    } else if (auto v = anyText(t, section, key)) {
      if (!row.noun.empty() && v->empty()) failAt(full, fmt::format("expected {}, got an empty string", row.noun));
      target.*field = *v;
    }
  } else if constexpr (std::is_same_v<F, std::optional<Vec3> S::*>) {
    if (auto v = vector(t, section, key)) {
      // A vector with a noun is a direction: non-zero, kept unit.
      if (!row.noun.empty()) {
        const double len = norm3(*v);
        if (len < 1e-12) failAt(full, fmt::format("expected {}, got [0, 0, 0]", row.noun));
        *v = unitVector(*v, len);
      }
      target.*field = *v;
    }
  } else if constexpr (std::is_same_v<F, ChoiceField<S>>) {
    if (auto v = text(t, section, key, {row.choices.begin(), row.choices.end()}))
      field.set(target, std::size_t(std::find(row.choices.begin(), row.choices.end(), *v) - row.choices.begin()));
  }
}

}  // namespace rollspin::scene::schema
