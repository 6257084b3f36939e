// rollspin::Error — the one exception type for invalid input or environment.
// It carries a SourceLoc (file:line:col, or the --set argument that gave the
// value) and a kind that main() maps to the exit code: BadInput → 2,
// Runtime → 1. Broken invariants assert instead; the numeric core never throws.
#pragma once

#include <fmt/format.h>

#include <stdexcept>
#include <string>

namespace rollspin {

// Where a value came from. line == 0 means "no line" (a default value, a
// command-line argument or a whole file).
struct SourceLoc {
  std::string file;
  int line = 0;
  int column = 0;

  [[nodiscard]] bool empty() const { return file.empty(); }
  [[nodiscard]] std::string str() const;  // "file:line:col", "file" or ""
};

enum class ErrorKind { BadInput, Runtime };

class Error : public std::runtime_error {
 public:
  Error(ErrorKind kind, SourceLoc where, std::string message);

  [[nodiscard]] ErrorKind kind() const { return kind_; }
  [[nodiscard]] const SourceLoc& where() const { return where_; }
  [[nodiscard]] const std::string& message() const { return message_; }
  [[nodiscard]] int exitCode() const { return kind_ == ErrorKind::BadInput ? 2 : 1; }

 private:
  ErrorKind kind_;
  SourceLoc where_;
  std::string message_;
};

// Formatting helpers: badInput(loc, "key {} must be > 0", k).
template <typename... Args>
[[nodiscard]] Error badInput(SourceLoc where, fmt::format_string<Args...> f, Args&&... args) {
  return Error(ErrorKind::BadInput, std::move(where), fmt::format(f, std::forward<Args>(args)...));
}

template <typename... Args>
[[nodiscard]] Error runtimeError(SourceLoc where, fmt::format_string<Args...> f, Args&&... args) {
  return Error(ErrorKind::Runtime, std::move(where), fmt::format(f, std::forward<Args>(args)...));
}

}  // namespace rollspin
