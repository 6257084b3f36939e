// Fuzzes the expression parser (muparser bytecode re-evaluated over jets):
// parse, then evaluate value and jet at a few points. ExpressionError is a
// correct answer; crashes, sanitizer reports and other exceptions are bugs.
#include <cstddef>
#include <cstdint>
#include <string>

#include "geometry/expression.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const rollspin::geometry::Expression e(text, {"x", "y"});
    for (double x : {0.0, 0.5, -1.25, 3.0}) {
      (void)e.value(x, 0.75 * x - 0.1);
      (void)e.jet(rollspin::geometry::Jet::variableA(x), rollspin::geometry::Jet::variableB(-x));
    }
  } catch (const rollspin::geometry::ExpressionError&) {
  }
  return 0;
}
