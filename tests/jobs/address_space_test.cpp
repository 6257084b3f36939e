// Under ulimit -v a render needs less address space: one malloc arena, and
// no more llvmpipe threads than a quarter of the limit holds at 32 MiB each.
#include "jobs/address_space.hpp"

#include <gtest/gtest.h>

namespace rollspin::jobs {
namespace {

constexpr std::uint64_t kMiB = 1ULL << 20;

TEST(AddressSpace, WithoutALimitNothingChanges) {
  const AddressSpacePlan plan = planForAddressSpace(std::nullopt, 64, false);
  EXPECT_FALSE(plan.oneArena);
  EXPECT_FALSE(plan.llvmpipeThreads);
}

TEST(AddressSpace, ALimitOnAManyCoreMachineCapsTheThreads) {
  // 700 MB, as the fault test sets: 683 MiB / 4 / 32 MiB = 5 threads.
  const AddressSpacePlan plan = planForAddressSpace(700000ULL * 1024, 64, false);
  EXPECT_TRUE(plan.oneArena);
  ASSERT_TRUE(plan.llvmpipeThreads);
  EXPECT_EQ(*plan.llvmpipeThreads, 5);
}

TEST(AddressSpace, ThreadsAreNotSetWhenTheCoresFitOrTheUserChose) {
  EXPECT_FALSE(planForAddressSpace(700000ULL * 1024, 2, false).llvmpipeThreads);
  EXPECT_FALSE(planForAddressSpace(64 * 1024 * kMiB, 64, false).llvmpipeThreads);  // 32 threads fit
  const AddressSpacePlan chosen = planForAddressSpace(700000ULL * 1024, 64, true);
  EXPECT_TRUE(chosen.oneArena);
  EXPECT_FALSE(chosen.llvmpipeThreads);
}

TEST(AddressSpace, ATinyLimitStillLeavesOneThread) {
  const AddressSpacePlan plan = planForAddressSpace(64 * kMiB, 16, false);
  ASSERT_TRUE(plan.llvmpipeThreads);
  EXPECT_EQ(*plan.llvmpipeThreads, 1);
}

}  // namespace
}  // namespace rollspin::jobs
