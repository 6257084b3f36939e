// StageLog — the pipeline stages one command actually ran ("scene", "solver",
// "gl-context", "shadow-map", "encoder", …), in order. `--verbose` prints
// them as they happen; tests assert on the list, which is how the project
// checks that a job builds only what its scene needs.
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace rollspin {

class StageLog {
 public:
  static StageLog& instance();

  // Appends a stage (once: a stage recorded twice, e.g. per frame, is
  // listed once) and, when echoing, prints "rollspin: stage: NAME".
  void record(std::string_view stage);
  void setEcho(bool echo) { echo_ = echo; }
  [[nodiscard]] bool echo() const { return echo_; }  // --verbose
  [[nodiscard]] const std::vector<std::string>& stages() const { return stages_; }
  void clear() { stages_.clear(); }

 private:
  std::vector<std::string> stages_;
  bool echo_ = false;
};

}  // namespace rollspin
