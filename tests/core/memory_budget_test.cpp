// core/memory_budget.hpp: what this process may still use, from
// /proc/meminfo and RLIMIT_AS less VmSize, checked against setrlimit in a
// child process (the limit is the child's alone).
#include "core/memory_budget.hpp"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace rollspin {
namespace {

TEST(MemoryBudget, ReadsTheMachinesMemoryAndWhatThisProcessHasMapped) {
  const auto available = availableMemoryBytes();
  ASSERT_TRUE(available.has_value()) << "Linux has /proc/meminfo";
  EXPECT_GT(*available, 16u << 20);
  const auto mapped = mappedBytes();
  ASSERT_TRUE(mapped.has_value());
  EXPECT_GT(*mapped, 1u << 20) << "a test program maps more than a MiB";
}

TEST(MemoryBudget, AnAddressSpaceLimitCapsWhatIsAvailable) {
#if defined(ROLLSPIN_ADDRESS_SANITIZER)
  GTEST_SKIP() << "AddressSanitizer reserves terabytes of shadow memory: a limit just above VmSize starves it";
#endif
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // In the child: a limit of what is mapped now plus 64 MiB.
    const std::uint64_t mapped = mappedBytes().value_or(0);
    const rlimit limit{rlim_t(mapped + (64u << 20)), rlim_t(mapped + (64u << 20))};
    if (mapped == 0 || ::setrlimit(RLIMIT_AS, &limit) != 0) ::_exit(3);
    const auto cap = addressSpaceLimitBytes();
    if (!cap || *cap != mapped + (64u << 20)) ::_exit(4);
    const auto available = availableMemoryBytes();
    // About 64 MiB left (less what this check mapped itself), never more.
    if (!available || *available > (64u << 20) || *available < (32u << 20)) ::_exit(5);
    ::_exit(0);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "3: no VmSize or setrlimit failed; 4: the limit read back wrong; "
                                       "5: available not capped by the limit";
}

}  // namespace
}  // namespace rollspin
