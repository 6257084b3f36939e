// ShaderLibrary: `#include "NAME"` lines are expanded from the same place the
// shader came from (embedded, or --shader-dir), recursively; a cycle is an error.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "render/shader_library.hpp"
#include "support/test_files.hpp"

namespace rollspin::render {
namespace {

TEST(ShaderLibrary, ExpandsIncludesFromTheOverrideDirectory) {
  const auto dir = test::freshTempDir("shader_include");
  std::ofstream(dir / "a.frag.glsl") << "#version 450 core\n#include \"b\"\nvoid main() { f(); }\n";
  std::ofstream(dir / "b.glsl") << "#include \"c\"\nvoid f() { g(); }\n";
  std::ofstream(dir / "c.glsl") << "void g() {}\n";
  EXPECT_EQ(ShaderLibrary(dir).source("a.frag"),
            "#version 450 core\nvoid g() {}\nvoid f() { g(); }\nvoid main() { f(); }\n");
}

TEST(ShaderLibrary, AnIncludeCycleIsAnError) {
  const auto dir = test::freshTempDir("shader_cycle");
  std::ofstream(dir / "a.glsl") << "#include \"b\"\n";
  std::ofstream(dir / "b.glsl") << "#include \"a\"\n";
  EXPECT_THROW((void)ShaderLibrary(dir).source("a"), Error);
}

TEST(ShaderLibrary, TheEmbeddedFragmentShadersShareOneSrgbEncoder) {
  const ShaderLibrary embedded;
  for (const char* name : {"mesh.frag", "line.frag", "text.frag"}) {
    const std::string text = embedded.source(name);
    EXPECT_NE(text.find("vec3 encodeSrgb(vec3 c)"), std::string::npos) << name;
    EXPECT_EQ(text.find("#include"), std::string::npos) << name;
  }
}

TEST(ShaderLibrary, ShadersAreEmbeddedAndOverridable) {
  EXPECT_NE(ShaderLibrary{}.source("mesh.frag").find("#version 450 core"), std::string::npos);
  EXPECT_THROW((void)ShaderLibrary{"/nonexistent-shader-dir"}.source("mesh.frag"), Error);
  // The repository's shaders/ folder is a valid override (--shader-dir shaders).
  EXPECT_EQ(ShaderLibrary{test::sourceDir() / "shaders"}.source("mesh.frag"), ShaderLibrary{}.source("mesh.frag"));
}

}  // namespace
}  // namespace rollspin::render
