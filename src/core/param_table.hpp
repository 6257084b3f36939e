// Parameter declarations: what a kind's own keys are, each with its type,
// default, allowed range, units and meaning, and the values a scene gave them.
// A kind table (geometry/surface_kinds.hpp) declares its keys with these; the
// scene loader reads, checks and prints them from the declarations alone, and
// `rollspin keys` can list them. No equation: a value is valid when
//   Number: value > lowerBound;  Direction: |v| > 0 (stored as v/|v|);
//   Choice: one of `choices`;   Expression: a non-empty formula of `variables`.
#pragma once

#include <array>
#include <limits>
#include <map>
#include <string>
#include <variant>
#include <vector>

namespace rollspin {

enum class ParamType { Number, Direction, Choice, Expression };

// A number, an [x, y, z] vector, or text (a choice or an expression).
using ParamValue = std::variant<double, std::array<double, 3>, std::string>;

struct ParamDecl {
  std::string key;
  ParamType type = ParamType::Number;
  ParamValue defaultValue = 0.0;
  std::string units;                                             // "length", "" for none
  std::string meaning;                                           // one line
  double lowerBound = -std::numeric_limits<double>::infinity();  // Number: exclusive
  std::string noun = "a value";                                  // Number: "expected <noun> > lowerBound" in messages
  std::vector<std::string> choices;                              // Choice: the accepted words, the default first
  std::vector<std::string> variables;                            // Expression: its free variables

  // The allowed range as one line: "> 0", "\"outside\" | \"inside\"", ...
  [[nodiscard]] std::string range() const;
};

// The values of one kind's keys (every declared key has one: given or default).
class ParamSet {
 public:
  ParamSet() = default;
  explicit ParamSet(const std::vector<ParamDecl>& decls) {
    for (const auto& d : decls) values_[d.key] = d.defaultValue;
  }
  void set(const std::string& key, ParamValue value) { values_[key] = std::move(value); }
  [[nodiscard]] bool has(const std::string& key) const { return values_.contains(key); }
  [[nodiscard]] const ParamValue& at(const std::string& key) const { return values_.at(key); }
  [[nodiscard]] double number(const std::string& key) const { return std::get<double>(values_.at(key)); }
  [[nodiscard]] const std::array<double, 3>& vector(const std::string& key) const {
    return std::get<std::array<double, 3>>(values_.at(key));
  }
  [[nodiscard]] const std::string& text(const std::string& key) const { return std::get<std::string>(values_.at(key)); }
  friend bool operator==(const ParamSet&, const ParamSet&) = default;

 private:
  std::map<std::string, ParamValue> values_;
};

}  // namespace rollspin
