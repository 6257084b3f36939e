// Where a scene document comes from besides its own file: `extends` (a
// base scene laid under it, recursively) and --set overrides laid over it.
// Internal to scene/.
#pragma once

#include <toml++/toml.h>

#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "core/error.hpp"

namespace rollspin::scene {

// Parses TOML; a syntax error is BadInput at its file:line:col.
toml::table parseText(std::string_view text, const std::string& sourceName);
// The file's text; BadInput naming who asked for it (`extends`) when unreadable.
std::string readSceneFile(const std::filesystem::path& file, const SourceLoc& askedBy, const std::string& what);
// `extends = "other.toml"` resolved into one table; `locations` gets every key's file:line:col.
toml::table resolveExtends(toml::table root, const std::filesystem::path& file,
                           std::vector<std::filesystem::path>& chain, std::map<std::string, SourceLoc>& locations);
// "key.sub=value" (from --set) laid into the document; the key's location becomes the argument.
void applyOverride(toml::table& root, const std::string& arg, std::map<std::string, SourceLoc>& locs);
// A flag's key (scene_loader.hpp) laid into the document; its location becomes the flag.
struct KeySetting;
void applySetting(toml::table& root, const KeySetting& setting, std::map<std::string, SourceLoc>& locs);

}  // namespace rollspin::scene
