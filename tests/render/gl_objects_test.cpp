// The renderer's GL objects (gl_objects.cpp): names owned once and deleted
// with their owner, framebuffers made and checked in one place, programs
// with their defines and their errors, and the per-draw vertex streams.
#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "gl_queries.hpp"
#include "render/gl_objects.hpp"
#include "renderer_fixture.hpp"
#include "support/test_files.hpp"

namespace rollspin::render {
namespace {

// A library read from `dir`, holding `files` (name → source).
ShaderLibrary libraryOf(const std::filesystem::path& dir,
                        const std::vector<std::pair<std::string, std::string>>& files) {
  for (const auto& [name, source] : files) std::ofstream(dir / (name + ".glsl")) << source;
  return ShaderLibrary(dir);
}

const std::string kFullScreen = R"(#version 450 core
void main() {
  vec2 p = vec2((gl_VertexID << 1) & 2, gl_VertexID & 2);
  gl_Position = vec4(p * 2.0 - 1.0, 0.0, 1.0);
}
)";

// The RGBA bytes of pixel (0, 0) of the bound read framebuffer.
std::array<unsigned char, 4> firstPixel() {
  std::array<unsigned char, 4> rgba{};
  glReadPixels(0, 0, 1, 1, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
  return rgba;
}

TEST_F(GlContextTest, AnObjectDeletesItsNameWhenItGoes) {
  GLuint texture = 0, buffer = 0, vertexArray = 0, framebuffer = 0, renderbuffer = 0;
  {
    const GlObject t = GlObject::generate(GlKind::Texture), b = GlObject::generate(GlKind::Buffer),
                   a = GlObject::generate(GlKind::VertexArray), f = GlObject::generate(GlKind::Framebuffer),
                   r = GlObject::generate(GlKind::Renderbuffer);
    // A generated name is an object once it is first bound.
    glBindTexture(GL_TEXTURE_2D, t);
    glBindBuffer(GL_ARRAY_BUFFER, b);
    glBindVertexArray(a);
    glBindFramebuffer(GL_FRAMEBUFFER, f);
    glBindRenderbuffer(GL_RENDERBUFFER, r);
    texture = t, buffer = b, vertexArray = a, framebuffer = f, renderbuffer = r;
    EXPECT_TRUE(TEST_GL(glIsTexture)(texture) && TEST_GL(glIsBuffer)(buffer) && TEST_GL(glIsVertexArray)(vertexArray) &&
                TEST_GL(glIsFramebuffer)(framebuffer) && TEST_GL(glIsRenderbuffer)(renderbuffer));
    glBindVertexArray(0);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
  }
  EXPECT_FALSE(TEST_GL(glIsTexture)(texture));
  EXPECT_FALSE(TEST_GL(glIsBuffer)(buffer));
  EXPECT_FALSE(TEST_GL(glIsVertexArray)(vertexArray));
  EXPECT_FALSE(TEST_GL(glIsFramebuffer)(framebuffer));
  EXPECT_FALSE(TEST_GL(glIsRenderbuffer)(renderbuffer));
}

TEST_F(GlContextTest, AMovedObjectHasOneOwnerAndAnAssignedOneLetsItsOldNameGo) {
  GlObject first = GlObject::createTexture(GL_TEXTURE_2D);  // DSA: an object at once
  const GLuint name = first;
  ASSERT_NE(name, 0u);
  ASSERT_TRUE(TEST_GL(glIsTexture)(name));
  GlObject second(std::move(first));
  EXPECT_EQ(GLuint(first), 0u);  // NOLINT(bugprone-use-after-move): moved-from is empty by contract
  EXPECT_EQ(GLuint(second), name);
  first.reset();  // an empty owner resets to nothing
  EXPECT_TRUE(TEST_GL(glIsTexture)(name));

  GlObject third = GlObject::createTexture(GL_TEXTURE_2D);
  const GLuint replaced = third;
  third = std::move(second);
  EXPECT_FALSE(TEST_GL(glIsTexture)(replaced));
  EXPECT_EQ(GLuint(third), name);
  third = std::move(third);  // NOLINT: self-move keeps the name
  EXPECT_TRUE(TEST_GL(glIsTexture)(name));
  third.reset();
  EXPECT_EQ(GLuint(third), 0u);
  EXPECT_FALSE(TEST_GL(glIsTexture)(name));
}

TEST_F(GlContextTest, AFramebufferDrawsIntoEveryColourAttachmentAndNoneForADepthMap) {
  GlObject colours[2] = {GlObject::createTexture(GL_TEXTURE_2D), GlObject::createTexture(GL_TEXTURE_2D)};
  for (const GlObject& c : colours) glTextureStorage2D(c, 1, GL_RGBA8, 8, 4);
  GlObject depth = GlObject::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(depth, 1, GL_DEPTH_COMPONENT24, 8, 4);

  const GlObject two = makeFramebuffer({{GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, colours[0]},
                                        {GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, colours[1]},
                                        {GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth}},
                                       8, 4, "test target");
  GLint bound = 0, drawBuffer0 = 0, drawBuffer1 = 0;
  glGetIntegerv(GL_FRAMEBUFFER_BINDING, &bound);
  EXPECT_EQ(GLuint(bound), GLuint(two));  // left bound
  glGetIntegerv(GL_DRAW_BUFFER0, &drawBuffer0);
  glGetIntegerv(GL_DRAW_BUFFER1, &drawBuffer1);
  EXPECT_EQ(drawBuffer0, GL_COLOR_ATTACHMENT0);
  EXPECT_EQ(drawBuffer1, GL_COLOR_ATTACHMENT1);
  // A clear reaches both colour attachments.
  const float green[4] = {0.0f, 1.0f, 0.0f, 1.0f};
  glClearBufferfv(GL_COLOR, 0, green);
  glClearBufferfv(GL_COLOR, 1, green);
  for (const GlObject& c : colours) {
    std::array<unsigned char, 8 * 4 * 4> pixels{};
    TEST_GL(glGetTextureImage)(c, 0, GL_RGBA, GL_UNSIGNED_BYTE, static_cast<GLsizei>(pixels.size()), pixels.data());
    EXPECT_EQ(pixels[1], 255);
    EXPECT_EQ(pixels[pixels.size() - 3], 255);
  }

  const GlObject depthMap = makeFramebuffer({{GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth}}, 8, 4, "depth map");
  glGetIntegerv(GL_DRAW_BUFFER0, &drawBuffer0);
  GLint readBuffer = 0;
  glGetIntegerv(GL_READ_BUFFER, &readBuffer);
  EXPECT_EQ(drawBuffer0, GL_NONE);
  EXPECT_EQ(readBuffer, GL_NONE);
  EXPECT_EQ(glCheckFramebufferStatus(GL_FRAMEBUFFER), GLenum(GL_FRAMEBUFFER_COMPLETE));
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(GlContextTest, AFramebufferGlCannotCompleteIsAnErrorThatSaysWhatAndHowLarge) {
  try {
    (void)makeFramebuffer({}, 640, 360, "retained layer with 4 samples");
    FAIL() << "a framebuffer with no attachment is incomplete";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Runtime);
    EXPECT_NE(std::string(e.what()).find("could not create a 640x360 retained layer with 4 samples"), std::string::npos)
        << e.what();
  }
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

// Defines go after the #version line (which must stay first) of both stages;
// a uniform is set by name, its location looked up once.
TEST_F(GlContextTest, AProgramTakesItsDefinesAfterTheVersionLineAndItsUniformsByName) {
  const auto dir = test::freshTempDir("gl_objects_program");
  const ShaderLibrary lib = libraryOf(dir, {{"full.vert", kFullScreen},
                                            {"level.frag",
                                             "#version 450 core\n#ifndef RED\n#error RED is not defined\n#endif\n"
                                             "uniform float green;\nout vec4 colour;\n"
                                             "void main() { colour = vec4(RED, green, 0.0, 1.0); }\n"}});
  Program program(lib, "full.vert", "level.frag", {}, "#define RED 1.0\n");
  GlObject target = GlObject::createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(target, 1, GL_RGBA8, 2, 2);
  const GlObject fbo = makeFramebuffer({{GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, target}}, 2, 2, "test target");
  const GlObject empty = GlObject::generate(GlKind::VertexArray);
  glViewport(0, 0, 2, 2);
  glDisable(GL_DEPTH_TEST);
  glDisable(GL_BLEND);
  glBindVertexArray(empty);
  program.use();
  const GLint location = program.at("green");
  EXPECT_GE(location, 0);
  EXPECT_EQ(program.at("green"), location);
  EXPECT_EQ(program.at("no_such_uniform"), -1);
  program.set("green", 0.5f);
  glDrawArrays(GL_TRIANGLES, 0, 3);
  const auto rgba = firstPixel();
  EXPECT_EQ(rgba[0], 255);
  EXPECT_NEAR(rgba[1], 128, 1);
  EXPECT_EQ(rgba[2], 0);

  // Without the define the fragment stage stops at its #error.
  EXPECT_THROW(Program(lib, "full.vert", "level.frag"), Error);
  glBindVertexArray(0);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

TEST_F(GlContextTest, AShaderThatDoesNotCompileOrLinkIsNamedWithGlsLog) {
  const auto dir = test::freshTempDir("gl_objects_errors");
  const ShaderLibrary lib =
      libraryOf(dir, {{"full.vert", kFullScreen},
                      {"broken.frag", "#version 450 core\nout vec4 colour;\nvoid main() { colour = vec4(1.0) }\n"},
                      {"unfed.frag",
                       "#version 450 core\nin vec3 neverWritten;\nout vec4 colour;\n"
                       "void main() { colour = vec4(neverWritten, 1.0); }\n"}});
  try {
    Program bad(lib, "full.vert", "broken.frag");
    FAIL() << "a missing semicolon compiles";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("broken.frag"), std::string::npos) << message;
    EXPECT_NE(message.find("shader compilation failed"), std::string::npos) << message;
  }
  try {
    Program unlinked(lib, "full.vert", "unfed.frag");
    FAIL() << "a fragment input no vertex stage writes links";
  } catch (const Error& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("full.vert + unfed.frag"), std::string::npos) << message;
    EXPECT_NE(message.find("shader link failed"), std::string::npos) << message;
  }
}

TEST_F(GlContextTest, TheStreamsUploadEachDrawsVerticesIntoTheirOwnArrays) {
  const VertexStreams streams;
  EXPECT_NE(GLuint(streams.empty), 0u);
  const std::vector<glm::vec3> points{{0, 0, 0}, {1, 2, 3}, {4, 5, 6}};
  streams.uploadPoints(points);
  GLint boundArray = 0, size = 0;
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &boundArray);
  EXPECT_EQ(GLuint(boundArray), GLuint(streams.points));
  TEST_GL(glGetNamedBufferParameteriv)(streams.pointBuffer, GL_BUFFER_SIZE, &size);
  EXPECT_EQ(size, GLint(3 * sizeof(glm::vec3)));
  std::array<float, 9> back{};
  TEST_GL(glGetNamedBufferSubData)(streams.pointBuffer, 0, sizeof(back), back.data());
  EXPECT_EQ(back[4], 2.0f);

  const std::vector<float> glyphs(2 * 6 * 4, 0.25f);  // two glyph quads of six corners
  streams.uploadGlyphs(glyphs);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &boundArray);
  EXPECT_EQ(GLuint(boundArray), GLuint(streams.glyphs));
  TEST_GL(glGetNamedBufferParameteriv)(streams.glyphBuffer, GL_BUFFER_SIZE, &size);
  EXPECT_EQ(size, GLint(glyphs.size() * sizeof(float)));
  // A glyph vertex is a pixel position and a texture coordinate: two attributes, four floats apart.
  GLint stride = 0;
  void* uvOffset = nullptr;
  TEST_GL(glGetVertexArrayIndexediv)(streams.glyphs, 1, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &stride);
  TEST_GL(glGetVertexAttribPointerv)(1, GL_VERTEX_ATTRIB_ARRAY_POINTER, &uvOffset);
  EXPECT_EQ(stride, GLint(4 * sizeof(float)));
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(uvOffset), 2 * sizeof(float));
  glBindVertexArray(0);
}

}  // namespace
}  // namespace rollspin::render
