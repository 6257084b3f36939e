// When `rollspin render` restarts itself for huge pages: only where the
// kernel hands them out on request, never over the user's own setting, and
// never where malloc is not glibc's.
#include "jobs/huge_pages.hpp"

#include <gtest/gtest.h>

using rollspin::jobs::HugePagesFacts;
using rollspin::jobs::hugePagesTunables;

namespace {

HugePagesFacts onMadvise() {
  HugePagesFacts facts;
  facts.transparentHugePages = "always [madvise] never\n";
  return facts;
}

}  // namespace

TEST(HugePages, RestartsWhereTheKernelGivesThemOnRequest) {
  EXPECT_EQ(hugePagesTunables(onMadvise()), "glibc.malloc.hugetlb=1");
  HugePagesFacts empty = onMadvise();
  empty.tunables = "";
  EXPECT_EQ(hugePagesTunables(empty), "glibc.malloc.hugetlb=1");
}

TEST(HugePages, KeepsTheUsersOtherTunables) {
  HugePagesFacts facts = onMadvise();
  facts.tunables = "glibc.malloc.arena_max=2";
  EXPECT_EQ(hugePagesTunables(facts), "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=1");
}

TEST(HugePages, NeverOverridesAChoiceOrRestartsTwice) {
  for (const char* set : {"glibc.malloc.hugetlb=0", "glibc.malloc.hugetlb=1", "glibc.malloc.hugetlb=2",
                          "glibc.malloc.arena_max=2:glibc.malloc.hugetlb=0"}) {
    HugePagesFacts facts = onMadvise();
    facts.tunables = set;
    EXPECT_EQ(hugePagesTunables(facts), std::nullopt) << set;
  }
}

TEST(HugePages, NotWhereTheKernelDecidesAlone) {
  for (const char* mode : {"[always] madvise never\n", "always madvise [never]\n", ""}) {
    HugePagesFacts facts = onMadvise();
    facts.transparentHugePages = mode;
    EXPECT_EQ(hugePagesTunables(facts), std::nullopt) << mode;
  }
}

TEST(HugePages, NotUnderValgrindOrSanitizers) {
  HugePagesFacts valgrind = onMadvise();
  valgrind.ldPreload =
      "/usr/libexec/valgrind/vgpreload_core-amd64-linux.so:/usr/libexec/valgrind/vgpreload_memcheck-amd64-linux.so";
  EXPECT_EQ(hugePagesTunables(valgrind), std::nullopt);
  HugePagesFacts other = onMadvise();
  other.ldPreload = "/usr/lib/x86_64-linux-gnu/libeatmydata.so";
  EXPECT_EQ(hugePagesTunables(other), "glibc.malloc.hugetlb=1");
  HugePagesFacts sanitized = onMadvise();
  sanitized.sanitized = true;
  EXPECT_EQ(hugePagesTunables(sanitized), std::nullopt);
}
