// The scene key registry: every key a scene file accepts, with its type,
// default, allowed range or values, units, meaning and the kinds it applies
// to. The loader takes from it the keys each table accepts and the choices
// of its text keys; `rollspin keys` and docs/scene-reference.md print it, so
// the loader and the reference cannot disagree. Numeric bounds are checked
// against the loader by tests/scene/key_registry_test.cpp.
#pragma once

#include <optional>
#include <set>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace rollspin::scene {

// lo < x < hi (open ends) or lo <= x <= hi (closed ends); an absent end is unbounded.
struct Bounds {
  std::optional<double> lo, hi;
  bool loOpen = false, hiOpen = false;
};

struct KeyInfo {
  std::string section;  // "ball", "path", "segment", "segment.camera"; "" for the top level
  std::string key;
  std::string type;  // "number", "integer", "boolean", "string", "[x, y, z]", "expression", "table", …
  std::string defaultText;
  std::optional<Bounds> bounds;      // numbers: the loader rejects values outside
  std::vector<std::string> choices;  // text keys with a fixed set of values
  std::string rangeNote;             // anything else the loader checks (e.g. "> t_start")
  std::string units;
  std::string meaning;
  std::string appliesTo;  // "" = always; else the kinds it applies to
};

// The tables of a scene, in the reference's order ("" first: `extends`).
[[nodiscard]] const std::vector<std::string>& keySections();
[[nodiscard]] std::span<const KeyInfo> sceneKeys();
// The keys a table accepts ("path" also serves a segment's path table).
[[nodiscard]] std::set<std::string> keysOf(std::string_view section);
// One key's row; throws std::logic_error for a key the registry lacks.
[[nodiscard]] const KeyInfo& keyInfo(std::string_view section, std::string_view key);
[[nodiscard]] std::set<std::string> keyChoices(std::string_view section, std::string_view key);
// "[1, 8192]", "> 0", "\"ccw\" | \"cw\"", …: the allowed values as text.
[[nodiscard]] std::string rangeText(const KeyInfo& info);

// `rollspin keys [SECTION]`: one block per key; throws BadInput for an unknown section.
[[nodiscard]] std::string keysText(std::string_view section = "");
// docs/scene-reference.md, whole.
[[nodiscard]] std::string keysMarkdown();

}  // namespace rollspin::scene
