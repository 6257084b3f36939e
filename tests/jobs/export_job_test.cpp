// jobs/export_job.hpp: the glTF export job both doors call. Its output is
// named from the scene when no -o is given, carries the resolved scene (or,
// with metadata off, none), and a name it cannot write is refused before
// any work, naming the flag.
#include "jobs/export_job.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "core/error.hpp"
#include "jobs/remembered_output.hpp"
#include "jobs/scene_print.hpp"
#include "scene/scene_loader.hpp"
#include "scene/scene_writer.hpp"
#include "support/test_files.hpp"

namespace rollspin::jobs {
namespace export_job_test {

namespace fs = std::filesystem;

scene::SceneSpec circleScene() {
  scene::SceneSpec spec =
      scene::loadSceneText("[ball]\nradius = 0.5\n[path]\nkind = \"circle\"\nradius = 2\n", "exported.toml");
  spec.name = "exported";
  return spec;
}

std::string firstBytes(const fs::path& file, std::size_t n) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes(n, '\0');
  in.read(bytes.data(), static_cast<std::streamsize>(n));
  bytes.resize(static_cast<std::size_t>(in.gcount()));
  return bytes;
}

// Run in a fresh folder: the default name is output/<scene>.glb below the working directory.
class ExportJobTest : public ::testing::Test {
 protected:
  void SetUp() override {
    before_ = fs::current_path();
    dir_ = test::freshTempDir("export_job");
    fs::current_path(dir_);
  }
  void TearDown() override { fs::current_path(before_); }
  fs::path before_, dir_;
};

TEST_F(ExportJobTest, WithoutANameTheSceneGoesToOutputAsAGlbThatRemembersIt) {
  const scene::SceneSpec spec = circleScene();
  const fs::path written = exportGltf(ExportJob{&spec, "exported.toml", {}, true});
  EXPECT_EQ(written, fs::path("output") / "exported.glb");
  ASSERT_TRUE(fs::exists(dir_ / written));
  EXPECT_EQ(firstBytes(written, 4), "glTF");
  // What it remembers is the resolved scene, which loads back to the same scene.
  const RememberedOutput remembered = readRememberedOutput(written);
  EXPECT_EQ(remembered.metadata.scene, resolvedSceneText("exported.toml", spec));
  EXPECT_EQ(scene::writeScene(scene::loadSceneText(remembered.metadata.scene, "remembered.toml")),
            scene::writeScene(spec));
  // Nothing else is left in output/: the temporary name was renamed.
  EXPECT_EQ(std::distance(fs::directory_iterator(dir_ / "output"), fs::directory_iterator()), 1);
}

TEST_F(ExportJobTest, WithoutMetadataTheFileCarriesNoScene) {
  const scene::SceneSpec spec = circleScene();
  const fs::path written = exportGltf(ExportJob{&spec, "exported.toml", dir_ / "bare.glb", false});
  EXPECT_EQ(written, dir_ / "bare.glb");
  EXPECT_EQ(firstBytes(written, 4), "glTF");
  try {
    (void)readRememberedOutput(written);
    FAIL() << "a file written without metadata remembers a scene";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadInput);
  }
}

TEST_F(ExportJobTest, AGltfNameWritesItsBufferBeside) {
  const scene::SceneSpec spec = circleScene();
  const fs::path written = exportGltf(ExportJob{&spec, "exported.toml", dir_ / "roll.gltf", true});
  EXPECT_EQ(written, dir_ / "roll.gltf");
  EXPECT_EQ(firstBytes(written, 1), "{");
  EXPECT_TRUE(fs::exists(dir_ / "roll.bin"));
  EXPECT_FALSE(readRememberedOutput(written).metadata.scene.empty());
}

TEST_F(ExportJobTest, ANameThatIsNotGltfIsRefusedNamingTheFlag) {
  for (const char* name : {"roll.png", "roll"}) {
    try {
      checkExportOutput(dir_ / name);
      FAIL() << name << " is accepted";
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadInput);
      EXPECT_NE(e.where().file.find("-o "), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("expected a .glb or .gltf file name"), std::string::npos) << e.what();
    }
  }
  fs::create_directories(dir_ / "taken.glb");  // a folder where the file would go
  EXPECT_THROW(checkExportOutput(dir_ / "taken.glb"), Error);
  EXPECT_NO_THROW(checkExportOutput(dir_ / "fine.GLB"));
}

}  // namespace export_job_test
}  // namespace rollspin::jobs
