// Fitting a render into a ulimit -v. What a limit on address space runs out
// of first is not memory but reservations: glibc's malloc gives each thread
// that allocates an arena of its own, 64 MiB of address space each, and
// llvmpipe starts a thread per core (up to 32). Measured on a 320x180 still
// (docs/speed-history.md, "Address space"): 496 MB of address space with one
// llvmpipe thread, 644 MB with two; with one arena, 293 MB + 17 MB a thread.
// Mesa does not survive running out inside its shader compiler (it crashes or
// hangs), so the way to a clear message is to need less and to refuse up
// front what still cannot fit.
#pragma once

#include <cstdint>
#include <optional>

namespace rollspin::jobs {

struct AddressSpacePlan {
  bool oneArena = false;               // mallopt(M_ARENA_MAX, 1)
  std::optional<int> llvmpipeThreads;  // LP_NUM_THREADS to set, if any
};

// With no limit nothing changes. Under one: one malloc arena, and unless the
// user chose LP_NUM_THREADS, at most a quarter of the limit for llvmpipe's
// threads at 32 MiB each (stack and heap), never more threads than cores.
[[nodiscard]] AddressSpacePlan planForAddressSpace(std::optional<std::uint64_t> limitBytes, unsigned cores,
                                                   bool userChoseThreads);

// Applies the plan for this process (before any thread starts); with verbose,
// says what it changed on stderr.
void fitToAddressSpaceLimit(bool verbose);

// The address space the GL driver maps for itself once loaded (its compiler,
// its threads), counted by a render's memory check when a limit is set.
[[nodiscard]] std::uint64_t glDriverAddressSpaceBytes();

}  // namespace rollspin::jobs
