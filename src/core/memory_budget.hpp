// Memory the process may still use: MemAvailable from /proc/meminfo, capped
// by RLIMIT_AS when one is set. Lets a job refuse up front (with the numbers)
// instead of failing half-way or being killed.
#pragma once

#include <cstdint>
#include <optional>

namespace rollspin {

// std::nullopt when neither source can be read (then no check is made).
[[nodiscard]] std::optional<std::uint64_t> availableMemoryBytes();

}  // namespace rollspin
