#include "core/stage_log.hpp"

#include <algorithm>
#include <cstdio>

namespace rollspin {

StageLog& StageLog::instance() {
  static StageLog log;
  return log;
}

void StageLog::record(std::string_view stage) {
  if (std::find(stages_.begin(), stages_.end(), stage) != stages_.end()) return;
  stages_.emplace_back(stage);
  if (echo_) std::fprintf(stderr, "rollspin: stage: %.*s\n", static_cast<int>(stage.size()), stage.data());
}

}  // namespace rollspin
