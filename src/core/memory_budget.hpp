// Memory the process may still use: MemAvailable from /proc/meminfo, capped
// by what RLIMIT_AS leaves (the limit less the address space already mapped,
// VmSize) when one is set. Lets a job refuse up front (with the numbers)
// instead of failing half-way or being killed.
#pragma once

#include <cstdint>
#include <optional>

namespace rollspin {

// std::nullopt when neither source can be read (then no check is made).
[[nodiscard]] std::optional<std::uint64_t> availableMemoryBytes();

// RLIMIT_AS's soft limit in bytes, or std::nullopt when there is none.
[[nodiscard]] std::optional<std::uint64_t> addressSpaceLimitBytes();

// The address space this process has mapped now (VmSize), or std::nullopt
// when /proc/self/statm cannot be read.
[[nodiscard]] std::optional<std::uint64_t> mappedBytes();

}  // namespace rollspin
