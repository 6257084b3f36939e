// GL objects owned once: a name deleted with its owner (GlObject), a linked
// program with its uniform locations (Program), a framebuffer made and
// checked in one place (makeFramebuffer), and the vertex arrays of the
// draws whose vertices are made per draw (VertexStreams). Renderer-internal:
// include only from render/'s GL files.
#pragma once

#include <glm/glm.hpp>

#include <initializer_list>
#include <map>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "render/gl.hpp"
#include "render/shader_library.hpp"

namespace rollspin::render {

enum class GlKind { Texture, Renderbuffer, Framebuffer, Buffer, VertexArray };

// One GL name, deleted when its owner goes (the context must be current).
class GlObject {
 public:
  GlObject() = default;
  // A new name of `kind` (glGen*: bound later with its target).
  [[nodiscard]] static GlObject generate(GlKind kind);
  // A new texture of `target` made with DSA, without binding it.
  [[nodiscard]] static GlObject createTexture(GLenum target);
  ~GlObject() { reset(); }
  GlObject(GlObject&& o) noexcept : kind_(o.kind_), id_(std::exchange(o.id_, 0)) {}
  GlObject& operator=(GlObject&& o) noexcept {
    if (this != &o) {
      reset();
      kind_ = o.kind_;
      id_ = std::exchange(o.id_, 0);
    }
    return *this;
  }
  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  operator GLuint() const { return id_; }  // NOLINT: a name is passed to GL as is
  void reset();

 private:
  GlObject(GlKind kind, GLuint id) : kind_(kind), id_(id) {}
  GlKind kind_ = GlKind::Texture;
  GLuint id_ = 0;
};

// What a framebuffer attaches at `point`: a renderbuffer (target
// GL_RENDERBUFFER) or level 0 of a texture of `target`.
struct Attachment {
  GLenum point;
  GLenum target;
  GLuint name;
};

// A framebuffer of `attachments`, left bound to GL_FRAMEBUFFER, drawing into
// its colour attachments in order (none: depth only). Throws when GL cannot
// complete it: "could not create a WxH <what> (out of memory?)".
[[nodiscard]] GlObject makeFramebuffer(std::initializer_list<Attachment> attachments, int width, int height,
                                       std::string_view what);

// A linked program with a uniform-location cache.
class Program {
 public:
  // `defines` ("#define X 1\n...") go right after each stage's #version line.
  Program(const ShaderLibrary& lib, const std::string& vert, const std::string& frag, const std::string& geom = {},
          const std::string& defines = {});
  ~Program();
  Program(Program&& o) noexcept : id_(std::exchange(o.id_, 0)), locations_(std::move(o.locations_)) {}
  Program& operator=(Program&&) = delete;
  Program(const Program&) = delete;
  void use() const { glUseProgram(id_); }
  GLint at(const char* name) {
    auto it = locations_.find(name);
    if (it == locations_.end()) it = locations_.emplace(name, glGetUniformLocation(id_, name)).first;
    return it->second;
  }
  void set(const char* n, const glm::mat4& m);
  void set(const char* n, const glm::mat3& m);
  void set(const char* n, const glm::vec4& v);
  void set(const char* n, const glm::vec3& v);
  void set(const char* n, const glm::vec2& v);
  void set(const char* n, float v) { glUniform1f(at(n), v); }
  void set(const char* n, int v) { glUniform1i(at(n), v); }
  void set(const char* n, const glm::ivec2& v) { glUniform2i(at(n), v.x, v.y); }
  void set(const char* n, unsigned v) { glUniform1ui(at(n), v); }

 private:
  GLuint id_ = 0;
  std::map<std::string, GLint> locations_;
};

// The vertex arrays of the draws whose vertices are made per draw: none (a
// full-screen or impostor triangle made in its vertex shader), points
// (vec3: a polyline's, a replay's corners) and glyph quads (vec2 pixel,
// vec2 uv).
struct VertexStreams {
  GlObject empty, points, pointBuffer, glyphs, glyphBuffer;
  VertexStreams();
  // Binds the array and uploads the vertices for one draw.
  void uploadPoints(std::span<const glm::vec3> vertices) const;
  void uploadGlyphs(std::span<const float> vertices) const;
};

}  // namespace rollspin::render
