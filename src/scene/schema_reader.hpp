// The scene schema: one TOML document (its `extends` resolved, its --set
// overrides laid in) → a validated SceneSpec, every key remembering where it
// came from. Internal to scene/: scene_loader.cpp composes it with the
// sources (scene_sources.hpp).
#pragma once

#include <toml++/toml.h>

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "scene/scene_spec.hpp"

namespace rollspin::scene::schema {

// For messages: "string \"x\"", "integer 3", …
std::string describeNode(const toml::node& node);
std::string joinKeys(const std::set<std::string>& keys);
// "KEY: unknown key; did you mean `NEAR`? TABLE accepts: …" (the nearest
// accepted key when the typed one is a likely typo); "did you mean
// `colatitude_deg` (in degrees)?" alone for the key without its unit suffix.
Error unknownKey(const SourceLoc& loc, const std::string& fullKey, const std::string& typed,
                 const std::string& table, const std::set<std::string>& allowed);
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


}  // namespace rollspin::scene::schema
