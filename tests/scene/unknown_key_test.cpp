// An unknown key's message (schema_reader.cpp, unknownKey): a key typed
// without its unit suffix (`colatitude` for `colatitude_deg`), or with
// another unit's (`_rad`), is answered with the key in the schema's unit
// alone, for every such key of the registry; a plain typo keeps the nearest
// key and the table's list.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/error.hpp"
#include "scene/scene_keys.hpp"
#include "scene/scene_loader.hpp"

namespace {

using namespace rollspin::scene;

// The message of loading an empty scene with this one --set override.
std::string messageOf(const std::string& override) {
  try {
    const std::vector<std::string> overrides{override};
    (void)loadSceneText("", "s.toml", overrides);
  } catch (const rollspin::Error& e) {
    return e.what();
  }
  return "(loaded)";
}

// `key` without the schema's unit suffix, or "" when it has none.
std::string stemOf(const std::string& key) {
  for (const std::string suffix : {"_deg", "_mm", "_pt"})
    if (key.ends_with(suffix)) return key.substr(0, key.size() - suffix.size());
  return "";
}

TEST(UnknownKey, AKeyWithoutItsUnitSuggestsTheKeyWithIt) {
  int checked = 0;
  for (const KeyInfo& k : sceneKeys()) {
    const std::string stem = stemOf(k.key);
    // Segments' keys need a [[segment]]: the same tables, checked through path and camera.
    // A stem that is a key of its own (figure.width = "column") is not a mistake.
    if (stem.empty() || k.section.starts_with("segment") || keysOf(k.section).contains(stem)) continue;
    const std::string message = messageOf(k.section + "." + stem + "=1");
    EXPECT_NE(message.find("did you mean `" + k.key + "` (in "), std::string::npos)
        << k.section << "." << k.key << ": " << message;
    EXPECT_EQ(message.find(" accepts: "), std::string::npos) << "the list buries the answer: " << message;
    ++checked;
  }
  EXPECT_GE(checked, 8) << "the registry's _deg, _mm and _pt keys";
}

TEST(UnknownKey, ColatitudeInDegreesWhateverTheUnitTyped) {
  EXPECT_EQ(messageOf("path.colatitude=60"),
            "--set path.colatitude=60: path.colatitude: unknown key; did you mean `colatitude_deg` (in degrees)?");
  EXPECT_NE(messageOf("path.colatitude_rad=1").find("did you mean `colatitude_deg` (in degrees)?"), std::string::npos);
  EXPECT_NE(messageOf("render.azimuth_degrees=1").find("did you mean `azimuth_deg` (in degrees)?"), std::string::npos);
}

TEST(UnknownKey, APlainTypoKeepsTheNearestKeyAndTheList) {
  const std::string message = messageOf("render.widht=640");
  EXPECT_NE(message.find("did you mean `width`? [render] accepts: "), std::string::npos) << message;
}

}  // namespace
