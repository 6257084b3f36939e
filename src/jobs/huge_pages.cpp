#include "jobs/huge_pages.hpp"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace rollspin::jobs {

namespace {

constexpr const char* kRestartMarker = "ROLLSPIN_RESTARTED_FOR_HUGE_PAGES";

std::optional<std::string> environmentValue(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? std::optional<std::string>(value) : std::nullopt;
}

}  // namespace

std::optional<std::string> hugePagesTunables(const HugePagesFacts& facts) {
  if (facts.sanitized) return std::nullopt;
  if (facts.ldPreload && facts.ldPreload->find("vgpreload") != std::string::npos) return std::nullopt;
  if (facts.transparentHugePages.find("[madvise]") == std::string::npos) return std::nullopt;
  if (!facts.tunables || facts.tunables->empty()) return "glibc.malloc.hugetlb=1";
  if (facts.tunables->find("glibc.malloc.hugetlb") != std::string::npos) return std::nullopt;
  return *facts.tunables + ":glibc.malloc.hugetlb=1";
}

HugePagesFacts readHugePagesFacts() {
  HugePagesFacts facts;
  facts.tunables = environmentValue("GLIBC_TUNABLES");
  facts.ldPreload = environmentValue("LD_PRELOAD");
  std::ifstream mode("/sys/kernel/mm/transparent_hugepage/enabled");
  facts.transparentHugePages.assign(std::istreambuf_iterator<char>(mode), {});
#if defined(ROLLSPIN_ADDRESS_SANITIZER)
  facts.sanitized = true;
#endif
  return facts;
}

void restartWithHugePages(char** argv) {
  const HugePagesFacts facts = readHugePagesFacts();
  const std::optional<std::string> tunables = hugePagesTunables(facts);
  if (!tunables) return;
  // The binary's own path, not /proc/self/exe: the kernel names a process
  // after the file it execs, and ps, top and pkill should still see
  // "rollspin". A binary replaced since it started reads "… (deleted)".
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if (error || self.string().ends_with(" (deleted)")) return;
  // Nothing is open or written yet; a failed execv leaves this process as
  // it was, with small pages.
  ::setenv("GLIBC_TUNABLES", tunables->c_str(), 1);
  ::setenv(kRestartMarker, "1", 1);
  std::fflush(nullptr);
  ::execv(self.c_str(), argv);
  if (facts.tunables) ::setenv("GLIBC_TUNABLES", facts.tunables->c_str(), 1);
  else ::unsetenv("GLIBC_TUNABLES");
  ::unsetenv(kRestartMarker);
}

bool restartedForHugePages() {
  static const bool restarted = [] {
    const bool marked = std::getenv(kRestartMarker) != nullptr;
    ::unsetenv(kRestartMarker);
    return marked;
  }();
  return restarted;
}

}  // namespace rollspin::jobs
