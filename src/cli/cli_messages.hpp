// The option parser's own errors in rollspin's voice: "rollspin: error: "
// first, CLI11's wording tidied ("Value abc not in range 0.000000 to …"
// becomes "--max-delta: expected a number in [0, 255], got abc"), and the
// nearest option or command suggested for a typo (--sett → --set).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "core/text.hpp"

namespace rollspin::cli {

// The typo helpers live in core/ (the scene loader suggests keys with them).
using rollspin::editDistance;
using rollspin::nearestName;

// Everything to print on stderr for a parse error of `argv` (lines ending in
// '\n'), naming the command whose options were searched.
[[nodiscard]] std::string describeParseError(const CLI::App& cli, const CLI::ParseError& error, int argc,
                                             const char* const* argv);

// Running out of memory (std::bad_alloc, or a GL buffer that could not be
// made) has a way out: `message` with what to lower appended when it says
// "out of memory", else `message` unchanged.
[[nodiscard]] std::string withMemoryWayOut(const std::string& message);

}  // namespace rollspin::cli
