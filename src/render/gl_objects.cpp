#include "render/gl_objects.hpp"

#include <glm/gtc/type_ptr.hpp>

#include <vector>

#include "core/error.hpp"

namespace rollspin::render {

GlObject GlObject::generate(GlKind kind) {
  GLuint id = 0;
  switch (kind) {
    case GlKind::Texture: glGenTextures(1, &id); break;
    case GlKind::Renderbuffer: glGenRenderbuffers(1, &id); break;
    case GlKind::Framebuffer: glGenFramebuffers(1, &id); break;
    case GlKind::Buffer: glGenBuffers(1, &id); break;
    case GlKind::VertexArray: glGenVertexArrays(1, &id); break;
  }
  return GlObject(kind, id);
}

GlObject GlObject::createTexture(GLenum target) {
  GLuint id = 0;
  glCreateTextures(target, 1, &id);
  return GlObject(GlKind::Texture, id);
}

void GlObject::reset() {
  if (id_ == 0) return;
  switch (kind_) {
    case GlKind::Texture: glDeleteTextures(1, &id_); break;
    case GlKind::Renderbuffer: glDeleteRenderbuffers(1, &id_); break;
    case GlKind::Framebuffer: glDeleteFramebuffers(1, &id_); break;
    case GlKind::Buffer: glDeleteBuffers(1, &id_); break;
    case GlKind::VertexArray: glDeleteVertexArrays(1, &id_); break;
  }
  id_ = 0;
}

GlObject makeFramebuffer(std::initializer_list<Attachment> attachments, int width, int height, std::string_view what) {
  GlObject fbo = GlObject::generate(GlKind::Framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  std::vector<GLenum> colours;
  for (const Attachment& a : attachments) {
    if (a.target == GL_RENDERBUFFER) glFramebufferRenderbuffer(GL_FRAMEBUFFER, a.point, GL_RENDERBUFFER, a.name);
    else glFramebufferTexture2D(GL_FRAMEBUFFER, a.point, a.target, a.name, 0);
    if (a.point != GL_DEPTH_ATTACHMENT) colours.push_back(a.point);
  }
  // One colour attachment draws by default; none: a depth map.
  if (colours.empty()) {
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
  } else if (colours.size() > 1) {
    glDrawBuffers(static_cast<GLsizei>(colours.size()), colours.data());
  }
  if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
    throw runtimeError({}, "OpenGL could not create a {}x{} {} (out of memory?)", width, height, what);
  return fbo;
}

namespace {

GLuint compileShader(GLenum type, const std::string& source, const std::string& name) {
  const GLuint shader = glCreateShader(type);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = 0;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    std::string log(4096, '\0');
    GLsizei len = 0;
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), &len, log.data());
    log.resize(static_cast<std::size_t>(len));
    glDeleteShader(shader);
    throw runtimeError({name}, "shader compilation failed:\n{}", log);
  }
  return shader;
}

}  // namespace

Program::Program(const ShaderLibrary& lib, const std::string& vert, const std::string& frag, const std::string& geom,
                 const std::string& defines) {
  auto withDefines = [&](std::string text) {
    if (defines.empty()) return text;
    const auto eol = text.find('\n');
    return eol == std::string::npos ? text : text.insert(eol + 1, defines);
  };
  id_ = glCreateProgram();
  std::vector<GLuint> shaders{compileShader(GL_VERTEX_SHADER, withDefines(lib.source(vert)), vert),
                              compileShader(GL_FRAGMENT_SHADER, withDefines(lib.source(frag)), frag)};
  if (!geom.empty()) shaders.push_back(compileShader(GL_GEOMETRY_SHADER, lib.source(geom), geom));
  for (GLuint s : shaders) glAttachShader(id_, s);
  glLinkProgram(id_);
  for (GLuint s : shaders) glDeleteShader(s);
  GLint ok = 0;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (!ok) {
    std::string log(4096, '\0');
    GLsizei len = 0;
    glGetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), &len, log.data());
    log.resize(static_cast<std::size_t>(len));
    glDeleteProgram(id_);
    throw runtimeError({vert + " + " + frag}, "shader link failed:\n{}", log);
  }
}

Program::~Program() {
  if (id_ != 0) glDeleteProgram(id_);
}

void Program::set(const char* n, const glm::mat4& m) { glUniformMatrix4fv(at(n), 1, GL_FALSE, glm::value_ptr(m)); }
void Program::set(const char* n, const glm::mat3& m) { glUniformMatrix3fv(at(n), 1, GL_FALSE, glm::value_ptr(m)); }
void Program::set(const char* n, const glm::vec4& v) { glUniform4fv(at(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::vec3& v) { glUniform3fv(at(n), 1, glm::value_ptr(v)); }
void Program::set(const char* n, const glm::vec2& v) { glUniform2fv(at(n), 1, glm::value_ptr(v)); }

VertexStreams::VertexStreams()
    : empty(GlObject::generate(GlKind::VertexArray)),
      points(GlObject::generate(GlKind::VertexArray)),
      pointBuffer(GlObject::generate(GlKind::Buffer)),
      glyphs(GlObject::generate(GlKind::VertexArray)),
      glyphBuffer(GlObject::generate(GlKind::Buffer)) {
  glBindVertexArray(points);
  glBindBuffer(GL_ARRAY_BUFFER, pointBuffer);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
  glBindVertexArray(glyphs);
  glBindBuffer(GL_ARRAY_BUFFER, glyphBuffer);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), reinterpret_cast<void*>(2 * sizeof(float)));
  glBindVertexArray(0);
}

void VertexStreams::uploadPoints(std::span<const glm::vec3> vertices) const {
  glBindVertexArray(points);
  glBindBuffer(GL_ARRAY_BUFFER, pointBuffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size_bytes()), vertices.data(), GL_STREAM_DRAW);
}

void VertexStreams::uploadGlyphs(std::span<const float> vertices) const {
  glBindVertexArray(glyphs);
  glBindBuffer(GL_ARRAY_BUFFER, glyphBuffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size_bytes()), vertices.data(), GL_STREAM_DRAW);
}

}  // namespace rollspin::render
