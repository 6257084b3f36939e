// Expression — a scalar function of one or two named variables given as text
// ("0.3*sin(x)*cos(y)"), parsed by muparser and differentiated exactly:
// muparser compiles the text to reverse-Polish bytecode, and this class
// re-evaluates that bytecode over Jet numbers (second-order forward-mode
// automatic differentiation), so f, ∇f and ∇²f carry no truncation error,
// only round-off (tested against closed forms to ~1e-14 relative).
// Functions: sin cos tan asin acos atan sinh cosh tanh asinh acosh atanh exp
// log (= ln) log10 log2 sqrt abs atan2 pow, operators + − * / ^, comparisons
// with ?:, constants _pi, _e, pi. A parse error throws ExpressionError with
// the 0-based character position in the text.
#pragma once

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "geometry/jet.hpp"

namespace rollspin::geometry {

class ExpressionError : public std::runtime_error {
 public:
  ExpressionError(int position, const std::string& message) : std::runtime_error(message), position_(position) {}
  // 0-based character offset of the offending token in the expression text.
  [[nodiscard]] int position() const { return position_; }

 private:
  int position_;
};

class Expression {
 public:
  // variables: the names the text may use, e.g. {"x", "y"} or {"t"} (≤ 2).
  Expression(std::string text, std::vector<std::string> variables);
  ~Expression();
  Expression(const Expression&) = delete;
  Expression& operator=(const Expression&) = delete;

  // f at the point (args[i] for variables[i]).
  [[nodiscard]] double value(double a, double b = 0.0) const;
  // f with first and second derivatives: variable 0 is the Jet's a, 1 its b.
  [[nodiscard]] Jet jet(const Jet& a, const Jet& b = Jet()) const;
  [[nodiscard]] const std::string& text() const { return text_; }

 private:
  struct Compiled;
  template <typename T>
  T evaluate(const T& a, const T& b) const;
  std::string text_;
  std::unique_ptr<Compiled> compiled_;
};

}  // namespace rollspin::geometry
