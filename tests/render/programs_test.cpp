// The renderer's programs (programs.cpp): the fixed ones, the mesh
// program's variants compiled once each on first use, and the resolve
// program made again for a new sample count.
#include <gtest/gtest.h>

#include <set>
#include <utility>
#include <vector>

#include "render/programs.hpp"
#include "renderer_fixture.hpp"

namespace rollspin::render {
namespace {

TEST_F(GlContextTest, AMeshVariantIsCompiledOnceAndEachSwitchMakesItsOwn) {
  Programs programs{ShaderLibrary{}};
  Program& plain = programs.mesh(0, false, true, true);
  EXPECT_EQ(&programs.mesh(0, false, true, true), &plain);
  // Each of mesh.frag's switches alone, from the plain lit variant: every
  // one compiles and links, and none is another's program.
  std::set<const Program*> variants{&plain};
  for (int pattern = 1; pattern <= 3; ++pattern) variants.insert(&programs.mesh(pattern, false, true, true));
  variants.insert(&programs.mesh(0, true, true, true));     // shadowed
  variants.insert(&programs.mesh(0, false, false, false));  // unlit
  variants.insert(&programs.mesh(0, false, true, false));   // no highlight
  variants.insert(&programs.mesh(0, false, true, true, 1));
  variants.insert(&programs.mesh(0, false, true, true, 2));
  variants.insert(&programs.mesh(0, false, true, true, 0, true));
  variants.insert(&programs.mesh(0, false, true, true, 1, false, true));
  variants.insert(&programs.mesh(0, false, true, true, 0, false, false, true));
  EXPECT_EQ(variants.size(), 12u);
  // A variant keeps its place when others are added after it.
  EXPECT_EQ(&programs.mesh(0, false, true, true), &plain);
}

TEST_F(GlContextTest, TheResolveProgramFollowsTheSampleCount) {
  Programs programs{ShaderLibrary{}};
  Program& four = programs.resolve(4);
  EXPECT_EQ(&programs.resolve(4), &four);
  four.use();
  const GLint location = four.at("samples");
  EXPECT_GE(location, 0);
  // Made again for 2 samples (the same slot: one resolver at a time).
  Program& two = programs.resolve(2);
  two.use();
  EXPECT_GE(two.at("samples"), 0);
  GLint linked = 0, current = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &current);
  glGetProgramiv(static_cast<GLuint>(current), GL_LINK_STATUS, &linked);
  EXPECT_EQ(linked, GL_TRUE);
  glUseProgram(0);
}

// A uniform a pass sets but its shader does not use (or that the compiler
// dropped) would be set at location -1: silently nothing.
TEST_F(GlContextTest, TheFixedProgramsUseEveryUniformThePassesSet) {
  Programs programs{ShaderLibrary{}};
  const std::pair<Program*, std::vector<const char*>> uses[] = {
      {&programs.text, {"viewportSize", "textColor", "solid", "glyphAtlas"}},
      {&programs.line, {"clipFromWorld", "viewportOrigin", "viewportSize", "widthPx", "depthBias", "lineColor"}},
      {&programs.shadow, {"lightClipFromModel"}},
      {&programs.shadowSphere, {"ndcRect", "ndcDepth", "mapSize", "sphereNdc", "depthRadius"}},
      {&programs.sphereReplay, {"capturedColor", "capturedDepth", "captureOrigin", "viewportRect"}},
      {&programs.resolve(4), {"samples"}},
  };
  for (const auto& [program, names] : uses)
    for (const char* name : names) EXPECT_GE(program->at(name), 0) << name;
}

}  // namespace
}  // namespace rollspin::render
