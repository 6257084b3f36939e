#include "heap_huge_pages.hpp"

#include <sys/mman.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <mutex>
#include <optional>
#include <vector>

#include "jobs/huge_pages.hpp"

namespace rollspin::python {

std::size_t markHeapForHugePages(long long width, long long height) {
#if defined(__GLIBC__)
  static std::mutex mutex;
  static std::optional<std::size_t> marked;
  const std::lock_guard lock(mutex);
  if (marked) return *marked;
  if (width <= 0 || height <= 0) return 0;  // asked before the first context: nothing yet
  marked = 0;
  if (!jobs::hugePagesTunables(jobs::readHugePagesFacts())) return 0;
  constexpr std::size_t kMiB = std::size_t{1} << 20;
  constexpr std::uintptr_t kHugePage = 2 * kMiB;
  constexpr std::size_t kMmapThresholdMax = 32 * kMiB;  // glibc's DEFAULT_MMAP_THRESHOLD_MAX on 64 bits
  constexpr std::size_t kBlock = 30 * kMiB;
  // The textures and the rest (32 MiB), and 128 bytes a pixel for the
  // multisampled and single targets; at most 1 GiB of address space.
  const auto frameBytes = static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 128;
  const std::size_t blocks = std::min<std::size_t>((32 * kMiB + frameBytes) / kBlock + 1, 1024 * kMiB / kBlock);
  void* volatile probe = std::malloc(kMmapThresholdMax - 64 * 1024);
  std::free(probe);
  std::vector<std::uintptr_t> taken;
  taken.reserve(blocks + 1);
  for (std::size_t k = 0; k <= blocks; ++k) {  // the last one becomes the fence
    void* block = std::malloc(kBlock);
    if (block == nullptr) break;
    taken.push_back(reinterpret_cast<std::uintptr_t>(block));
  }
  if (taken.size() < 2) {
    for (const std::uintptr_t block : taken) std::free(reinterpret_cast<void*>(block));
    return 0;
  }
  // The fence: the last block shrunk in place; what it gave up joins the top.
  void* fence = std::realloc(reinterpret_cast<void*>(taken.back()), 64);
  (void)fence;  // kept for the process's life (64 bytes)
  taken.pop_back();
  // Adjacent blocks (one chunk header apart) are marked as one range.
  std::sort(taken.begin(), taken.end());
  auto mark = [&](std::uintptr_t begin, std::uintptr_t end) {
    begin = (begin + kHugePage - 1) & ~(kHugePage - 1);
    end &= ~std::uintptr_t{4095};
    if (end > begin && ::madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE) == 0)
      *marked += end - begin;
  };
  std::uintptr_t runBegin = taken.front(), runEnd = taken.front() + kBlock;
  for (std::size_t k = 1; k < taken.size(); ++k) {
    if (taken[k] - runEnd > 64) {
      mark(runBegin, runEnd);
      runBegin = taken[k];
    }
    runEnd = taken[k] + kBlock;
  }
  mark(runBegin, runEnd);
  for (const std::uintptr_t block : taken) std::free(reinterpret_cast<void*>(block));
  return *marked;
#else
  (void)width, (void)height;
  return 0;
#endif
}

}  // namespace rollspin::python
