#include "core/param_table.hpp"

#include <fmt/format.h>

namespace rollspin {

std::string ParamDecl::range() const {
  switch (type) {
    case ParamType::Number:
      return lowerBound == -std::numeric_limits<double>::infinity() ? "any finite number"
                                                                    : fmt::format("> {}", lowerBound);
    case ParamType::Direction: return "a non-zero vector [x, y, z] (normalised)";
    case ParamType::Choice: {
      std::string out;
      for (const auto& c : choices) out += (out.empty() ? "\"" : " | \"") + c + "\"";
      return out;
    }
    case ParamType::Expression: {
      std::string vars;
      for (const auto& v : variables) vars += (vars.empty() ? "" : ", ") + v;
      return "a formula of " + vars;
    }
  }
  return "";
}

}  // namespace rollspin
