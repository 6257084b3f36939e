// KeyRow — one scene key as one row of its section's table (scene_tables.cpp):
// its name, the field of the section struct it reads into, the range the
// loader enforces and how its messages say it, how `scene --print` writes it,
// and what `rollspin keys` and docs/scene-reference.md say about it.
#pragma once

#include <fmt/format.h>

#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "scene/scene_keys.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::scene {

// A text key whose values name an enum or a flag: get/set the index of the
// value in the row's choices.
template <class S>
struct ChoiceField {
  std::size_t (*get)(const S&) = nullptr;
  void (*set)(S&, std::size_t) = nullptr;
};

// Where a key's value lives in its section struct S; monostate: nowhere
// (the section's rule code reads it, and prints it if at all).
template <class S>
using FieldOf = std::variant<std::monostate, double S::*, std::optional<double> S::*, long long S::*,
                             std::optional<long long> S::*, bool S::*, std::optional<bool> S::*, std::string S::*,
                             std::optional<std::string> S::*, std::optional<Vec3> S::*, ChoiceField<S>>;

template <class S>
struct KeyRow {
  std::string_view name;
  std::string type;  // as `rollspin keys` shows it: "number", "integer", "[x, y, z]", …
  FieldOf<S> field{};
  std::optional<Bounds> bounds{};
  std::vector<std::string> choices{};
  // Messages: "expected NOUN BOUNDS UNIT_WORD, got V" ("expected an image size
  // in [1, 8192] pixels, got 0"). A text key with a noun must not be empty
  // ("expected NOUN, got an empty string"); a vector with a noun is a
  // direction, non-zero and normalised.
  std::string noun{};
  std::string unitWord{};
  // Where the bounds alone do not say it: the whole expectation, and the test.
  std::string expected{};
  bool (*accepts)(double) = nullptr;
  std::string defaultText{};  // `keys`: "" = the default struct's value as printed
  std::string rangeNote{};
  std::string units{};
  std::string meaning{};
  std::string appliesTo{};
  bool byRule = false;      // read by the section's rule code, not by the generic reader
  bool printed = true;      // written by `scene --print`
  std::string unsetNote{};  // printed as "# key = NOTE" when the value is unset (an empty optional or text)
  // Printed text in place of the field's; nullopt: unset (see unsetNote).
  std::optional<std::string> (*printText)(const S&) = nullptr;
  int printOrder = -1;  // the position in `scene --print` where it differs from the table's
};

template <class S>
using KeyTable = std::vector<KeyRow<S>>;

// TOML text of a value, as `scene --print` writes it and `keys` shows a default.
[[nodiscard]] std::string tomlQuoted(std::string_view text);
[[nodiscard]] inline std::string tomlNumber(double v) { return fmt::format("{}", v); }  // shortest round trip
[[nodiscard]] inline std::string tomlVector(const Vec3& v) { return fmt::format("[{}, {}, {}]", v[0], v[1], v[2]); }
[[nodiscard]] inline std::string tomlBool(bool b) { return b ? "true" : "false"; }

// A row's value in `s` as TOML text; nullopt when unset (an empty optional,
// an empty text with an unsetNote, or a row its rule code prints).
template <class S>
[[nodiscard]] std::optional<std::string> printedValue(const KeyRow<S>& row, const S& s) {
  if (row.printText != nullptr) return row.printText(s);
  return std::visit(
      [&](auto field) -> std::optional<std::string> {
        using F = decltype(field);
        if constexpr (std::is_same_v<F, double S::*>) return tomlNumber(s.*field);
        else if constexpr (std::is_same_v<F, long long S::*>) return std::to_string(s.*field);
        else if constexpr (std::is_same_v<F, bool S::*>) return tomlBool(s.*field);
        else if constexpr (std::is_same_v<F, std::string S::*>) {
          if ((s.*field).empty() && !row.unsetNote.empty()) return std::nullopt;
          return tomlQuoted(s.*field);
        } else if constexpr (std::is_same_v<F, std::optional<double> S::*>) {
          if (s.*field) return tomlNumber(*(s.*field));
        } else if constexpr (std::is_same_v<F, std::optional<long long> S::*>) {
          if (s.*field) return std::to_string(*(s.*field));
        } else if constexpr (std::is_same_v<F, std::optional<bool> S::*>) {
          if (s.*field) return tomlBool(*(s.*field));
        } else if constexpr (std::is_same_v<F, std::optional<std::string> S::*>) {
          if (s.*field) return tomlQuoted(*(s.*field));
        } else if constexpr (std::is_same_v<F, std::optional<Vec3> S::*>) {
          if (s.*field) return tomlVector(*(s.*field));
        } else if constexpr (std::is_same_v<F, ChoiceField<S>>) {
          return tomlQuoted(row.choices.at(field.get(s)));
        }
        return std::nullopt;
      },
      row.field);
}

// A row's registry entry: `keys` and the reference show it.
template <class S>
[[nodiscard]] KeyInfo keyInfoOf(const std::string& section, const KeyRow<S>& row) {
  return {section,       std::string(row.name),
          row.type,      row.defaultText.empty() ? printedValue(row, S{}).value_or("") : row.defaultText,
          row.bounds,    row.choices,
          row.rangeNote, row.units,
          row.meaning,   row.appliesTo};
}

// "section.key" (a dotted key as locations and messages spell it).
[[nodiscard]] inline std::string dotted(std::string_view section, std::string_view key) {
  return std::string(section) + "." + std::string(key);
}

}  // namespace rollspin::scene
