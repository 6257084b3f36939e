// Output paths checked before any work: a command that will write FILE or
// FOLDER refuses up front (BadInput, exit 2) what would only fail at the end,
// after minutes of solving or rendering: a folder where a file goes, a file
// where a folder goes, a missing or unwritable parent, a path through a file.
#pragma once

#include <filesystem>
#include <string>

#include "core/error.hpp"

namespace rollspin {

// FILE will be written (through AtomicFile: a temporary beside it, then a
// rename). Its folder must exist and take a new file (tried, then removed).
// A device or pipe that exists (/dev/null) is accepted as is.
void checkOutputFile(const std::filesystem::path& file, const SourceLoc& where);

// FOLDER will be created if missing (with its parents) and filled: it must
// not be a file, and its nearest existing ancestor must be a folder that
// takes a new entry.
void checkOutputFolder(const std::filesystem::path& folder, const SourceLoc& where);

// output/NAME: where a command writes when no -o is given. Nothing is made
// here: the folder is made by createOutputParent when the command is about to
// write, after every check of its input, so a refused command leaves nothing.
[[nodiscard]] std::filesystem::path defaultOutputFile(const std::string& name);
// Makes FILE's folder (and its parents) when missing; Runtime error if it cannot.
void createOutputParent(const std::filesystem::path& file);

}  // namespace rollspin
