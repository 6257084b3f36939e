// Huge pages for `rollspin render`: glibc's malloc asks the kernel for
// transparent huge pages (2 MiB) for its large blocks when
// GLIBC_TUNABLES holds glibc.malloc.hugetlb=1. llvmpipe zeroes every buffer
// it allocates, and each 4 KiB page is a fault; with 2 MiB pages a 1080p
// still took 0.73 s instead of 0.86, a 4K one 1.04 instead of 2.29
// (docs/speed-history.md#render-speed-bench_render-as-the-readme-had-it,
// "Huge pages"). glibc reads the variable only when a process
// starts, so a render restarts itself (execv of its own binary, same pid,
// same arguments) with it set.
#pragma once

#include <optional>
#include <string>

namespace rollspin::jobs {

// What the decision depends on, read from the environment and the kernel.
struct HugePagesFacts {
  std::optional<std::string> tunables;   // GLIBC_TUNABLES
  std::optional<std::string> ldPreload;  // LD_PRELOAD (valgrind preloads its core)
  std::string transparentHugePages;      // /sys/kernel/mm/transparent_hugepage/enabled
  bool sanitized = false;                // AddressSanitizer replaces malloc
};

// The facts of this process (its environment, the kernel's mode, this build).
[[nodiscard]] HugePagesFacts readHugePagesFacts();

// The GLIBC_TUNABLES value to restart with, or nothing when a restart would
// not help: the kernel's mode is not "madvise" ("always" gives huge pages
// already, "never" none), the variable already names glibc.malloc.hugetlb
// (the user's choice, or the restarted process), or malloc is not glibc's
// (valgrind, sanitizers).
[[nodiscard]] std::optional<std::string> hugePagesTunables(const HugePagesFacts& facts);

// Restarts this process with the tunable set when hugePagesTunables says so;
// returns only when it did not (nothing to do, or execv failed).
void restartWithHugePages(char** argv);

// True in a process restartWithHugePages started (read once: the marker is
// removed from the environment so that child processes do not inherit it).
[[nodiscard]] bool restartedForHugePages();

}  // namespace rollspin::jobs
