#include "core/memory_budget.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <string>

namespace rollspin {

std::optional<std::uint64_t> addressSpaceLimitBytes() {
  rlimit limit{};
  if (getrlimit(RLIMIT_AS, &limit) != 0 || limit.rlim_cur == RLIM_INFINITY) return std::nullopt;
  return static_cast<std::uint64_t>(limit.rlim_cur);
}

std::optional<std::uint64_t> mappedBytes() {
  std::ifstream statm("/proc/self/statm");
  std::uint64_t pages = 0;
  if (!(statm >> pages)) return std::nullopt;
  return pages * static_cast<std::uint64_t>(sysconf(_SC_PAGESIZE));
}

std::optional<std::uint64_t> availableMemoryBytes() {
  std::optional<std::uint64_t> available;
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  std::uint64_t kib = 0;
  std::string unit;
  while (meminfo >> key >> kib >> unit) {
    if (key == "MemAvailable:") {
      available = kib * 1024;
      break;
    }
  }
  // Under ulimit -v what counts is address space, and part of it is mapped
  // already (the binary, its libraries, the GL driver once loaded).
  if (const auto limit = addressSpaceLimitBytes()) {
    const std::uint64_t mapped = mappedBytes().value_or(0);
    const std::uint64_t left = *limit > mapped ? *limit - mapped : 0;
    available = available ? std::min(*available, left) : left;
  }
  return available;
}

}  // namespace rollspin
