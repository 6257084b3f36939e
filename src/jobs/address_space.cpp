#include "jobs/address_space.hpp"

#include <malloc.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <thread>

#include "core/memory_budget.hpp"

namespace rollspin::jobs {

namespace {
constexpr std::uint64_t kMiB = 1ULL << 20;
constexpr unsigned kLlvmpipeMaxThreads = 32;  // LP_MAX_THREADS
// Planned per thread (stack and heap, with room to spare) ...
constexpr std::uint64_t kBytesPerLlvmpipeThread = 32 * kMiB;
// ... and counted by the memory check (measured 17 MB, rounded up).
constexpr std::uint64_t kDriverBaseBytes = 180 * kMiB, kDriverBytesPerThread = 20 * kMiB;

// The threads llvmpipe will start: LP_NUM_THREADS, else one a core.
unsigned llvmpipeThreads() {
  if (const char* chosen = std::getenv("LP_NUM_THREADS"))
    return unsigned(std::clamp(std::strtol(chosen, nullptr, 10), 1L, long(kLlvmpipeMaxThreads)));
  return std::clamp(std::thread::hardware_concurrency(), 1U, kLlvmpipeMaxThreads);
}
}  // namespace

AddressSpacePlan planForAddressSpace(std::optional<std::uint64_t> limitBytes, unsigned cores, bool userChoseThreads) {
  AddressSpacePlan plan;
  if (!limitBytes) return plan;
  plan.oneArena = true;
  const unsigned usable = std::clamp(cores, 1U, kLlvmpipeMaxThreads);
  const auto fit =
      unsigned(std::clamp<std::uint64_t>(*limitBytes / 4 / kBytesPerLlvmpipeThread, 1, kLlvmpipeMaxThreads));
  if (!userChoseThreads && fit < usable) plan.llvmpipeThreads = static_cast<int>(fit);
  return plan;
}

void fitToAddressSpaceLimit(bool verbose) {
  const auto limit = addressSpaceLimitBytes();
  const AddressSpacePlan plan =
      planForAddressSpace(limit, std::thread::hardware_concurrency(), std::getenv("LP_NUM_THREADS") != nullptr);
  if (plan.oneArena) mallopt(M_ARENA_MAX, 1);
  if (plan.llvmpipeThreads) setenv("LP_NUM_THREADS", std::to_string(*plan.llvmpipeThreads).c_str(), 1);
  if (verbose && limit)
    std::fprintf(stderr, "rollspin: memory: address space limited to %llu MiB (ulimit -v): one malloc arena%s\n",
                 static_cast<unsigned long long>(*limit / kMiB),
                 plan.llvmpipeThreads
                     ? (", llvmpipe threads " + std::to_string(*plan.llvmpipeThreads) + " (LP_NUM_THREADS)").c_str()
                     : "");
}

std::uint64_t glDriverAddressSpaceBytes() {
  // Measured with one arena: a 320x180 still peaks at 275 MB of address
  // space plus 17 MB a llvmpipe thread, of which the process had mapped
  // about 20 MB before the driver was loaded, and the frame buffers
  // (rendererBytes) count about 100 MB; the rest is the driver's own: its
  // code, its compiler's heaps, its threads. Rounded up, so that a render
  // the check lets through does not run out inside the driver.
  return kDriverBaseBytes + llvmpipeThreads() * kDriverBytesPerThread;
}

}  // namespace rollspin::jobs
