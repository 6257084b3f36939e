// Sub-command registration: each command family lives in its own file and
// adds itself to the CLI11 app; main() only dispatches and maps errors to
// exit codes. A handler returns the process exit code.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>

namespace rollspin::cli {

using CommandHandler = std::function<int()>;

// Adds `solve` and `timeline`; sets `handler` when one of them is chosen.
void registerSolveCommands(CLI::App& cli, CommandHandler& handler);

// Adds `render` (stills) and `compare` (images); render_commands.cpp.
void registerRenderCommands(CLI::App& cli, CommandHandler& handler);
// `scene --print` and `scene --from FILE` (scene_command.cpp).
void registerSceneCommand(CLI::App& cli, CommandHandler& handler);

// Adds `report` with errors | stress | paper; report_commands.cpp.
void registerReportCommands(CLI::App& cli, CommandHandler& handler);

// Adds `join` (the parts of a split render → one clip); join_command.cpp.
void registerJoinCommand(CLI::App& cli, CommandHandler& handler);
// Adds `info`: the GL backends and the context a render gets; info_command.cpp.
void registerInfoCommand(CLI::App& cli, CommandHandler& handler);
// Adds `export` (glTF 2.0); export_command.cpp.
void registerExportCommand(CLI::App& cli, CommandHandler& handler);
// Adds `keys`, `scenes` and the hidden `generate` (man page, completions); help_commands.cpp.
void registerHelpCommands(CLI::App& cli, CommandHandler& handler);

}  // namespace rollspin::cli
