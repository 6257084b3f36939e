#include "scene/scene_keys.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <limits>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "core/error.hpp"
#include "core/text.hpp"
#include "media/output_format.hpp"
#include "render/gl_context.hpp"
#include "scene/scene_spec.hpp"
#include "scene/scene_tables.hpp"
#include "scene/surface_kinds.hpp"
#include "spin/propagator.hpp"

namespace rollspin::scene {

namespace {

// Defaults are read off a default SceneSpec, so that the reference shows
// the values the engine starts from (scene_spec.hpp), never a copy of them.
std::string num(double v) { return fmt::format("{}", v); }
std::string vectorText(const Vec3& v) { return fmt::format("[{}, {}, {}]", v[0], v[1], v[2]); }
std::string inQuotes(std::string_view s) { return fmt::format("\"{}\"", s); }

Bounds above(double lo) { return {lo, std::nullopt, true, false}; }

struct Row {
  std::string type, defaultText;
  std::optional<Bounds> bounds;
  std::vector<std::string> choices;
  std::string rangeNote, units, meaning;
};

KeyInfo info(std::string section, std::string key, Row r, std::string appliesTo = "") {
  return {
      std::move(section),   std::move(key),         std::move(r.type),  std::move(r.defaultText), r.bounds,
      std::move(r.choices), std::move(r.rangeNote), std::move(r.units), std::move(r.meaning),     std::move(appliesTo)};
}

// [surface]: each kind declares its own keys (geometry/surface_kinds.cpp,
// ParamDecl: type, default, range, units, meaning); the reference lists each
// key once, with the kinds it applies to and, where kinds differ, each one's
// default and meaning.
std::string declDefault(const ParamDecl& decl) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, double>) return num(v);
        else if constexpr (std::is_same_v<T, std::string>) return inQuotes(v);
        else return vectorText(v);
      },
      decl.defaultValue);
}

std::string declType(ParamType type) {
  switch (type) {
    case ParamType::Number: return "number";
    case ParamType::Direction: return "[x, y, z]";
    case ParamType::Choice: return "string";
    case ParamType::Expression: return "expression";
  }
  return "?";
}

std::vector<KeyInfo> surfaceKeyInfos(const SurfaceSpec& d) {
  std::vector<std::string> kindNames;
  for (const auto& row : surfaceKinds()) kindNames.emplace_back(row.name);
  std::vector<KeyInfo> out{
      info("surface", "kind",
           {"string", inQuotes(toString(d.kind)), {}, kindNames, "", "", "the surface the ball rolls on"})};
  for (const std::string& key : allSurfaceKeys()) {
    // (kind, declaration) for every kind that declares the key.
    std::vector<std::pair<std::string, const ParamDecl*>> decls;
    for (const auto& row : surfaceKinds())
      for (const ParamDecl& decl : surfaceKeyDecls(row.kind))
        if (decl.key == key) decls.emplace_back(std::string(row.name), &decl);
    const ParamDecl& first = *decls.front().second;
    // One value when every kind agrees, else "k1, k2: value; k3: other".
    auto perKind = [&](auto field) {
      std::vector<std::pair<std::string, std::string>> groups;  // (value, kinds)
      for (const auto& [kind, decl] : decls) {
        const std::string value = field(*decl);
        auto it = std::find_if(groups.begin(), groups.end(), [&](const auto& g) { return g.first == value; });
        if (it == groups.end()) groups.emplace_back(value, kind);
        else it->second += ", " + kind;
      }
      if (groups.size() == 1) return groups.front().first;
      std::string joined;
      for (const auto& [value, kinds] : groups) joined += (joined.empty() ? "" : "; ") + kinds + ": " + value;
      return joined;
    };
    Row row{declType(first.type), perKind(declDefault), {}, {}, "", first.units, perKind([](const ParamDecl& decl) {
              return decl.meaning;
            })};
    if (first.type == ParamType::Number && first.lowerBound > -std::numeric_limits<double>::infinity())
      row.bounds = above(first.lowerBound);
    for (const auto& [kind, decl] : decls)
      for (const std::string& choice : decl->choices)
        if (std::find(row.choices.begin(), row.choices.end(), choice) == row.choices.end())
          row.choices.push_back(choice);
    if (first.type != ParamType::Number && first.type != ParamType::Choice)
      row.rangeNote = perKind([](const ParamDecl& decl) { return decl.range(); });
    out.push_back(info("surface", key, row, "kind = " + surfaceKeyRule(key, d.kind).kinds));
  }
  return out;
}

// [path], and a segment's path: which keys apply to which kinds comes from
// the path kind table (path_kinds.cpp).
std::vector<KeyInfo> pathKeyInfos() {
  std::vector<std::string> kindNames;
  for (const auto& row : pathKinds()) kindNames.emplace_back(row.name);
  std::vector<KeyInfo> out{info("path", "kind",
                                {"string",
                                 "\"circle\" on a plane, else the surface's own (parallel or meridian)",
                                 {},
                                 kindNames,
                                 "",
                                 "",
                                 "the curve the contact point follows"})};
  for (const std::string& key : allPathKeys()) {
    KeyInfo k = keyInfoOf("path", rowOf(pathKeys(), key));
    k.appliesTo = "kind = " + pathKeyRule(key, PathKind::Line, SurfaceKind::Plane).kinds;
    out.push_back(std::move(k));
  }
  return out;
}

template <class S>
void appendTable(std::vector<KeyInfo>& keys, const std::string& section, const KeyTable<S>& rows) {
  for (const KeyRow<S>& row : rows) keys.push_back(keyInfoOf(section, row));
}

std::vector<KeyInfo> buildRegistry() {
  const SceneSpec d;
  std::vector<KeyInfo> keys{
      info("", "extends",
           {"string",
            "(none)",
            {},
            {},
            "",
            "",
            "a base scene whose keys this one overrides: a file relative to this one, else a bundled scene's name "
            "(\"storyboard\")"}),
  };
  appendTable(keys, "ball", ballKeys());
  for (KeyInfo& k : surfaceKeyInfos(d.surface)) keys.push_back(std::move(k));
  appendTable(keys, "plate", plateKeys());
  for (KeyInfo& k : pathKeyInfos()) keys.push_back(std::move(k));

  appendTable(keys, "solver", solverKeys());
  appendTable(keys, "timeline", timelineKeys());
  appendTable(keys, "render", renderKeys());
  appendTable(keys, "figure", figureKeys());
  appendTable(keys, std::string(key::kLabels), labelsKeys());
  appendTable(keys, "animation", animationKeys());

  appendTable(keys, "segment", segmentKeys());
  appendTable(keys, "segment.camera", segmentCameraKeys());
  return keys;
}

std::string boundText(const Bounds& b) {
  if (b.lo && b.hi) return fmt::format("{}{}, {}{}", b.loOpen ? "(" : "[", *b.lo, *b.hi, b.hiOpen ? ")" : "]");
  if (b.lo) return fmt::format("{} {}", b.loOpen ? ">" : ">=", *b.lo);
  if (b.hi) return fmt::format("{} {}", b.hiOpen ? "<" : "<=", *b.hi);
  return "";
}

std::string fullName(const KeyInfo& k) { return k.section.empty() ? k.key : k.section + "." + k.key; }

std::string sectionTitle(const std::string& section) {
  if (section.empty()) return "Top level";
  if (section == "segment") return "[[segment]]";
  if (section == "segment.camera") return "segment camera = { ... }";
  return "[" + section + "]";
}

}  // namespace

std::span<const KeyInfo> sceneKeys() {
  static const std::vector<KeyInfo> keys = buildRegistry();
  return keys;
}

const std::vector<std::string>& keySections() {
  static const std::vector<std::string> sections = [] {
    std::vector<std::string> out;
    for (const KeyInfo& k : sceneKeys())
      if (std::find(out.begin(), out.end(), k.section) == out.end()) out.push_back(k.section);
    return out;
  }();
  return sections;
}

std::set<std::string> keysOf(std::string_view section) {
  std::set<std::string> out;
  for (const KeyInfo& k : sceneKeys())
    if (k.section == section) out.insert(k.key);
  return out;
}

const KeyInfo& keyInfo(std::string_view section, std::string_view key) {
  for (const KeyInfo& k : sceneKeys())
    if (k.section == section && k.key == key) return k;
  throw std::logic_error(fmt::format("scene key registry: no key {}.{}", section, key));
}

std::set<std::string> keyChoices(std::string_view section, std::string_view key) {
  const KeyInfo& k = keyInfo(section, key);
  return {k.choices.begin(), k.choices.end()};
}

std::string rangeText(const KeyInfo& k) {
  std::vector<std::string> parts;
  if (!k.choices.empty()) {
    std::string c;
    for (const auto& v : k.choices) c += (c.empty() ? "" : " | ") + inQuotes(v);
    if (k.rangeNote.empty()) parts.push_back(c);
  }
  if (k.bounds) parts.push_back(boundText(*k.bounds));
  if (!k.rangeNote.empty()) parts.push_back(k.rangeNote);
  std::string out;
  for (const auto& p : parts) out += (out.empty() ? "" : "; ") + p;
  return out;
}

std::string keysText(std::string_view section) {
  const auto& sections = keySections();
  const std::string wanted(section);
  if (!wanted.empty() && std::find(sections.begin(), sections.end(), wanted) == sections.end()) {
    std::string names;
    for (const auto& s : sections)
      if (!s.empty()) names += (names.empty() ? "" : ", ") + s;
    std::vector<std::string> candidates(sections.begin(), sections.end());
    const std::string guess = nearestName(wanted, candidates);
    throw badInput(SourceLoc{"keys"}, "unknown section '{}'{}; the sections: {}", wanted,
                   guess.empty() ? "" : fmt::format(" (did you mean '{}'?)", guess), names);
  }
  std::string out;
  std::string current = "\x01";
  for (const KeyInfo& k : sceneKeys()) {
    if (!wanted.empty() && k.section != wanted) continue;
    if (k.section != current) {
      out += (out.empty() ? "" : "\n") + sectionTitle(k.section) + "\n";
      current = k.section;
    }
    out += fmt::format("  {} ({}) = {}\n      {}\n", fullName(k), k.type, k.defaultText, k.meaning);
    const std::string range = rangeText(k);
    if (!range.empty()) out += fmt::format("      allowed: {}\n", range);
    if (!k.units.empty()) out += fmt::format("      units: {}\n", k.units);
    if (!k.appliesTo.empty()) out += fmt::format("      applies to: {}\n", k.appliesTo);
  }
  return out;
}

std::string keysMarkdown() {
  std::string out =
      "# Scene reference\n\n"
      "<!-- Generated by `rollspin keys --markdown`; do not edit by hand. Regenerate with\n"
      "     build/rollspin keys --markdown > docs/scene-reference.md -->\n\n"
      "Every key a scene file (TOML) accepts, with its default, the values the loader accepts, its units and\n"
      "its meaning. The loader reads the same table, so a key missing here is a key the loader rejects.\n"
      "`rollspin keys [SECTION]` prints the same in a terminal; `rollspin scene FILE --print` shows a scene\n"
      "with every default filled in. Lengths are in the scene's units (the ball's radius is 1 by default).\n";
  std::string current = "\x01";
  auto cell = [](std::string text) {
    std::string out;
    for (char c : text) out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
  };
  for (const KeyInfo& k : sceneKeys()) {
    if (k.section != current) {
      out += "\n## " + sectionTitle(k.section) + "\n\n";
      out += "| Key | Type | Default | Allowed | Units | Meaning |\n|---|---|---|---|---|---|\n";
      current = k.section;
    }
    std::string meaning = k.meaning;
    if (!k.appliesTo.empty()) meaning += " (" + k.appliesTo + ")";
    out += fmt::format("| `{}` | {} | {} | {} | {} | {} |\n", k.key, cell(k.type), cell(k.defaultText),
                       cell(rangeText(k)), k.units, cell(meaning));
  }
  return out;
}

}  // namespace rollspin::scene
