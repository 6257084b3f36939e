// The key registry (scene/scene_keys.hpp) against the loader and the docs:
// docs/scene-reference.md is the registry's Markdown, byte for byte; every
// key the shipped scenes and `rollspin scene --print` use is in the
// registry; and each documented numeric bound is one the loader enforces.
#include <fmt/format.h>
#include <gtest/gtest.h>
#include <toml++/toml.h>

#include <cmath>
#include <filesystem>
#include <set>

#include "core/error.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_loader.hpp"
#include "support/cli_runner.hpp"
#include "support/sweep.hpp"
#include "support/test_paths.hpp"

namespace {

using namespace rollspin::scene;
using rollspin::test::readFile;
using rollspin::test::runRollspin;
using rollspin::test::sourceDir;

const char* kRegenerate = "regenerate it with: build/rollspin keys --markdown > docs/scene-reference.md";

TEST(KeyRegistry, ReferenceListsEveryKeyTheLoaderAccepts) {
  const std::string docs = readFile(sourceDir() / "docs" / "scene-reference.md");
  ASSERT_FALSE(docs.empty()) << "docs/scene-reference.md is missing; " << kRegenerate;
  for (const KeyInfo& k : sceneKeys()) {
    // Each section's table starts at its heading; the key must be in that table.
    const std::size_t heading = docs.find(k.section.empty()               ? std::string("## Top level")
                                          : k.section == "segment"        ? std::string("## [[segment]]")
                                          : k.section == "segment.camera" ? std::string("## segment camera")
                                                                          : "## [" + k.section + "]");
    ASSERT_NE(heading, std::string::npos) << "no section for " << k.section << "; " << kRegenerate;
    const std::size_t next = docs.find("\n## ", heading + 1);
    const std::string table = docs.substr(heading, next == std::string::npos ? std::string::npos : next - heading);
    EXPECT_NE(table.find("| `" + k.key + "` |"), std::string::npos)
        << (k.section.empty() ? k.key : k.section + "." + k.key) << " is accepted by the loader but missing from "
        << "docs/scene-reference.md; " << kRegenerate;
  }
}

TEST(KeyRegistry, ReferenceIsCurrent) {
  EXPECT_TRUE(readFile(sourceDir() / "docs" / "scene-reference.md") == keysMarkdown())
      << "docs/scene-reference.md differs from `rollspin keys --markdown` (stale); " << kRegenerate;
}

// The registry's key names for one table of a document, recursively:
// a segment's path is a [path], its surface a [surface], its camera the
// segment.camera table.
void collectKeys(const toml::table& t, const std::string& section, std::set<std::string>& out) {
  for (auto&& [k, node] : t) {
    const std::string key(k.str());
    out.insert(section.empty() ? key : section + "." + key);
    if (section.empty() && node.is_table()) collectKeys(*node.as_table(), key, out);
    if (section.empty() && node.is_array_of_tables())
      for (const auto& entry : *node.as_array()) collectKeys(*entry.as_table(), key, out);
    if (section == "segment" && node.is_table())
      collectKeys(*node.as_table(), key == "path" ? "path" : key == "surface" ? "surface" : "segment.camera", out);
  }
}

bool inRegistry(const std::string& full) {
  const std::size_t dot = full.rfind('.');
  const std::string section = dot == std::string::npos ? "" : full.substr(0, dot);
  const std::string key = dot == std::string::npos ? full : full.substr(dot + 1);
  if (section.empty() && key != "extends") return std::ranges::find(keySections(), key) != keySections().end();
  return keysOf(section).contains(key);
}

TEST(KeyRegistry, HoldsEveryKeyOfTheShippedScenesAndTheirPrintedForm) {
  int scenes = 0;
  for (const std::filesystem::path& scene : rollspin::test::sweep(rollspin::test::bundledSceneFiles())) {
    const std::filesystem::directory_entry entry(scene);
    ++scenes;
    std::set<std::string> keys;
    collectKeys(toml::parse_file(entry.path().string()), "", keys);
    // The printed scene: every default filled in, for the scene's kinds.
    const auto printed = runRollspin({"scene", entry.path().string(), "--print"});
    ASSERT_EQ(printed.exitCode, 0) << printed.err;
    collectKeys(toml::parse(printed.out), "", keys);
    for (const std::string& key : keys)
      EXPECT_TRUE(inRegistry(key)) << entry.path().filename() << ": " << key << " is not in the key registry";
  }
  EXPECT_GE(scenes, rollspin::test::sweepSampled() ? 3 : 10);
}

// A scene where the key applies: for a surface key its first kind, for a
// path key the first path kind (and a surface it lies on) that takes it.
std::string sceneFor(const KeyInfo& k, const std::string& value) {
  if (k.section == "surface") {
    for (const auto& row : surfaceKinds())
      if (std::ranges::find(row.keys, k.key) != row.keys.end())
        return "[surface]\nkind = \"" + std::string(row.name) + "\"\n" + k.key + " = " + value + "\n";
  }
  if (k.section == "path") {
    for (const auto& row : pathKinds())
      for (const auto& pk : row.keys) {
        if (pk.key != k.key) continue;
        for (const auto& surface : surfaceKinds()) {
          const bool onIt = pk.on.empty() || std::ranges::find(pk.on, surface.kind) != pk.on.end();
          if (onIt && liesOn(row.kind, surface.kind))
            return "[surface]\nkind = \"" + std::string(surface.name) + "\"\n[path]\nkind = \"" +
                   std::string(row.name) + "\"\n" + k.key + " = " + value + "\n";
        }
      }
  }
  if (k.section == "segment")
    return "[[segment]]\nhold = 1\n[[segment]]\npath = { kind = \"line\" }\n" +
           (k.key == "hold" ? "[[segment]]\nhold = " + value + "\n" : k.key + " = " + value + "\n");
  if (k.section == "segment.camera") return "[[segment]]\nhold = 1\ncamera = { " + k.key + " = " + value + " }\n";
  if (k.section == "solver" && k.key == "steps") return "[solver]\nmethod = \"rk4\"\nsteps = " + value + "\n";
  if (k.section == "solver" && k.key == "tolerance") return "[solver]\nmethod = \"rk45\"\ntolerance = " + value + "\n";
  return "[" + k.section + "]\n" + k.key + " = " + value + "\n";
}

std::string literal(double v, bool integer) {
  if (integer) return std::to_string(static_cast<long long>(v));
  return fmt::format("{:.17g}", v).find_first_of(".e") == std::string::npos ? fmt::format("{:.17g}.0", v)
                                                                            : fmt::format("{:.17g}", v);
}

TEST(KeyRegistry, EveryDocumentedBoundIsOneTheLoaderEnforces) {
  int probes = 0;
  for (const KeyInfo& k : sceneKeys()) {
    if (!k.bounds) continue;
    const bool integer = k.type == "integer";
    // The first value past each end: the end itself when open, a step beyond when closed.
    std::vector<double> outside;
    // animation.fps reads decimals to 3 places (23.976), so its step is 0.001.
    const double step = integer ? 1.0 : k.key == "fps" ? 1e-3 : 1e-9;
    if (k.bounds->lo)
      outside.push_back(k.bounds->loOpen ? *k.bounds->lo
                                         : *k.bounds->lo - step * std::max(1.0, std::abs(*k.bounds->lo)));
    if (k.bounds->hi)
      outside.push_back(k.bounds->hiOpen ? *k.bounds->hi
                                         : *k.bounds->hi + step * std::max(1.0, std::abs(*k.bounds->hi)));
    for (double v : outside) {
      const std::string text = sceneFor(k, literal(v, integer));
      const std::string full =
          (k.section == "segment" || k.section == "segment.camera") ? k.key : k.section + "." + k.key;
      try {
        (void)loadSceneText(text, "probe.toml");
        ADD_FAILURE() << full << " = " << literal(v, integer) << " was accepted, but the reference says "
                      << rangeText(k) << "\n"
                      << text;
      } catch (const rollspin::Error& e) {
        EXPECT_NE(std::string(e.what()).find(full), std::string::npos) << e.what() << "\n" << text;
      }
      ++probes;
    }
  }
  EXPECT_GE(probes, 40);
}

TEST(KeyRegistry, AMisspelledKeySuggestsTheNearestOne) {
  try {
    (void)loadSceneText("[ball]\nradus = 2\n", "typo.toml");
    FAIL() << "accepted an unknown key";
  } catch (const rollspin::Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("typo.toml:2:"), std::string::npos) << message;
    EXPECT_NE(message.find("ball.radus: unknown key; did you mean `radius`?"), std::string::npos) << message;
  }
}

}  // namespace
