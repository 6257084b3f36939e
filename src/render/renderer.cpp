#include "render/renderer.hpp"

#include <glm/gtc/matrix_inverse.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <bit>
#include <cstring>
#include <deque>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "core/error.hpp"
#include "core/stage_log.hpp"
#include "render/coverage_edges.hpp"
#include "render/font_atlas.hpp"
#include "render/gl.hpp"
#include "render/layer_key.hpp"
#include "render/mesh_builders.hpp"
#include "render/screen_bounds.hpp"

namespace rollspin::render {

namespace {

// The shadow box is fitted to the casters (see shadowPass), so a small map
// resolves a ball's shadow finely: at 256 texels a ball spans about 200 and
// the soft-shadow filter about 13 in radius.
constexpr int kShadowMapSize = 256;

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

// A linked program with a uniform-location cache.
class Program {
 public:
  Program() = default;
  // `defines` ("#define X 1\n...") go right after each stage's #version line.
  Program(const ShaderLibrary& lib, const std::string& vert, const std::string& frag, const std::string& geom = {},
          const std::string& defines = {}) {
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
      throw runtimeError({vert + " + " + frag}, "shader link failed:\n{}", log);
    }
  }
  void use() const { glUseProgram(id_); }
  GLint at(const char* name) {
    auto it = locations_.find(name);
    if (it == locations_.end()) it = locations_.emplace(name, glGetUniformLocation(id_, name)).first;
    return it->second;
  }
  void set(const char* n, const glm::mat4& m) { glUniformMatrix4fv(at(n), 1, GL_FALSE, glm::value_ptr(m)); }
  void set(const char* n, const glm::mat3& m) { glUniformMatrix3fv(at(n), 1, GL_FALSE, glm::value_ptr(m)); }
  void set(const char* n, const glm::vec4& v) { glUniform4fv(at(n), 1, glm::value_ptr(v)); }
  void set(const char* n, const glm::vec3& v) { glUniform3fv(at(n), 1, glm::value_ptr(v)); }
  void set(const char* n, const glm::vec2& v) { glUniform2fv(at(n), 1, glm::value_ptr(v)); }
  void set(const char* n, float v) { glUniform1f(at(n), v); }
  void set(const char* n, int v) { glUniform1i(at(n), v); }
  void set(const char* n, const glm::ivec2& v) { glUniform2i(at(n), v.x, v.y); }
  void set(const char* n, unsigned v) { glUniform1ui(at(n), v); }
  void set(const char* n, const glm::vec2* v, int count) { glUniform2fv(at(n), count, glm::value_ptr(*v)); }
  void release() {
    if (id_ != 0) glDeleteProgram(id_);
    id_ = 0;
  }

 private:
  GLuint id_ = 0;
  std::map<std::string, GLint> locations_;
};

// A run of a mesh's triangles, consecutive in its index buffer, and the
// bounding box of their corners in model coordinates.
struct MeshChunk {
  GLsizei firstIndex = 0, indexCount = 0;
  glm::vec3 lo{0.0f}, hi{0.0f};
};

struct GpuMesh {
  GLuint vao = 0, vbo = 0, ebo = 0;
  GLsizei indexCount = 0;
  glm::vec4 bound{0.0f};  // a bounding sphere in model coordinates: centre, radius
  glm::vec3 lo{0.0f}, hi{0.0f};  // the bounding box in model coordinates
  std::vector<MeshChunk> chunks;  // the triangles in runs of kChunkTriangles, in index order
};

// Small enough that a run of a sphere's band spans a few degrees of it, large
// enough that testing the runs costs little beside drawing them.
constexpr std::size_t kChunkTriangles = 32;

GpuMesh upload(const MeshData& m) {
  GpuMesh g;
  glGenVertexArrays(1, &g.vao);
  glGenBuffers(1, &g.vbo);
  glGenBuffers(1, &g.ebo);
  glBindVertexArray(g.vao);
  glBindBuffer(GL_ARRAY_BUFFER, g.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.vertices.size() * sizeof(Vertex)), m.vertices.data(),
               GL_STATIC_DRAW);
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, g.ebo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(m.indices.size() * sizeof(std::uint32_t)),
               m.indices.data(), GL_STATIC_DRAW);
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, normal)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, sizeof(Vertex), reinterpret_cast<void*>(offsetof(Vertex, uv)));
  glBindVertexArray(0);
  g.indexCount = static_cast<GLsizei>(m.indices.size());
  if (!m.vertices.empty()) {
    glm::vec3 lo(m.vertices[0].position), hi(lo);
    for (const Vertex& v : m.vertices) {
      lo = glm::min(lo, v.position);
      hi = glm::max(hi, v.position);
    }
    g.lo = lo;
    g.hi = hi;
    const glm::vec3 centre = 0.5f * (lo + hi);
    float radius = 0.0f;
    for (const Vertex& v : m.vertices) radius = std::max(radius, glm::length(v.position - centre));
    g.bound = glm::vec4(centre, radius);
  }
  for (std::size_t first = 0; first + 3 <= m.indices.size(); first += 3 * kChunkTriangles) {
    const std::size_t end = std::min(m.indices.size() - m.indices.size() % 3, first + 3 * kChunkTriangles);
    MeshChunk c{static_cast<GLsizei>(first), static_cast<GLsizei>(end - first), m.vertices[m.indices[first]].position,
                m.vertices[m.indices[first]].position};
    for (std::size_t i = first; i < end; ++i) {
      c.lo = glm::min(c.lo, m.vertices[m.indices[i]].position);
      c.hi = glm::max(c.hi, m.vertices[m.indices[i]].position);
    }
    g.chunks.push_back(c);
  }
  return g;
}

void release(GpuMesh& g) {
  glDeleteBuffers(1, &g.vbo);
  glDeleteBuffers(1, &g.ebo);
  glDeleteVertexArrays(1, &g.vao);
  g = {};
}

// The eight corners of the box [lo, hi], placed by `transform`.
std::array<glm::vec3, 8> boxCorners(const glm::vec3& lo, const glm::vec3& hi,
                                    const glm::mat4& transform = glm::mat4(1.0f)) {
  std::array<glm::vec3, 8> corners;
  for (int k = 0; k < 8; ++k)
    corners[std::size_t(k)] =
        glm::vec3(transform * glm::vec4(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z, 1.0f));
  return corners;
}

// worldFromModel for a unit z-aligned primitive stretched from a to b.
glm::mat4 alongSegment(const glm::vec3& a, const glm::vec3& b, float radius) {
  const glm::vec3 d = b - a;
  const float len = glm::length(d);
  const glm::vec3 z = len > 0.0f ? d / len : glm::vec3(0, 0, 1);
  const glm::vec3 helper = std::abs(z.z) < 0.9f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
  const glm::vec3 x = glm::normalize(glm::cross(helper, z));
  const glm::vec3 y = glm::cross(z, x);
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(x * radius, 0.0f);
  m[1] = glm::vec4(y * radius, 0.0f);
  m[2] = glm::vec4(d, 0.0f);
  m[3] = glm::vec4(a, 1.0f);
  return m;
}


}  // namespace

// Per-view state every mesh program needs.
struct MeshViewUniforms {
  glm::mat4 clipFromWorld{1.0f};
  glm::mat4 lightClipFromWorld{1.0f};
  glm::vec3 towardLight{0.0f, 0.0f, 1.0f};
  glm::vec3 lightColor{1.0f};
  float ambient = 0.35f;
  glm::vec3 cameraPosition{0.0f};
  float shadowFilterRadius = 0.0f;
  const View* view = nullptr;  // its viewport, for ray-cast spheres
};

// An image's pixels: the layer image of `epoch` at `version`, except inside
// `written` (a frame's rectangles). Epochs are unique in the process, so a
// history never matches another renderer's layer.
struct ImageHistory::State {
  std::uint64_t epoch = 0;  // 0: unknown
  std::uint64_t version = 0;
  std::vector<PixelRect> written;
  const std::uint8_t* pixels = nullptr;  // the buffer it describes
};
ImageHistory::ImageHistory() = default;
ImageHistory::~ImageHistory() = default;
ImageHistory::ImageHistory(ImageHistory&&) noexcept = default;
ImageHistory& ImageHistory::operator=(ImageHistory&&) noexcept = default;
void ImageHistory::reset() { state_.reset(); }

struct Renderer::Impl {
  ShaderLibrary library;  // a copy: mesh variants compile lazily
  bool retainLayers = true;
  std::map<int, Program> meshPrograms;  // by variant: see meshProgram
  MeshViewUniforms viewUniforms;
  Program shadow, shadowSphere, line, text, depthProgram, sphereReplay;
  GLuint emptyVao = 0;
  GLuint streamVao = 0, streamVbo = 0;  // polylines (vec3)
  GLuint textVao = 0, textVbo = 0;      // glyph quads (vec2 pixel, vec2 uv)
  struct ShadowMap {
    GLuint fbo = 0, texture = 0;
  };
  std::vector<ShadowMap> shadowMaps;  // one per view that has a shadow (usually one)
  // The static opaque meshes are drawn into sceneFbo (a colour texture of
  // one sample, over transparent black), and near their edges also into
  // opaqueFbo (multisampled; none at msaa = 1) and resolved over it (see
  // drawViewOpaque); every later step draws into sceneFbo with analytic
  // coverage; then it is read back, the backdrop put behind and the rows
  // flipped top-down on the CPU (see readBack).
  GLuint opaqueFbo = 0, opaqueColor = 0, opaquePacked = 0, opaqueDepth = 0;
  GLuint resolveFbo = 0;            // the scene's colour as packed words (see resolveOpaque)
  std::optional<Program> resolver;  // for the sample count of opaqueFbo
  int targetSamples = 1;            // of the framebuffer beginView bound
  bool depthOnly = false;           // colour writes are off (see drawOpaqueAtCentres)
  // Where a ray-cast sphere's under pass (drawImpostor) can change a pixel:
  // in a view drawn whole, its tiles drawn in samples; over a retained
  // layer, the layer's edge tiles and the tiles of moving meshes drawn in
  // samples; and the rectangles of the spheres drawn before it in the
  // frame. Everywhere when set.
  bool underEverywhere = true;
  std::vector<PixelRect> underRects;
  std::vector<PixelRect> parts, underParts;  // drawImpostor's scratch
  // A ray-cast sphere's pixels: one pixel of its coverage ramp lies outside
  // the silhouette, one more for rounding; drawn in bands of 16 rows (see
  // sphereBands; narrower bands fit closer, but each is a draw).
  static constexpr float kImpostorMarginPx = 2.0f;
  static constexpr int kImpostorBandRows = 16;
  std::vector<PixelRect> layerEdgeRects;  // tiles where the layer's opaque meshes cover pixels in part
  GLuint sceneFbo = 0, sceneColor = 0, sceneDepth = 0;
  GLuint scenePacked = 0;  // sceneColor viewed as R32UI: one packed RGBA8 word per pixel
  int fbWidth = 0, fbHeight = 0, fbSamples = 0;

  struct CachedMesh {
    std::shared_ptr<const MeshData> keepAlive;
    GpuMesh gpu;
    bool used = false;  // by the current frame; unused entries are evicted after it
    std::optional<MeshEdges> edges;  // made on first use (see sampleTiles)
  };
  std::map<const MeshData*, CachedMesh> meshes;
  struct CachedTexture {
    std::shared_ptr<const TextureImage> keepAlive;
    GLuint id = 0;
  };
  std::map<const TextureImage*, CachedTexture> textures;
  struct CachedFont {
    std::unique_ptr<FontAtlas> atlas;
    GLuint id = 0;
  };
  std::map<std::pair<int, bool>, CachedFont> fonts;
  std::shared_ptr<MeshData> cylinder = unitCylinder(24), cone = unitCone(32);

  explicit Impl(const ShaderLibrary& lib)
      : library(lib),
        shadow(lib, "shadow.vert", "shadow.frag"),
        shadowSphere(lib, "impostor.vert", "shadow_sphere.frag"),
        line(lib, "line.vert", "line.frag", "line.geom"),
        text(lib, "text.vert", "text.frag"),
        depthProgram(lib, "mesh.vert", "depth.frag", {}, "#define LIT 0\n"),
        sphereReplay(lib, "sphere_replay.vert", "sphere_replay.frag") {
    glGenVertexArrays(1, &emptyVao);
    glGenVertexArrays(1, &streamVao);
    glGenBuffers(1, &streamVbo);
    glBindVertexArray(streamVao);
    glBindBuffer(GL_ARRAY_BUFFER, streamVbo);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(glm::vec3), nullptr);
    glGenVertexArrays(1, &textVao);
    glGenBuffers(1, &textVbo);
    glBindVertexArray(textVao);
    glBindBuffer(GL_ARRAY_BUFFER, textVbo);
    glEnableVertexAttribArray(0);
    glVertexAttribPointer(0, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), nullptr);
    glEnableVertexAttribArray(1);
    glVertexAttribPointer(1, 2, GL_FLOAT, GL_FALSE, 4 * sizeof(float), reinterpret_cast<void*>(2 * sizeof(float)));
    glBindVertexArray(0);
  }

  ~Impl() {
    for (auto& [k, m] : meshes) release(m.gpu);
    for (auto& [k, t] : textures) glDeleteTextures(1, &t.id);
    for (auto& [k, f] : fonts) glDeleteTextures(1, &f.id);
    releaseFramebuffers();
    releaseSnapshot();
    for (ShadowMap& m : shadowMaps) {
      glDeleteFramebuffers(1, &m.fbo);
      glDeleteTextures(1, &m.texture);
    }
    glDeleteBuffers(1, &streamVbo);
    glDeleteBuffers(1, &textVbo);
    glDeleteVertexArrays(1, &streamVao);
    glDeleteVertexArrays(1, &textVao);
    glDeleteVertexArrays(1, &emptyVao);
    for (auto& [key, p] : meshPrograms) p.release();
    for (Program* p : {&shadow, &shadowSphere, &line, &text, &depthProgram, &sphereReplay}) p->release();
    releaseSphereCaptures();
    if (resolver) resolver->release();
  }

  void releaseFramebuffers() {
    GLuint fbos[] = {sceneFbo, opaqueFbo, resolveFbo};
    GLuint rbs[] = {sceneDepth, opaqueDepth};
    glDeleteFramebuffers(3, fbos);
    glDeleteRenderbuffers(2, rbs);
    GLuint textures[] = {scenePacked, sceneColor, opaquePacked, opaqueColor};
    glDeleteTextures(4, textures);
    sceneFbo = sceneDepth = sceneColor = scenePacked = 0;
    opaqueFbo = opaqueColor = opaquePacked = opaqueDepth = resolveFbo = 0;
  }

  void ensureFramebuffers(int w, int h, int samples) {
    if (w == fbWidth && h == fbHeight && samples == fbSamples) return;
    releaseFramebuffers();
    releaseSphereCaptures();
    auto checkComplete = [&] {
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw runtimeError({}, "OpenGL could not create a {}x{} framebuffer with {} samples (out of memory?)", w, h,
                           samples);
    };
    // The scene has one sample; its colour is a texture so that the resolve
    // pass can write it as packed words.
    glGenTextures(1, &sceneColor);
    glBindTexture(GL_TEXTURE_2D, sceneColor);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, w, h);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenTextures(1, &scenePacked);
    glTextureView(scenePacked, GL_TEXTURE_2D, sceneColor, GL_R32UI, 0, 1, 0, 1);
    // An integer texture with the default LINEAR filter is incomplete and
    // texelFetch returns 0.
    glBindTexture(GL_TEXTURE_2D, scenePacked);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    glGenRenderbuffers(1, &sceneDepth);
    glBindRenderbuffer(GL_RENDERBUFFER, sceneDepth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, w, h);
    glGenFramebuffers(1, &sceneFbo);
    glBindFramebuffer(GL_FRAMEBUFFER, sceneFbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, sceneColor, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, sceneDepth);
    checkComplete();
    if (samples > 1) {
      // A texture, viewed as packed words by the resolve pass.
      glGenTextures(1, &opaqueColor);
      glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, opaqueColor);
      glTexStorage2DMultisample(GL_TEXTURE_2D_MULTISAMPLE, samples, GL_RGBA8, w, h, GL_TRUE);
      glGenTextures(1, &opaquePacked);
      glTextureView(opaquePacked, GL_TEXTURE_2D_MULTISAMPLE, opaqueColor, GL_R32UI, 0, 1, 0, 1);
      glGenRenderbuffers(1, &opaqueDepth);
      glBindRenderbuffer(GL_RENDERBUFFER, opaqueDepth);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, samples, GL_DEPTH_COMPONENT24, w, h);
      glGenFramebuffers(1, &opaqueFbo);
      glBindFramebuffer(GL_FRAMEBUFFER, opaqueFbo);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D_MULTISAMPLE, opaqueColor, 0);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, opaqueDepth);
      checkComplete();
      // The scene's colour as packed words, written by the resolve pass.
      glGenFramebuffers(1, &resolveFbo);
      glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, scenePacked, 0);
      checkComplete();
    }
    fbWidth = w;
    fbHeight = h;
    if (samples != fbSamples && resolver) {
      resolver->release();
      resolver.reset();
    }
    fbSamples = samples;
  }

  // The opaque meshes' samples of `r` (image pixels) averaged into the
  // scene's colour, over what they drew there at one sample. Not their
  // depth: a resolve keeps one sample's, off the pixel centre, where a step
  // at one sample tests its own depth (a small ball would sink into the
  // surface it touches); the scene keeps the depth of the one-sample draw.
  void resolveOpaque(const DrawList& list, const PixelRect& r) {
    if (opaqueFbo == 0) return;
    glBindFramebuffer(GL_FRAMEBUFFER, resolveFbo);
    glViewport(0, 0, list.width, list.height);
    glEnable(GL_SCISSOR_TEST);
    glScissor(r.x0, list.height - r.y1, r.x1 - r.x0, r.y1 - r.y0);
    glDisable(GL_DEPTH_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D_MULTISAMPLE, opaquePacked);
    if (!resolver)
      resolver.emplace(library, "fullscreen.vert", "resolve.frag", "", fmt::format("#define SAMPLES {}\n", fbSamples));
    resolver->use();
    resolver->set("samples", 0);
    glBindVertexArray(emptyVao);
    glDrawArrays(GL_TRIANGLES, 0, 3);
    glEnable(GL_DEPTH_TEST);
  }

  const GpuMesh& gpuMesh(const std::shared_ptr<const MeshData>& m) {
    auto it = meshes.find(m.get());
    if (it == meshes.end()) it = meshes.emplace(m.get(), CachedMesh{m, upload(*m), false, std::nullopt}).first;
    it->second.used = true;
    return it->second.gpu;
  }

  const MeshEdges& meshEdges(const std::shared_ptr<const MeshData>& m) {
    gpuMesh(m);
    CachedMesh& cached = meshes.at(m.get());
    if (!cached.edges) cached.edges = meshEdgesOf(*m);
    return *cached.edges;
  }

  GLuint gpuTexture(const std::shared_ptr<const TextureImage>& t) {
    auto it = textures.find(t.get());
    if (it != textures.end()) return it->second.id;
    GLuint id = 0;
    glGenTextures(1, &id);
    glBindTexture(GL_TEXTURE_2D, id);
    const int levels = 1 + static_cast<int>(std::floor(std::log2(std::max(t->width, t->height))));
    glTexStorage2D(GL_TEXTURE_2D, levels, GL_SRGB8_ALPHA8, t->width, t->height);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    // Row 0 of the image is v = 0 (the +z pole of an equirectangular map).
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, t->width, t->height, GL_RGBA, GL_UNSIGNED_BYTE, t->rgba.data());
    glGenerateMipmap(GL_TEXTURE_2D);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR_MIPMAP_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    textures.emplace(t.get(), CachedTexture{t, id});
    return id;
  }

  CachedFont& font(float sizePx, bool bold) {
    const auto key = std::make_pair(static_cast<int>(std::lround(sizePx)), bold);
    auto it = fonts.find(key);
    if (it != fonts.end()) return it->second;
    CachedFont f;
    StageLog::instance().record("font");
    f.atlas = std::make_unique<FontAtlas>(defaultFontFile(bold), static_cast<float>(key.first));
    glGenTextures(1, &f.id);
    glBindTexture(GL_TEXTURE_2D, f.id);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, f.atlas->atlasWidth(), f.atlas->atlasHeight(), 0, GL_RED, GL_UNSIGNED_BYTE,
                 f.atlas->coverage().data());
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    return fonts.emplace(key, std::move(f)).first->second;
  }

  // Everything a view draws as a lit mesh: its MeshItems plus its arrows.
  struct Drawable {
    std::shared_ptr<const MeshData> mesh;
    glm::mat4 worldFromModel;
    const Material* material;
    bool dynamic = false;  // see MeshItem::dynamic
    bool sphere = false;   // see MeshItem::sphere
    // An arrow's cylinder or cone (opaque, plain, culled, its facets a
    // pixel or two wide): lit per vertex, see mesh.vert's VERTEX_LIT.
    bool litPerVertex = false;
  };

  std::vector<Drawable> drawablesOf(const DrawList& list, int view, std::vector<Material>& arrowMaterials) {
    std::vector<Drawable> out;
    for (const MeshItem& m : list.meshes)
      if (m.view == view && m.mesh) out.push_back({m.mesh, m.worldFromModel, &m.material, m.dynamic, m.sphere});
    for (const ArrowItem& a : list.arrows) {
      if (a.view != view) continue;
      const float len = glm::length(a.tip - a.origin);
      if (len <= 0.0f) continue;
      const float headLength = std::min(len * 0.35f, a.shaftRadius * 6.0f);
      const glm::vec3 dir = (a.tip - a.origin) / len;
      const glm::vec3 neck = a.tip - dir * headLength;
      Material& mat = arrowMaterials.emplace_back();
      mat.color = a.color;
      mat.specular = 0.35f;
      mat.shininess = 64.0f;
      out.push_back({cylinder, alongSegment(a.origin, neck, a.shaftRadius), &mat, a.dynamic, false, true});
      out.push_back({cone, alongSegment(neck, a.tip, a.shaftRadius * 2.6f), &mat, a.dynamic, false, true});
    }
    // Every mesh the list names stays cached, also one a retained frame does
    // not draw (evicting it would re-upload it at the next layer build).
    for (const Drawable& d : out) gpuMesh(d.mesh);
    return out;
  }

  // The n-th shadow map, made on first use.
  const ShadowMap& shadowMap(std::size_t n) {
    while (shadowMaps.size() <= n) {
      ShadowMap m;
      // Depth texture with hardware comparison: sampler2DShadow does the test.
      glGenTextures(1, &m.texture);
      glBindTexture(GL_TEXTURE_2D, m.texture);
      glTexStorage2D(GL_TEXTURE_2D, 1, GL_DEPTH_COMPONENT24, kShadowMapSize, kShadowMapSize);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
      glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
      glGenFramebuffers(1, &m.fbo);
      glBindFramebuffer(GL_FRAMEBUFFER, m.fbo);
      glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, m.texture, 0);
      glDrawBuffer(GL_NONE);
      glReadBuffer(GL_NONE);
      shadowMaps.push_back(m);
    }
    return shadowMaps[n];
  }

  struct ShadowSetup {
    glm::mat4 lightClipFromWorld{1.0f};
    float filterRadius = 0.0f;  // PCF radius in map uv
  };

  // Renders the view's shadow map. The light's box (shadowCenter,
  // shadowRadius) fixes the depth range; across the light it is narrowed to
  // the casters' bounding spheres plus the filter radius, because every
  // pixel of a receiver inside the box pays for the filter, and a tighter
  // box is a finer map.
  ShadowSetup shadowPass(const View& v, const std::vector<Drawable>& items, const ShadowMap& map) {
    const Light& l = v.light;
    const glm::vec3 toward = glm::normalize(l.towardLight);
    const glm::vec3 up = std::abs(toward.z) < 0.95f ? glm::vec3(0, 0, 1) : glm::vec3(1, 0, 0);
    const float r = l.shadowRadius;
    const glm::mat4 lightViewFromWorld = glm::lookAt(l.shadowCenter + toward * (2.0f * r), l.shadowCenter, up);
    glm::vec2 lo(r), hi(-r);
    for (const Drawable& d : items) {
      if (!d.material->castsShadow || d.material->opacity < 0.5f) continue;
      const glm::vec4 b = gpuMesh(d.mesh).bound;
      const glm::mat3 linear(d.worldFromModel);
      const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
      const glm::vec3 c(lightViewFromWorld * d.worldFromModel * glm::vec4(glm::vec3(b), 1.0f));
      lo = glm::min(lo, glm::vec2(c) - b.w * scale);
      hi = glm::max(hi, glm::vec2(c) + b.w * scale);
    }
    glm::vec2 centre(0.0f);
    float half = r;
    if (lo.x <= hi.x) {  // some caster: a square around them, inside the light's box
      lo = glm::max(lo, glm::vec2(-r));
      hi = glm::min(hi, glm::vec2(r));
      centre = 0.5f * (lo + hi);
      half = std::min(r, 0.5f * std::max(hi.x - lo.x, hi.y - lo.y) + l.shadowSoftness * 1.1f);
    }
    // Depth: from 2r in front of the centre to 6r behind it. A receiver past
    // the far plane is lit, and on a wall lit from above the shadow lands
    // well behind the ball along the light (the floor: about R behind).
    ShadowSetup setup;
    // The map as a view, for a sphere's bands (see drawShadowSphere).
    View mapView;
    mapView.width = mapView.height = kShadowMapSize;
    mapView.camera.viewFromWorld = lightViewFromWorld;
    mapView.camera.clipFromView =
        glm::ortho(centre.x - half, centre.x + half, centre.y - half, centre.y + half, 0.01f * r, 8.0f * r);
    const glm::mat4 lightClipFromWorld = mapView.camera.clipFromView * lightViewFromWorld;
    setup.lightClipFromWorld = lightClipFromWorld;
    // The filter radius in map uv: the light's softness (world units), and
    // at least 1.5 texels so that the edge is always filtered.
    setup.filterRadius = std::max(l.shadowSoftness / (2.0f * half), 1.5f / float(kShadowMapSize));
    glBindFramebuffer(GL_FRAMEBUFFER, map.fbo);
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, kShadowMapSize, kShadowMapSize);
    glClear(GL_DEPTH_BUFFER_BIT);
    glEnable(GL_DEPTH_TEST);
    glDepthMask(GL_TRUE);
    glDisable(GL_BLEND);
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(1.5f, 2.0f);
    for (const Drawable& d : items) {
      if (!d.material->castsShadow || d.material->opacity < 0.5f) continue;
      // A sphere that also took a shadow would need the triangles' offset.
      if (d.sphere && !d.material->receivesShadow) {
        drawShadowSphere(d, mapView, lightClipFromWorld);
        continue;
      }
      shadow.use();
      // Closed casters draw only the faces towards the light: casters take
      // no shadow, so their far sides' depths are never needed.
      if (d.material->cull == Cull::Back) {
        glEnable(GL_CULL_FACE);
        glCullFace(GL_BACK);
      } else {
        glDisable(GL_CULL_FACE);
      }
      shadow.set("lightClipFromModel", lightClipFromWorld * d.worldFromModel);
      const GpuMesh& g = gpuMesh(d.mesh);
      glBindVertexArray(g.vao);
      glDrawElements(GL_TRIANGLES, g.indexCount, GL_UNSIGNED_INT, nullptr);
    }
    glDisable(GL_POLYGON_OFFSET_FILL);
    return setup;
  }

  // A sphere (MeshItem::sphere) into the bound shadow map `map`, ray-cast
  // (see shadow_sphere.frag) in the bands of its square that its circle
  // reaches, one scissored triangle of impostor.vert each (see
  // drawImpostorParts). It takes no shadow (shadowPass sees to it), so the
  // polygon offset that triangles get (against a receiver's shadow on its
  // own faces) is not needed where gl_FragDepth replaces it.
  void drawShadowSphere(const Drawable& d, const View& map, const glm::mat4& lightClipFromWorld) {
    const glm::vec3 centre(d.worldFromModel[3]);
    const float radius = glm::length(glm::vec3(d.worldFromModel[0]));
    const std::optional<PixelRect> box = sphereBounds(map, centre, radius, kImpostorMarginPx);
    if (!box || box->empty()) return;
    // The light's clip space is a box, square across the light: the
    // sphere's radius across it and along it, in its coordinates (the rows
    // of the linear part hold each axis's scale).
    const glm::vec3 c(lightClipFromWorld * glm::vec4(centre, 1.0f));
    auto scaleOfRow = [&](int row) {
      return glm::length(glm::vec3(lightClipFromWorld[0][row], lightClipFromWorld[1][row], lightClipFromWorld[2][row]));
    };
    shadowSphere.use();
    shadowSphere.set("ndcDepth", 0.0f);
    shadowSphere.set("mapSize", glm::vec2(float(kShadowMapSize)));
    shadowSphere.set("sphereNdc", glm::vec4(c, radius * scaleOfRow(0)));
    shadowSphere.set("depthRadius", radius * scaleOfRow(2));
    glDisable(GL_CULL_FACE);
    glBindVertexArray(emptyVao);
    glEnable(GL_SCISSOR_TEST);
    for (const PixelRect& band : sphereBands(map, *box, centre, radius, kImpostorMarginPx, kImpostorBandRows)) {
      glScissor(band.x0, kShadowMapSize - band.y1, band.x1 - band.x0, band.y1 - band.y0);
      shadowSphere.set("ndcRect", ndcRectOf(map, band));
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glDisable(GL_SCISSOR_TEST);
  }

  // `impostor`: 0 the mesh's triangles, 1 a ray-cast sphere, 2 the same
  // under what is drawn (see drawImpostor); see mesh.frag.
  // `vertexLit`: lit per vertex with the highlight (an arrow's own meshes).
  Program& meshProgram(int pattern, bool shadowed, bool lit, bool specular, int impostor = 0, bool vertexLit = false,
                       bool capture = false) {
    const int key = (capture ? 256 : 0) + (vertexLit ? 128 : 0) + impostor * 32 + pattern * 8 + (shadowed ? 4 : 0) +
                    (lit ? 2 : 0) + (specular ? 1 : 0);
    auto it = meshPrograms.find(key);
    if (it == meshPrograms.end()) {
      const std::string defines = fmt::format(
          "#define PATTERN {}\n#define SHADOWED {}\n#define LIT {}\n#define SPECULAR {}\n#define IMPOSTOR {}\n"
          "#define VERTEX_LIT {}\n#define CAPTURE {}\n",
          pattern, shadowed ? 1 : 0, lit ? 1 : 0, specular ? 1 : 0, impostor, vertexLit ? 1 : 0, capture ? 1 : 0);
      it = meshPrograms
               .emplace(key, Program(library, impostor != 0 ? "impostor.vert" : "mesh.vert", "mesh.frag", {}, defines))
               .first;
    }
    return it->second;
  }

  // Shadow receivers (the surfaces) pay for the shadow filter only inside
  // the shadow box: llvmpipe runs both sides of every branch, even on
  // uniforms, so the split is made with two draws instead. The whole mesh is
  // drawn without the filter with the other opaque items; then, after every
  // opaque item (the ball included), the re-shade: the mesh clipped to the
  // box, with the filter, pulled forward by a polygon offset so that it
  // passes the depth test over its own unfiltered pixels. A retained layer
  // holds the unfiltered surface, and a frame re-shades only the box.
  //
  // The scene holds the surface resolved from its samples: at its edges,
  // premultiplied by its coverage (alpha). The re-shade keeps that
  // coverage: its colour is weighted by the pixel's alpha, which stays.
  void drawReshade(const Drawable& d) {
    glEnable(GL_POLYGON_OFFSET_FILL);
    glPolygonOffset(-1.0f, -4.0f);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_DST_ALPHA, GL_ZERO, GL_ZERO, GL_ONE);
    drawMesh(d, true, d.material->cull, true);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glDisable(GL_BLEND);
    glDisable(GL_POLYGON_OFFSET_FILL);
  }

  // Whether `d` is drawn as a ray-cast sphere: at one sample (with more, the
  // samples antialias its triangles' edges), whole (no cut-away, not the
  // re-shade's clipped part), in a view whose camera sphereBounds
  // understands; its screen rectangle if so.
  std::optional<PixelRect> impostorRect(const Drawable& d, bool clipToShadowBox) const {
    const Material& m = *d.material;
    if (!d.sphere || targetSamples != 1 || clipToShadowBox || viewUniforms.view == nullptr ||
        m.cutPlane != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f))
      return std::nullopt;
    return sphereBounds(*viewUniforms.view, glm::vec3(d.worldFromModel[3]), glm::length(glm::vec3(d.worldFromModel[0])),
                        kImpostorMarginPx);
  }

  // The uniforms of a mesh program (each program ignores those it lacks).
  void setMeshUniforms(Program& mesh, const Drawable& d, bool clipToShadowBox) {
    const Material& m = *d.material;
    const MeshViewUniforms& u = viewUniforms;
    mesh.set("clipFromWorld", u.clipFromWorld);
    mesh.set("lightClipFromWorld", u.lightClipFromWorld);
    mesh.set("towardLight", u.towardLight);
    mesh.set("lightColor", u.lightColor);
    mesh.set("ambient", u.ambient);
    mesh.set("cameraPosition", u.cameraPosition);
    mesh.set("albedoTexture", 0);
    mesh.set("shadowMap", 1);
    mesh.set("shadowFilterRadius", u.shadowFilterRadius);
    mesh.set("cutPlane", m.cutPlane);
    mesh.set("twoSided", m.cull == Cull::None ? 1 : 0);
    mesh.set("backFacesShown", m.cull == Cull::Front ? 1 : 0);
    mesh.set("worldFromModel", d.worldFromModel);
    mesh.set("normalWorldFromModel", glm::inverseTranspose(glm::mat3(d.worldFromModel)));
    mesh.set("color", m.color);
    mesh.set("color2", m.color2);
    mesh.set("opacity", m.opacity);
    mesh.set("specular", m.specular);
    mesh.set("shininess", m.shininess);
    mesh.set("patternScale", m.patternScale);
    mesh.set("clipToShadowBox", clipToShadowBox ? 1 : 0);
  }

  // A ray-cast sphere (mesh.frag with IMPOSTOR): the bands of its screen
  // rectangle that it reaches, its silhouette's coverage blended over what
  // is behind, depth per pixel.
  void drawImpostor(const Drawable& d, Program& mesh, const PixelRect& rect, int pattern, bool shadowed) {
    const View& v = *viewUniforms.view;
    const Material& m = *d.material;
    const bool opaque = m.opacity >= 1.0f;
    // Only the rectangle's bands that the silhouette reaches (its corners,
    // a fifth of it, are all outside), and over a retained layer only their
    // parts inside the rectangles being redrawn: an island's scissor box
    // reaches pixels outside them, which are neither composited nor read
    // back, and a large sphere (the Bloch sphere's glass) would be shaded
    // over all of them. Each pixel is shaded as the whole rectangle shades
    // it (the shader depends on the pixel's position alone).
    const float radius = glm::length(glm::vec3(d.worldFromModel[0]));
    const std::vector<PixelRect> bands =
        sphereBands(v, rect, glm::vec3(d.worldFromModel[3]), radius, kImpostorMarginPx, kImpostorBandRows);
    parts.clear();
    for (const PixelRect& band : bands) {
      if (drawClips == nullptr) {
        parts.push_back(band);
        continue;
      }
      for (const PixelRect& clip : *drawClips)
        if (const PixelRect p = intersect(band, clip); !p.empty()) parts.push_back(p);
    }
    if (parts.empty()) return;
    const glm::mat4 worldFromClip = glm::inverse(viewUniforms.clipFromWorld);
    const glm::vec4 viewport(float(v.x), float(fbHeight - v.y - v.height), float(v.width), float(v.height));
    // Opaque meshes are drawn without blending (drawOpaque): on for this one.
    glEnable(GL_BLEND);
    glDisable(GL_CULL_FACE);
    glBindVertexArray(emptyVao);
    // Over a retained layer, a translucent sphere that stays there (the
    // Bloch sphere's glass, shaded again in every frame's rectangles over
    // it) is replayed from its capture.
    if (!opaque && !depthOnly && !shadowed && drawClips != nullptr) {
      const SphereCapture& capture = sphereCaptureOf(d, rect, pattern, worldFromClip, viewport);
      glBindTextureUnit(2, capture.color);
      glBindTextureUnit(3, capture.depth);
      sphereReplay.use();
      sphereReplay.set("capturedColor", 2);
      sphereReplay.set("capturedDepth", 3);
      sphereReplay.set("captureOrigin", glm::ivec2(capture.originX, capture.originY));
      sphereReplay.set("viewportRect", viewport);
      replayCorners.clear();
      for (const PixelRect& p : parts) {
        const float x0 = float(p.x0), x1 = float(p.x1), y0 = float(fbHeight - p.y1), y1 = float(fbHeight - p.y0);
        for (const glm::vec2 corner : {glm::vec2(x0, y0), glm::vec2(x1, y0), glm::vec2(x1, y1), glm::vec2(x0, y0),
                                       glm::vec2(x1, y1), glm::vec2(x0, y1)})
          replayCorners.emplace_back(corner, 0.0f);
      }
      glBindVertexArray(streamVao);
      glBindBuffer(GL_ARRAY_BUFFER, streamVbo);
      glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(replayCorners.size() * sizeof(glm::vec3)),
                   replayCorners.data(), GL_STREAM_DRAW);
      glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(replayCorners.size()));
      ++stats.sphereReplays;
      return;
    }
    const bool behindEdges = opaque && !depthOnly;
    if (behindEdges) {
      // Behind what a pixel's centre shows, where that covers the pixel only
      // in part (an edge of a surface, resolved from its samples over
      // transparent black: alpha < 1), the sphere shows through the rest:
      // added under it (premultiplied, weighted by 1 − alpha), as the
      // samples of a whole multisampled frame would have shown it. Drawn
      // first, before the sphere's own edges are there to be drawn under.
      // Its rectangle lies at the sphere's far depth (IMPOSTOR 2 gives no
      // depth of its own): llvmpipe rejects the pixels where the scene is
      // behind the whole sphere before it shades them. Where the scene lies
      // within the sphere's depth, the pass adds it under what is there
      // (alpha 1 away from edges: nothing changes), and the sphere, in
      // front there, is drawn over it next. Over a retained layer only
      // where such pixels can be (see underRects): elsewhere alpha is 1 or
      // the depth is the clear value, and the pass would change nothing.
      Program& under = meshProgram(pattern, false, m.lit, m.specular > 0.0f, 2);
      under.use();
      setMeshUniforms(under, d, false);
      under.set("worldFromClip", worldFromClip);
      under.set("viewportRect", viewport);
      const glm::vec4 centre = v.camera.viewFromWorld * d.worldFromModel[3];
      const glm::vec4 far = v.camera.clipFromView * (centre - glm::vec4(0.0f, 0.0f, radius, 0.0f));
      under.set("ndcDepth", std::clamp(far.z / far.w, -1.0f, 1.0f));
      glDepthFunc(GL_GREATER);
      glDepthMask(GL_FALSE);
      glBlendFuncSeparate(GL_ONE_MINUS_DST_ALPHA, GL_ONE, GL_ONE_MINUS_DST_ALPHA, GL_ONE);
      if (underEverywhere) {
        drawImpostorParts(under, v, parts);
      } else {
        for (const PixelRect& part : underRects) {
          clippedParts(parts, part, underParts);
          drawImpostorParts(under, v, underParts);
        }
      }
      glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
      glDepthMask(GL_TRUE);
      glDepthFunc(GL_LEQUAL);
      mesh.use();
    }
    mesh.set("worldFromClip", worldFromClip);
    mesh.set("viewportRect", viewport);
    mesh.set("ndcDepth", 0.0f);
    drawImpostorParts(mesh, v, parts);
    if (behindEdges && !underEverywhere) underRects.push_back(rect);  // its edges, for a sphere drawn after it
    if (opaque) glDisable(GL_BLEND);
  }

  // A translucent ray-cast sphere's fragments depend on the pixel's
  // position and on uniforms alone (see mesh.frag's castSphere): captured
  // once over its screen rectangle (the colour mesh.frag gives each pixel,
  // before blending, and its depth), they are replayed in later frames
  // (sphere_replay.frag) with the same values, so blending and the depth
  // test give the same bytes. A frame over the layer then fetches two
  // texels a pixel instead of casting the ray and lighting it.
  // What a sphere's fragments depend on (the unshadowed program reads no more).
  struct SphereInputs {
    glm::mat4 worldFromModel, clipFromWorld;
    glm::vec3 towardLight, lightColor, cameraPosition;
    float ambient;
    glm::vec4 viewport;
    PixelRect rect;
    Material material;
    bool operator==(const SphereInputs&) const = default;
  };
  struct SphereCapture {
    SphereInputs inputs;
    GLuint fbo = 0, color = 0, depth = 0;
    int originX = 0, originY = 0;  // the window pixel (GL, from the bottom) of texel (0, 0)
  };
  std::deque<SphereCapture> sphereCaptures;  // the newest last
  std::vector<glm::vec3> replayCorners;      // drawImpostor's scratch
  static constexpr std::size_t kSphereCapturesKept = 4;

  static void releaseCapture(const SphereCapture& c) {
    glDeleteFramebuffers(1, &c.fbo);
    const GLuint textures[] = {c.color, c.depth};
    glDeleteTextures(2, textures);
  }

  void releaseSphereCaptures() {
    for (const SphereCapture& c : sphereCaptures) releaseCapture(c);
    sphereCaptures.clear();
  }

  // The capture of the unshadowed translucent sphere `d` drawn in `rect`
  // with the uniforms in force, made now if none matches. Drawn into its
  // own framebuffer, as drawImpostor draws it, with texel (0, 0) at an even
  // window pixel: the derivatives pair the pixels of the same 2×2 quads.
  // (Binding that framebuffer makes llvmpipe run the scene binned so far:
  // once per layer.)
  const SphereCapture& sphereCaptureOf(const Drawable& d, const PixelRect& rect, int pattern,
                                       const glm::mat4& worldFromClip, const glm::vec4& viewport) {
    const MeshViewUniforms& u = viewUniforms;
    SphereInputs inputs{d.worldFromModel, u.clipFromWorld, u.towardLight, u.lightColor, u.cameraPosition,
                        u.ambient,        viewport,        rect,          *d.material};
    for (const SphereCapture& c : sphereCaptures)
      if (c.inputs == inputs) return c;
    if (sphereCaptures.size() == kSphereCapturesKept) {
      releaseCapture(sphereCaptures.front());
      sphereCaptures.pop_front();
    }
    SphereCapture& c = sphereCaptures.emplace_back(SphereCapture{std::move(inputs)});
    c.originX = rect.x0 & ~1;
    c.originY = (fbHeight - rect.y1) & ~1;
    const int width = rect.x1 - c.originX, height = fbHeight - rect.y0 - c.originY;
    // Made without binding: the active unit holds the sphere's own texture.
    for (const auto& [texture, format] : {std::pair{&c.color, GL_RGBA32F}, std::pair{&c.depth, GL_R32F}}) {
      glCreateTextures(GL_TEXTURE_2D, 1, texture);
      glTextureStorage2D(*texture, 1, format, width, height);
      glTextureParameteri(*texture, GL_TEXTURE_MIN_FILTER, GL_NEAREST);
      glTextureParameteri(*texture, GL_TEXTURE_MAG_FILTER, GL_NEAREST);
    }
    GLint drawFbo = 0, viewportBox[4], scissorBox[4];
    glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFbo);
    glGetIntegerv(GL_VIEWPORT, viewportBox);
    glGetIntegerv(GL_SCISSOR_BOX, scissorBox);
    const bool scissored = glIsEnabled(GL_SCISSOR_TEST), blended = glIsEnabled(GL_BLEND),
               depthTested = glIsEnabled(GL_DEPTH_TEST);
    glGenFramebuffers(1, &c.fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, c.fbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, c.color, 0);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT1, GL_TEXTURE_2D, c.depth, 0);
    const GLenum buffers[] = {GL_COLOR_ATTACHMENT0, GL_COLOR_ATTACHMENT1};
    glDrawBuffers(2, buffers);
    if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
      throw runtimeError({}, "OpenGL could not create a {}x{} float framebuffer (out of memory?)", width, height);
    glDisable(GL_SCISSOR_TEST);
    glDisable(GL_BLEND);
    glDisable(GL_DEPTH_TEST);
    const float none[4] = {0.0f, 0.0f, 0.0f, 0.0f}, noDepth[4] = {-1.0f, 0.0f, 0.0f, 0.0f};
    glClearBufferfv(GL_COLOR, 0, none);
    glClearBufferfv(GL_COLOR, 1, noDepth);
    const glm::vec4 shifted = viewport - glm::vec4(float(c.originX), float(c.originY), 0.0f, 0.0f);
    glViewport(int(shifted.x), int(shifted.y), int(shifted.z), int(shifted.w));
    const Material& m = *d.material;
    Program& program = meshProgram(pattern, false, m.lit, m.specular > 0.0f, 1, false, true);
    program.use();
    setMeshUniforms(program, d, false);
    program.set("worldFromClip", worldFromClip);
    program.set("viewportRect", shifted);
    program.set("ndcDepth", 0.0f);
    const View& v = *u.view;
    glEnable(GL_SCISSOR_TEST);
    for (const PixelRect& band :
         sphereBands(v, rect, glm::vec3(d.worldFromModel[3]), glm::length(glm::vec3(d.worldFromModel[0])),
                     kImpostorMarginPx, kImpostorBandRows)) {
      glScissor(band.x0 - c.originX, fbHeight - band.y1 - c.originY, band.x1 - band.x0, band.y1 - band.y0);
      program.set("ndcRect", ndcRectOf(v, band));
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    ++stats.sphereCaptures;
    glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(drawFbo));
    glViewport(viewportBox[0], viewportBox[1], viewportBox[2], viewportBox[3]);
    glScissor(scissorBox[0], scissorBox[1], scissorBox[2], scissorBox[3]);
    if (!scissored) glDisable(GL_SCISSOR_TEST);
    if (blended) glEnable(GL_BLEND);
    if (depthTested) glEnable(GL_DEPTH_TEST);
    return c;
  }

  // The parts of `r` outside `hole`, appended to `out` (disjoint, at most four).
  static void outside(const PixelRect& r, const PixelRect& hole, std::vector<PixelRect>& out) {
    const PixelRect h = intersect(r, hole);
    if (h.empty()) {
      out.push_back(r);
      return;
    }
    for (const PixelRect& p : {PixelRect{r.x0, r.y0, r.x1, h.y0}, PixelRect{r.x0, h.y1, r.x1, r.y1},
                               PixelRect{r.x0, h.y0, h.x0, h.y1}, PixelRect{h.x1, h.y0, r.x1, h.y1}})
      if (!p.empty()) out.push_back(p);
  }

  // The non-empty parts of `rects` inside `box`, into `out`.
  static void clippedParts(const std::vector<PixelRect>& rects, const PixelRect& box, std::vector<PixelRect>& out) {
    out.clear();
    for (const PixelRect& r : rects)
      if (const PixelRect p = intersect(r, box); !p.empty()) out.push_back(p);
  }

  // One triangle of impostor.vert per part (disjoint: blending draws each
  // pixel once), scissored to the part inside the scissor in force: a
  // rectangle's two triangles would both shade the pixel blocks along
  // their diagonal (llvmpipe shades a block that a triangle covers in part
  // whole, under a mask), and a band is little more than that diagonal.
  void drawImpostorParts(Program& program, const View& v, const std::vector<PixelRect>& rects) {
    GLint box[4] = {0, 0, fbWidth, fbHeight};
    const bool scissored = glIsEnabled(GL_SCISSOR_TEST) == GL_TRUE;
    if (scissored) glGetIntegerv(GL_SCISSOR_BOX, box);
    const PixelRect inForce{box[0], fbHeight - box[1] - box[3], box[0] + box[2], fbHeight - box[1]};
    glEnable(GL_SCISSOR_TEST);
    for (const PixelRect& r : rects) {
      const PixelRect part = intersect(r, inForce);
      if (part.empty()) continue;
      glScissor(part.x0, fbHeight - part.y1, part.x1 - part.x0, part.y1 - part.y0);
      program.set("ndcRect", ndcRectOf(v, part));
      glDrawArrays(GL_TRIANGLES, 0, 3);
    }
    glScissor(box[0], box[1], box[2], box[3]);
    if (!scissored) glDisable(GL_SCISSOR_TEST);
  }

  // Image pixels (top-left origin) to the view's normalized device coordinates.
  static glm::vec4 ndcRectOf(const View& v, const PixelRect& rect) {
    return glm::vec4(
        2.0f * float(rect.x0 - v.x) / float(v.width) - 1.0f, 1.0f - 2.0f * float(rect.y1 - v.y) / float(v.height),
        2.0f * float(rect.x1 - v.x) / float(v.width) - 1.0f, 1.0f - 2.0f * float(rect.y0 - v.y) / float(v.height));
  }

  void drawMesh(const Drawable& d, bool shadowOn, Cull cull, bool clipToShadowBox = false) {
    const Material& m = *d.material;
    int pattern = m.pattern == Pattern::Checker ? 1 : 0;
    if (m.pattern == Pattern::Texture && m.texture) {
      pattern = 2;
      glActiveTexture(GL_TEXTURE0);
      glBindTexture(GL_TEXTURE_2D, gpuTexture(m.texture));
    }
    const std::optional<PixelRect> impostor = impostorRect(d, clipToShadowBox);
    // Depth alone (drawOpaqueAtCentres) needs no shading; a ray-cast
    // sphere's depth comes from its fragment stage.
    Program& mesh = depthOnly && !impostor ? depthProgram
                                           : meshProgram(pattern, shadowOn && m.lit, m.lit, m.specular > 0.0f,
                                                         impostor ? 1 : 0, d.litPerVertex);
    mesh.use();
    setMeshUniforms(mesh, d, clipToShadowBox);
    if (impostor) {
      drawImpostor(d, mesh, *impostor, pattern, shadowOn && m.lit);
      return;
    }
    if (cull == Cull::None) {
      glDisable(GL_CULL_FACE);
    } else {
      glEnable(GL_CULL_FACE);
      glCullFace(cull == Cull::Back ? GL_BACK : GL_FRONT);
    }
    const GpuMesh& g = gpuMesh(d.mesh);
    glBindVertexArray(g.vao);
    if (drawClips == nullptr || clipView == nullptr || g.chunks.size() < 2) {
      glDrawElements(GL_TRIANGLES, g.indexCount, GL_UNSIGNED_INT, nullptr);
      return;
    }
    // Inside a retained frame's rectangles, only the runs of triangles whose
    // screen bounds reach one: llvmpipe transforms, sets up and bins every
    // triangle of a draw however much the scissor leaves of it (a surface's
    // thousands for its re-shade box, the Bloch glass's for the twin's
    // arrows). The runs left out cover no pixel of the rectangles, and the
    // rest are drawn in their order: the rectangles' bytes do not change.
    const glm::mat4 clipFromModel = viewUniforms.clipFromWorld * d.worldFromModel;
    keptParts.clear();
    for (const MeshChunk& c : g.chunks) {
      const std::array<glm::vec3, 8> corners = boxCorners(c.lo, c.hi);
      if (reachesAny(*drawClips, screenBounds(*clipView, clipFromModel, corners.data(), 8, 2.0f)))
        keptParts.add(c.firstIndex, c.firstIndex + c.indexCount);
    }
    // The runs go to GL in one call: a draw call costs llvmpipe more than a
    // run of triangles.
    runCounts.clear();
    runOffsets.clear();
    for (const RunsOfParts::Run& r : keptParts.runs()) {
      runCounts.push_back(static_cast<GLsizei>(r.end - r.begin));
      runOffsets.push_back(reinterpret_cast<const void*>(r.begin * sizeof(std::uint32_t)));
      stats.meshIndicesDrawn += static_cast<long long>(r.end - r.begin);
    }
    stats.meshIndicesInRects += g.indexCount;
    if (!runCounts.empty())
      glMultiDrawElements(GL_TRIANGLES, runCounts.data(), GL_UNSIGNED_INT, runOffsets.data(),
                          static_cast<GLsizei>(runCounts.size()));
  }
  RunsOfParts keptParts;
  std::vector<GLsizei> runCounts;
  std::vector<const void*> runOffsets;
  std::vector<GLint> lineFirsts;  // drawPolyline's runs

  // Over a retained layer only the dirty rectangles are read back (see
  // drawOverLayer), so a polyline draws only the runs of segments whose
  // screen bounds reach one: the geometry shader pays per segment, and the
  // static lines (the whole path, the Bloch grid) are long. Segments are
  // independent quads, drawn in the same order either way: the bytes of the
  // dirty pixels do not change.
  // The rectangles that a frame over the retained layer redraws, and their
  // view, while it draws an island of them (meshes too, see drawMesh).
  const std::vector<PixelRect>* drawClips = nullptr;
  const View* clipView = nullptr;
  static constexpr std::size_t kLineRun = 32;
  std::vector<glm::vec3> paddedPoints;  // a polyline's points with its ends repeated

  void drawPolyline(const PolylineItem& p, const glm::mat4& clipFromWorld, const View& v) {
    if (p.points.size() < 2) return;
    line.use();
    line.set("clipFromWorld", clipFromWorld);
    line.set("viewportOrigin", glm::vec2(v.x, fbHeight - v.y - v.height));  // GL counts rows from the bottom
    line.set("viewportSize", glm::vec2(v.width, v.height));
    line.set("widthPx", p.widthPx);
    line.set("depthBias", p.depthTested ? 0.0008f : 0.0f);
    line.set("lineColor", p.color);
    // Drawn with adjacency (each segment sees its neighbours, see line.frag):
    // the ends repeated, so point k is vertex k + 1 and the segments from
    // point a to point b are the strip's vertices a to b + 2.
    paddedPoints.clear();
    paddedPoints.push_back(p.points.front());
    paddedPoints.insert(paddedPoints.end(), p.points.begin(), p.points.end());
    paddedPoints.push_back(p.points.back());
    glBindVertexArray(streamVao);
    glBindBuffer(GL_ARRAY_BUFFER, streamVbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(paddedPoints.size() * sizeof(glm::vec3)), paddedPoints.data(),
                 GL_STREAM_DRAW);
    if (drawClips == nullptr) {
      glDrawArrays(GL_LINE_STRIP_ADJACENCY, 0, static_cast<GLsizei>(paddedPoints.size()));
      return;
    }
    // A segment draws only within half a width of its ends' span (a capsule).
    // A part is the points [first, last] of up to kLineRun segments; the
    // next part begins at its last point, so adjacent parts merge.
    const float margin = 0.7072f * p.widthPx + 2.0f;
    keptParts.clear();
    for (std::size_t first = 0; first + 1 < p.points.size(); first += kLineRun) {
      const std::size_t last = std::min(first + kLineRun, p.points.size() - 1);
      if (reachesAny(*drawClips, screenBounds(v, clipFromWorld, &p.points[first], last - first + 1, margin)))
        keptParts.add(first, last);
    }
    // The runs go to GL in one call, as a mesh's do.
    lineFirsts.clear();
    runCounts.clear();
    for (const RunsOfParts::Run& r : keptParts.runs()) {
      lineFirsts.push_back(static_cast<GLint>(r.begin));
      runCounts.push_back(static_cast<GLsizei>(r.end - r.begin + 3));
      stats.lineSegmentsDrawn += static_cast<long long>(r.end - r.begin);
    }
    if (!lineFirsts.empty())
      glMultiDrawArrays(GL_LINE_STRIP_ADJACENCY, lineFirsts.data(), runCounts.data(),
                        static_cast<GLsizei>(lineFirsts.size()));
    stats.lineSegmentsInRects += static_cast<long long>(p.points.size() - 1);
  }

  // Pixel-space quads (x0, y0, x1, y1, s0, t0, s1, t1) with the text program.
  void drawQuads(const std::vector<GlyphQuad>& quads, glm::vec2 viewportSize, const glm::vec4& color, GLuint atlas,
                 bool solid) {
    if (quads.empty()) return;
    std::vector<float> data;
    data.reserve(quads.size() * 24);
    for (const GlyphQuad& q : quads) {
      const float v[6][4] = {{q.x0, q.y0, q.s0, q.t0}, {q.x0, q.y1, q.s0, q.t1}, {q.x1, q.y1, q.s1, q.t1},
                             {q.x0, q.y0, q.s0, q.t0}, {q.x1, q.y1, q.s1, q.t1}, {q.x1, q.y0, q.s1, q.t0}};
      for (const auto& vert : v) data.insert(data.end(), vert, vert + 4);
    }
    text.use();
    text.set("viewportSize", viewportSize);
    text.set("textColor", color);
    text.set("solid", solid ? 1 : 0);
    text.set("glyphAtlas", 0);
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, atlas);
    glBindVertexArray(textVao);
    glBindBuffer(GL_ARRAY_BUFFER, textVbo);
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(data.size() * sizeof(float)), data.data(), GL_STREAM_DRAW);
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(quads.size() * 6));
  }

  // The label's glyph quads in the viewport's pixels (top-left origin) and
  // its font; null when a world anchor lies behind the camera.
  CachedFont* labelQuads(const LabelItem& label, glm::vec2 viewportSize, const glm::mat4* clipFromWorld,
                         std::vector<GlyphQuad>& quads) {
    glm::vec2 pen(label.anchor.x, label.anchor.y);
    if (label.worldAnchored && clipFromWorld != nullptr) {
      const glm::vec4 c = *clipFromWorld * glm::vec4(label.anchor, 1.0f);
      if (c.w <= 0.0f) return nullptr;
      pen = glm::vec2((c.x / c.w * 0.5f + 0.5f) * viewportSize.x, (0.5f - c.y / c.w * 0.5f) * viewportSize.y);
    }
    pen += label.offsetPx;
    CachedFont& f = font(label.sizePx, label.bold);
    const float width = f.atlas->layout(label.text, 0.0f, 0.0f, nullptr);
    if (label.align == Align::Center) pen.x -= 0.5f * width;
    if (label.align == Align::Right) pen.x -= width;
    // Anchor = the middle of the capital height, which centres labels on points.
    const float baseline = pen.y + 0.36f * f.atlas->pixelHeight();
    quads.clear();
    f.atlas->layout(label.text, std::round(pen.x), std::round(baseline), &quads);
    return &f;
  }

  // The pixels glyph quads (relative to a view at ox, oy) can touch, with a
  // margin for their filtered edges.
  static PixelRect glyphBounds(std::span<const GlyphQuad> quads, int ox, int oy) {
    float x0 = 1e30f, y0 = 1e30f, x1 = -1e30f, y1 = -1e30f;
    for (const GlyphQuad& q : quads) {
      x0 = std::min({x0, q.x0, q.x1}), x1 = std::max({x1, q.x0, q.x1});
      y0 = std::min({y0, q.y0, q.y1}), y1 = std::max({y1, q.y0, q.y1});
    }
    auto toInt = [](float f) { return static_cast<int>(std::clamp(f, -1e7f, 1e7f)); };
    return PixelRect{ox + toInt(std::floor(x0)) - 2, oy + toInt(std::floor(y0)) - 2, ox + toInt(std::ceil(x1)) + 3,
                     oy + toInt(std::ceil(y1)) + 3};
  }

  // Over a retained layer (drawClips set), a label whose glyphs reach none
  // of the island's dirty rectangles is not drawn: it could change only
  // pixels that are not read back (each label is a draw of its own, with
  // its vertices uploaded; a frame has about twenty).
  void drawLabel(const LabelItem& label, glm::vec2 viewportSize, const glm::mat4* clipFromWorld) {
    std::vector<GlyphQuad> quads;
    CachedFont* f = labelQuads(label, viewportSize, clipFromWorld, quads);
    if (f == nullptr || quads.empty()) return;
    if (drawClips != nullptr && clipView != nullptr &&
        !reachesAny(*drawClips, glyphBounds(quads, clipView->x, clipView->y)))
      return;
    drawQuads(quads, viewportSize, label.color, f->id, false);
  }

  // What one view draws, gathered before anything is drawn so that the
  // shadow maps can be rendered first (see render()).
  struct ViewItems {
    std::vector<Material> arrowMaterials;  // the arrows' Drawables point here
    std::vector<Drawable> items;
    const ShadowMap* shadowMap = nullptr;  // null: no shadow
    ShadowSetup shadow;
  };

  // Which items a drawing step takes: a retained layer is drawn from the
  // static ones; a frame (whole, or a rectangle over a layer) from all.
  enum class Items { StaticOnly, DynamicOnly, All };
  static bool takes(Items which, bool dynamic) {
    return which == Items::All || (which == Items::DynamicOnly) == dynamic;
  }

  // Binds the scene, the view's viewport and uniforms, scissored to `clip`
  // (image pixels, top-left origin; the view's own rectangle if null).
  void beginView(const DrawList& list, const View& v, const ViewItems& viewItems, const PixelRect* clip,
                 GLuint fbo = 0) {
    glBindFramebuffer(GL_FRAMEBUFFER, fbo != 0 ? fbo : sceneFbo);
    targetSamples = fbo != 0 && fbo == opaqueFbo ? fbSamples : 1;
    const int glY = list.height - v.y - v.height;  // GL counts rows from the bottom
    glViewport(v.x, glY, v.width, v.height);
    glEnable(GL_SCISSOR_TEST);
    const PixelRect r = clip != nullptr ? *clip : PixelRect{v.x, v.y, v.x + v.width, v.y + v.height};
    glScissor(r.x0, list.height - r.y1, r.x1 - r.x0, r.y1 - r.y0);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LEQUAL);
    glDepthMask(GL_TRUE);
    viewUniforms.clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
    viewUniforms.lightClipFromWorld = viewItems.shadow.lightClipFromWorld;
    viewUniforms.towardLight = glm::normalize(v.light.towardLight);
    viewUniforms.lightColor = v.light.color;
    viewUniforms.ambient = v.light.ambient;
    viewUniforms.cameraPosition = v.camera.position;
    viewUniforms.shadowFilterRadius = viewItems.shadow.filterRadius;
    viewUniforms.view = &v;
    glActiveTexture(GL_TEXTURE1);
    glBindTexture(GL_TEXTURE_2D, viewItems.shadowMap != nullptr ? viewItems.shadowMap->texture : 0);
  }

  // A label as `which` takes it. A layer's static items take the static
  // part of a dynamic label (its leading words); everything else draws a
  // label whole, in one draw, as a still does.
  void drawLabelAs(const LabelItem& label, Items which, glm::vec2 viewportSize, const glm::mat4* clipFromWorld) {
    if (which == Items::StaticOnly) {
      if (const auto part = staticPartOf(label)) drawLabel(*part, viewportSize, clipFromWorld);
    } else if (takes(which, label.dynamic)) {
      drawLabel(label, viewportSize, clipFromWorld);
    }
  }

  // The opaque meshes; receivers without the shadow filter (see drawReshade).
  // Where an opaque mesh is drawn: with the static ones, in their samples
  // (Pass::Samples: every static mesh, and a moving one that is not a
  // sphere, an arrow say, whose triangle edges the samples antialias), or
  // after the resolve at one sample (Pass::Coverage: a moving sphere,
  // ray-cast with its coverage; every moving mesh at msaa = 1).
  enum class Pass { Samples, Coverage };
  bool inSamplesPass(const Drawable& d) const { return !d.dynamic || (opaqueFbo != 0 && !d.sphere); }

  void drawOpaque(const ViewItems& viewItems, Items which, Pass pass) {
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    for (GLenum plane = 0; plane < 5; ++plane) glEnable(GL_CLIP_DISTANCE0 + plane);
    for (const Drawable& d : viewItems.items)
      if (d.material->opacity >= 1.0f && takes(which, d.dynamic) && inSamplesPass(d) == (pass == Pass::Samples))
        drawMesh(d, false, d.material->cull);
    for (GLenum plane = 0; plane < 5; ++plane) glDisable(GL_CLIP_DISTANCE0 + plane);
    glDisable(GL_CULL_FACE);
  }

  // The opaque meshes drawn in samples (`which` of them) drawn at one
  // sample into the scene bound by beginView, for the depth at the pixel
  // centres, everywhere, and the static ones' colour: right wherever no
  // triangle covers a pixel in part (every sample would show what the
  // centre shows, and the resolve's rounded mean of equal samples is that
  // value). Elsewhere, and wherever a moving one (an arrow) can be, the
  // samples are resolved over it (see sampleTiles), so a moving one is
  // drawn for its depth alone. Drawn as in samples: a sphere as its
  // triangles, not ray-cast.
  void drawOpaqueAtCentres(const ViewItems& viewItems, Items which) {
    const bool depthAlone = which == Items::DynamicOnly && opaqueFbo != 0;
    if (depthAlone) {
      glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
      depthOnly = true;
    }
    targetSamples = fbSamples;
    drawOpaque(viewItems, which, Pass::Samples);
    targetSamples = 1;
    if (depthAlone) {
      depthOnly = false;
      glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    }
  }

  // The tiles of view v (inside its rectangle) where the opaque meshes drawn
  // in samples (`which` of them) can cover a pixel in part, so where their
  // samples are drawn and resolved: near a static mesh's outline or cuts
  // (coverage_edges.hpp), where two static meshes' boxes meet (their
  // intersection is no edge of either), and all over a moving one's bounds
  // (an arrow: the same tiles redrawSamples redraws over a layer).
  // A surface that intersects itself gets no samples along the crossing.
  std::vector<PixelRect> sampleTiles(const DrawList& list, const View& v, const ViewItems& viewItems, Items which) {
    TileGrid grid(list.width, list.height);
    const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
    std::vector<PixelRect> bounds;
    std::vector<std::pair<glm::vec3, glm::vec3>> boxes;  // the static meshes' world boxes
    for (const Drawable& d : viewItems.items) {
      if (d.material->opacity < 1.0f || !inSamplesPass(d) || !takes(which, d.dynamic)) continue;
      if (d.dynamic) {
        bounds.clear();
        meshBounds(v, clipFromWorld, d, bounds);
        for (const PixelRect& r : bounds) grid.add(r);
        continue;
      }
      addOutlineTiles(*d.mesh, meshEdges(d.mesh), d.worldFromModel, d.material->cutPlane, v, 2.0f, grid);
      const GpuMesh& g = gpuMesh(d.mesh);
      glm::vec3 lo(1e30f), hi(-1e30f);
      for (const glm::vec3& corner : boxCorners(g.lo, g.hi, d.worldFromModel)) {
        lo = glm::min(lo, corner);
        hi = glm::max(hi, corner);
      }
      boxes.emplace_back(lo, hi);
    }
    for (std::size_t a = 0; a < boxes.size(); ++a)
      for (std::size_t b = a + 1; b < boxes.size(); ++b) {
        const glm::vec3 lo = glm::max(boxes[a].first, boxes[b].first), hi = glm::min(boxes[a].second, boxes[b].second);
        if (lo.x > hi.x || lo.y > hi.y || lo.z > hi.z) continue;
        grid.add(screenBounds(v, clipFromWorld, boxCorners(lo, hi).data(), 8, 2.0f));
      }
    const PixelRect area{v.x, v.y, v.x + v.width, v.y + v.height};
    std::vector<PixelRect> tiles;
    for (const PixelRect& r : grid.rects())
      if (const PixelRect inside = intersect(r, area); !inside.empty()) tiles.push_back(inside);
    return tiles;
  }

  // A view's opaque meshes drawn whole (in a frame drawn whole, or a fresh
  // view): at one sample, then in samples tile rectangle by tile rectangle
  // of sampleTiles, resolved over them. `clear`: the view's rectangle is cleared
  // first, scissored (an inset, a fresh view); otherwise the frame's one
  // clear did it. llvmpipe pays for samples (a clear, a draw and a resolve
  // of four values a pixel) only near edges: a 1080p frame whose camera
  // moves drew its ball view's floor in samples in full.
  // Returns the tiles drawn in samples: the only pixels that the meshes
  // cover in part (alpha strictly between 0 and 1).
  std::vector<PixelRect> drawViewOpaque(const DrawList& list, const View& v, const ViewItems& viewItems, bool clear) {
    beginView(list, v, viewItems, nullptr);
    if (clear) {
      glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
      glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
    }
    drawOpaqueAtCentres(viewItems, Items::StaticOnly);
    drawOpaqueAtCentres(viewItems, Items::DynamicOnly);
    if (opaqueFbo == 0) return {};
    const std::vector<PixelRect> tiles = sampleTiles(list, v, viewItems, Items::All);
    stats.wholeViewPixels += static_cast<long long>(v.width) * v.height;
    for (const PixelRect& r : tiles) stats.sampledPixels += static_cast<long long>(r.x1 - r.x0) * (r.y1 - r.y0);
    // Each tile rectangle drawn in a box of its own, a pixel wider than it:
    // a multisampled pixel on a scissor's edge can lose samples, and those
    // it keeps are shaded at their centroid, off the pixel's (seen: one
    // pixel in a 1080p frame differed from a draw without a scissor, on a
    // box's top row). Islands (see redrawRects) would merge the tiles along
    // a long diagonal edge into the box it spans. So the boxes go in
    // rounds: no box of a round reaches another rectangle of it, and a
    // round's rectangles are resolved before the next round's boxes (which
    // can reach them) are cleared and drawn. Rectangles that touch are in
    // different rounds; two to four rounds in practice.
    const PixelRect area{v.x, v.y, v.x + v.width, v.y + v.height};
    std::vector<PixelRect> boxes;
    for (const PixelRect& r : tiles)
      boxes.push_back(intersect(PixelRect{r.x0 - 1, r.y0 - 1, r.x1 + 1, r.y1 + 1}, area));
    std::vector<int> roundOf(tiles.size(), 0);
    int rounds = 0;
    for (std::size_t i = 0; i < tiles.size(); ++i) {
      std::vector<bool> taken(static_cast<std::size_t>(rounds) + 1, false);
      for (std::size_t j = 0; j < i; ++j)
        if (overlaps(boxes[i], tiles[j])) taken[static_cast<std::size_t>(roundOf[j])] = true;
      while (taken[static_cast<std::size_t>(roundOf[i])]) ++roundOf[i];
      rounds = std::max(rounds, roundOf[i] + 1);
    }
    std::vector<PixelRect> oneBox(1);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    for (int round = 0; round < rounds; ++round) {
      for (std::size_t i = 0; i < tiles.size(); ++i) {
        if (roundOf[i] != round) continue;
        oneBox[0] = boxes[i];
        beginView(list, v, viewItems, &oneBox[0], opaqueFbo);
        glClear(GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT);
      }
      drawClips = &oneBox;
      clipView = &v;
      for (std::size_t i = 0; i < tiles.size(); ++i) {
        if (roundOf[i] != round) continue;
        oneBox[0] = boxes[i];
        beginView(list, v, viewItems, &oneBox[0], opaqueFbo);
        drawOpaque(viewItems, Items::StaticOnly, Pass::Samples);
        drawOpaque(viewItems, Items::DynamicOnly, Pass::Samples);
      }
      drawClips = nullptr;
      clipView = nullptr;
      for (std::size_t i = 0; i < tiles.size(); ++i)
        if (roundOf[i] == round) resolveOpaque(list, tiles[i]);
    }
    return tiles;
  }

  // After drawViewOpaque: the steps at one sample, a ray-cast sphere's
  // under pass only where the meshes cover pixels in part (`sampled`) or a
  // sphere drawn before it does (the pass changes nothing elsewhere: see
  // drawImpostor), then the rest.
  void drawViewAfterOpaque(const DrawList& list, int view, const ViewItems& viewItems, std::vector<PixelRect> sampled) {
    const bool under = underEverywhere;
    std::vector<PixelRect> kept = std::exchange(underRects, std::move(sampled));
    underEverywhere = false;
    drawAfterResolve(viewItems);
    underEverywhere = under;
    underRects = std::move(kept);
    drawRest(list, view, viewItems, Items::All);
  }

  // The receivers' re-shade (not in a static layer: the shadow moves with
  // the ball), right after the resolve: before the ray-cast spheres, whose
  // edges blend over the shadowed surface (drawn after them, a re-shade
  // would miss the pixels that a sphere's edge covers in part, and leave
  // them lit).
  void drawReshades(const ViewItems& viewItems) {
    if (viewItems.shadowMap == nullptr) return;
    glDisable(GL_BLEND);
    glDepthMask(GL_TRUE);
    for (GLenum plane = 0; plane < 5; ++plane) glEnable(GL_CLIP_DISTANCE0 + plane);
    for (const Drawable& d : viewItems.items)
      if (d.material->opacity >= 1.0f && d.material->receivesShadow) drawReshade(d);
    for (GLenum plane = 0; plane < 5; ++plane) glDisable(GL_CLIP_DISTANCE0 + plane);
    glDisable(GL_CULL_FACE);
  }

  // What a frame draws at one sample after the resolve, before drawRest.
  void drawAfterResolve(const ViewItems& viewItems) {
    drawReshades(viewItems);
    drawOpaque(viewItems, Items::DynamicOnly, Pass::Coverage);
  }

  // Everything after the opaque meshes and the re-shade: depth-tested lines,
  // translucent meshes far to near, then lines over everything, labels and
  // the inset frame.
  void drawRest(const DrawList& list, int index, const ViewItems& viewItems, Items which) {
    const View& v = list.views[static_cast<std::size_t>(index)];
    const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
    // A line's quad faces either way: no culling, whatever ran before (the
    // shadow pass culls, and a layer's update draws no opaque mesh first).
    glDisable(GL_CULL_FACE);
    glDepthMask(GL_FALSE);
    glEnable(GL_BLEND);
    for (const PolylineItem& p : list.polylines)
      if (p.view == index && p.depthTested && takes(which, p.dynamic)) drawPolyline(p, clipFromWorld, v);

    // Far to near. A closed translucent mesh shows its front half only: its
    // back half would double the blending cost for little visual gain.
    std::vector<const Drawable*> translucent;
    for (const Drawable& d : viewItems.items)
      if (d.material->opacity < 1.0f && takes(which, d.dynamic)) translucent.push_back(&d);
    auto depthOf = [&](const Drawable* d) { return (v.camera.viewFromWorld * d->worldFromModel[3]).z; };
    std::stable_sort(translucent.begin(), translucent.end(),
                     [&](const Drawable* a, const Drawable* b) { return depthOf(a) < depthOf(b); });
    for (GLenum plane = 0; plane < 5; ++plane) glEnable(GL_CLIP_DISTANCE0 + plane);
    for (const Drawable* d : translucent) {
      // Translucent layers (glass, the Bloch sphere) take no shadow.
      drawMesh(*d, false, d->material->cull);
    }
    for (GLenum plane = 0; plane < 5; ++plane) glDisable(GL_CLIP_DISTANCE0 + plane);
    glDisable(GL_CULL_FACE);
    glDisable(GL_DEPTH_TEST);
    for (const PolylineItem& p : list.polylines)
      if (p.view == index && !p.depthTested && takes(which, p.dynamic)) drawPolyline(p, clipFromWorld, v);
    for (const LabelItem& l : list.labels)
      if (l.view == index) drawLabelAs(l, which, glm::vec2(v.width, v.height), &clipFromWorld);
    if (v.frame && which != Items::DynamicOnly) {
      const float w = float(v.width), h = float(v.height), t = std::max(1.0f, h / 300.0f);
      const std::vector<GlyphQuad> border{{0, 0, w, t, 0, 0, 0, 0}, {0, h - t, w, h, 0, 0, 0, 0},
                                          {0, 0, t, h, 0, 0, 0, 0}, {w - t, 0, w, h, 0, 0, 0, 0}};
      drawQuads(border, glm::vec2(w, h), glm::vec4(0.35f, 0.38f, 0.42f, 1.0f), 0, true);
    }
    glDepthMask(GL_TRUE);
  }

  // Image-level labels (titles) over everything, scissored to `clip`.
  void drawImageLabels(const DrawList& list, Items which, const PixelRect& clip) {
    glBindFramebuffer(GL_FRAMEBUFFER, sceneFbo);
    glEnable(GL_SCISSOR_TEST);
    glScissor(clip.x0, list.height - clip.y1, clip.x1 - clip.x0, clip.y1 - clip.y0);
    glViewport(0, 0, list.width, list.height);
    glDisable(GL_DEPTH_TEST);
    glEnable(GL_BLEND);
    glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
    for (const LabelItem& l : list.labels)
      if (l.view < 0) drawLabelAs(l, which, glm::vec2(list.width, list.height), nullptr);
  }

  static bool overlap(const View& a, const View& b) {
    return a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height;
  }

  static bool viewsDisjoint(const DrawList& list) {
    for (std::size_t i = 0; i < list.views.size(); ++i)
      for (std::size_t j = i + 1; j < list.views.size(); ++j)
        if (overlap(list.views[i], list.views[j])) return false;
    return true;
  }

  // sRGB encoding of a backdrop colour (readBack composites encoded
  // values, as the scene's blending does).
  static glm::vec3 encodeSrgb(const glm::vec3& linear) {
    glm::vec3 out;
    for (int k = 0; k < 3; ++k) {
      const float c = std::clamp(linear[k], 0.0f, 1.0f);
      out[k] = c < 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    }
    return out;
  }

  // The scene's pixels of `r` (image rows, top-down) made the output's, on
  // the CPU as they are read back: rows flipped top-down, the view's
  // backdrop gradient put behind (the scene is premultiplied colour over
  // transparent black: out = c + (1 − a)·backdrop, the "over" operator,
  // exact for any stack of blended layers), values sRGB-encoded bytes as the
  // scene's blending left them. llvmpipe pays about 11 ns a pixel for any
  // full-image pass (a 1080p still's composite cost 21–22 ms of CPU); this
  // loop costs a small fraction of that, and the read-back it rides on is
  // paid anyway. A pixel belongs to the last view that holds it, as the
  // views are drawn; pixels between views get no backdrop.
  void readBack(const DrawList& list, media::Image& image, const PixelRect& r) {
    if (r.empty()) return;
    const int width = r.x1 - r.x0, rows = r.y1 - r.y0;
    readRows.resize(static_cast<std::size_t>(width) * rows);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, sceneFbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(r.x0, list.height - r.y1, width, rows, GL_RGBA, GL_UNSIGNED_BYTE, readRows.data());
    static_assert(std::endian::native == std::endian::little, "the packed RGBA8 words assume little endian");
    const std::uint32_t opaqueAlpha = list.transparent ? 0u : 255u;
    // Each view's backdrop ends, sRGB-encoded once (not per row).
    std::vector<std::pair<glm::vec3, glm::vec3>>& ends = backdropEnds;
    ends.clear();
    for (const View& v : list.views) ends.emplace_back(encodeSrgb(v.backgroundTop), encodeSrgb(v.backgroundBottom));
    std::vector<int>& cuts = rowCuts;
    for (int y = r.y0; y < r.y1; ++y) {
      // GL rows count from the bottom: read row k is image row r.y1 − 1 − k.
      const std::uint32_t* in = readRows.data() + static_cast<std::size_t>(r.y1 - 1 - y) * width;
      auto* out =
          reinterpret_cast<std::uint32_t*>(image.rgba.data() + (static_cast<std::size_t>(y) * list.width + r.x0) * 4);
      // The row cut where views begin and end; each piece belongs to the
      // last view that holds it (or none).
      cuts.assign({r.x0, r.x1});
      for (const View& v : list.views)
        if (y >= v.y && y < v.y + v.height)
          for (const int x : {v.x, v.x + v.width})
            if (x > r.x0 && x < r.x1) cuts.push_back(x);
      std::sort(cuts.begin(), cuts.end());
      for (std::size_t c = 0; c + 1 < cuts.size(); ++c) {
        const int x0 = cuts[c], x1 = cuts[c + 1];
        if (x0 == x1) continue;
        std::size_t owner = list.views.size();  // none
        for (std::size_t i = 0; i < list.views.size(); ++i) {
          const View& v = list.views[i];
          if (y >= v.y && y < v.y + v.height && x0 >= v.x && x0 < v.x + v.width) owner = i;
        }
        glm::vec3 backdrop(0.0f);
        if (owner < list.views.size() && list.views[owner].background && !list.transparent) {
          // Linear in the row, sampled at the pixel centre.
          const View& v = list.views[owner];
          const auto& [top, bottom] = ends[owner];
          backdrop = top + (bottom - top) * ((float(y - v.y) + 0.5f) / float(v.height));
        }
        compositeSpan(in + (x0 - r.x0), in + (x1 - r.x0), out + (x0 - r.x0), backdrop, opaqueAlpha);
      }
      if (list.transparent) {
        // Blending left premultiplied colour over the empty background.
        for (int x = 0; x < width; ++x) {
          auto* p = reinterpret_cast<std::uint8_t*>(out + x);
          if (p[3] != 0 && p[3] != 255)
            for (int c = 0; c < 3; ++c) p[c] = static_cast<std::uint8_t>(std::min(255, (p[c] * 255 + p[3] / 2) / p[3]));
        }
      }
    }
  }
  std::vector<std::uint32_t> readRows;  // readBack's rows as read, bottom-up
  std::vector<std::pair<glm::vec3, glm::vec3>> backdropEnds;  // readBack's, per view
  std::vector<int> rowCuts;                                   // readBack's, per row

  // out = c + (1 − a)·backdrop per channel, rounded, clamped; alpha at
  // least opaqueAlpha. Pixels the scene covers fully keep their word, and
  // those it leaves empty take the backdrop's, computed once.
  static void compositeSpan(const std::uint32_t* begin, const std::uint32_t* end, std::uint32_t* out,
                            const glm::vec3& backdrop, std::uint32_t opaqueAlpha) {
    auto over = [&](std::uint32_t t) {
      const std::uint32_t a = t >> 24u;
      const float uncovered = float(255u - a);
      std::uint32_t word = std::max(a, opaqueAlpha) << 24u;
      for (int c = 0; c < 3; ++c) {
        const auto behind = static_cast<std::uint32_t>(backdrop[c] * uncovered + 0.5f);
        word |= std::min(((t >> (8 * c)) & 0xFFu) + behind, 255u) << (8 * c);
      }
      return word;
    };
    const std::uint32_t empty = over(0u);
    for (const std::uint32_t* p = begin; p != end; ++p, ++out) {
      const std::uint32_t t = *p;
      *out = t >= 0xFF000000u ? t : t == 0u ? empty : over(t);
    }
  }

  // ---- Retained layers ----------------------------------------------------
  //
  // A frame is drawn in this order, view by view. The static opaque
  // meshes, then the moving opaque meshes that are not spheres (arrows), at
  // one sample into the scene (its colour where no pixel is covered in
  // part, the depth at the pixel centres everywhere), and in samples
  // (opaqueFbo, msaa of them) in the tiles near their edges and over the
  // arrows, resolved there over the scene (see drawViewOpaque). Then at one
  // sample, each step antialiased by its own coverage: the receivers'
  // re-shade inside the shadow box; the moving spheres, ray-cast;
  // depth-tested lines; translucent meshes; overlays (see drawRest). So
  // llvmpipe pays for the samples only near edges, and over a layer only
  // over the arrows.
  // When the static items and the views are the same as in the frame
  // before, the renderer keeps (a) the scene after the static opaque meshes
  // (colour and depth, one sample, and their samples too) and (b) the
  // finished image of the static items alone. A frame then starts from (b)
  // and redraws only the rectangles that its dynamic items (and the shadow
  // box) can touch: (a) copied in, the arrows' tiles drawn over its samples
  // and resolved, then every later step, scissored. Outside those
  // rectangles a whole frame draws exactly what (b) holds, and inside them
  // exactly the same steps run on the same values, so both ways give the
  // same bytes: a frame does not depend on the frames before it (tested),
  // and the first frame of a span is simply drawn whole.
  // The retained layer: (a) in snapshotFbo and snapshotSamplesFbo, (b) in
  // layerImage; valid while `layerKey` matches. `pendingKey`: the last frame drawn whole, so a layer
  // is built only when a second frame shares it (a moving camera pays
  // nothing for layers it would never reuse).
  GLuint snapshotFbo = 0, snapshotColor = 0, snapshotDepth = 0;
  GLuint snapshotSamplesFbo = 0, snapshotSamplesColor = 0, snapshotSamplesDepth = 0;  // opaqueFbo's, when it exists
  int snapshotWidth = 0, snapshotHeight = 0, snapshotSamples = 0;
  std::optional<StaticKey> layerKey, pendingKey;
  bool lastFrameOverLayer = false;
  media::Image layerImage;
  // layerImage's identity: a new epoch per build, a new version per update
  // in place, with the rectangles each recent update changed (what an image
  // drawn over an older version must put back besides its own rectangles).
  std::uint64_t layerEpoch = 0, layerVersion = 0, restorableFrom = 0;
  std::deque<std::pair<std::uint64_t, std::vector<PixelRect>>> layerUpdates;
  static constexpr std::size_t kLayerUpdatesKept = 64;
  RenderStats stats;

  void releaseSnapshot() {
    glDeleteFramebuffers(1, &snapshotFbo);
    glDeleteTextures(1, &snapshotColor);
    glDeleteRenderbuffers(1, &snapshotDepth);
    glDeleteFramebuffers(1, &snapshotSamplesFbo);
    GLuint rbs[] = {snapshotSamplesColor, snapshotSamplesDepth};
    glDeleteRenderbuffers(2, rbs);
    snapshotFbo = snapshotColor = snapshotDepth = 0;
    snapshotSamplesFbo = snapshotSamplesColor = snapshotSamplesDepth = 0;
    snapshotWidth = snapshotHeight = snapshotSamples = 0;
  }

  void ensureSnapshot() {
    if (snapshotWidth == fbWidth && snapshotHeight == fbHeight && snapshotSamples == fbSamples) return;
    releaseSnapshot();
    glGenTextures(1, &snapshotColor);
    glBindTexture(GL_TEXTURE_2D, snapshotColor);
    glTexStorage2D(GL_TEXTURE_2D, 1, GL_RGBA8, fbWidth, fbHeight);
    glGenRenderbuffers(1, &snapshotDepth);
    glBindRenderbuffer(GL_RENDERBUFFER, snapshotDepth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, fbWidth, fbHeight);
    glGenFramebuffers(1, &snapshotFbo);
    glBindFramebuffer(GL_FRAMEBUFFER, snapshotFbo);
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D, snapshotColor, 0);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, snapshotDepth);
    auto checkComplete = [&] {
      if (glCheckFramebufferStatus(GL_FRAMEBUFFER) != GL_FRAMEBUFFER_COMPLETE)
        throw runtimeError({}, "OpenGL could not create a {}x{} retained layer with {} samples (out of memory?)",
                           fbWidth, fbHeight, fbSamples);
    };
    checkComplete();
    if (opaqueFbo != 0) {
      glGenRenderbuffers(1, &snapshotSamplesColor);
      glBindRenderbuffer(GL_RENDERBUFFER, snapshotSamplesColor);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, fbSamples, GL_RGBA8, fbWidth, fbHeight);
      glGenRenderbuffers(1, &snapshotSamplesDepth);
      glBindRenderbuffer(GL_RENDERBUFFER, snapshotSamplesDepth);
      glRenderbufferStorageMultisample(GL_RENDERBUFFER, fbSamples, GL_DEPTH_COMPONENT24, fbWidth, fbHeight);
      glGenFramebuffers(1, &snapshotSamplesFbo);
      glBindFramebuffer(GL_FRAMEBUFFER, snapshotSamplesFbo);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, snapshotSamplesColor);
      glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, snapshotSamplesDepth);
      checkComplete();
    }
    snapshotWidth = fbWidth;
    snapshotHeight = fbHeight;
    snapshotSamples = fbSamples;
  }

  // A mesh's screen bounds, as rectangles that together hold it: the
  // corners of its model-space bounding box, narrowed to its bounding
  // sphere's projection (a ball's box projects to a square about 1.5 times
  // its outline). A long thin mesh (an arrow's shaft) is cut across its
  // length into slabs of about its width, each bounded alone: a diagonal
  // arrow dirties a band along itself, not the square it spans.
  void meshBounds(const View& v, const glm::mat4& clipFromWorld, const Drawable& d, std::vector<PixelRect>& out) {
    const GpuMesh& g = gpuMesh(d.mesh);
    const glm::mat3 linear(d.worldFromModel);
    const glm::vec3 extent = (g.hi - g.lo) * glm::vec3(glm::length(linear[0]), glm::length(linear[1]),
                                                       glm::length(linear[2]));
    int along = 0;
    for (int a = 1; a < 3; ++a)
      if (extent[a] > extent[along]) along = a;
    const float across = std::max(extent[(along + 1) % 3], extent[(along + 2) % 3]);
    const int slabs = across > 0.0f ? std::clamp(int(std::ceil(extent[along] / across)), 1, 16) : 1;
    const float scale = std::max({glm::length(linear[0]), glm::length(linear[1]), glm::length(linear[2])});
    const glm::vec3 centre(d.worldFromModel * glm::vec4(glm::vec3(g.bound), 1.0f));
    const std::optional<PixelRect> sphere = sphereBounds(v, centre, g.bound.w * scale, 2.0f);
    for (int slab = 0; slab < slabs; ++slab) {
      glm::vec3 lo = g.lo, hi = g.hi;
      lo[along] = g.lo[along] + (g.hi[along] - g.lo[along]) * float(slab) / float(slabs);
      hi[along] = slab + 1 == slabs ? g.hi[along] : g.lo[along] + (g.hi[along] - g.lo[along]) * float(slab + 1) / float(slabs);
      const PixelRect box = screenBounds(v, clipFromWorld, boxCorners(lo, hi, d.worldFromModel).data(), 8, 2.0f);
      out.push_back(sphere ? intersect(box, *sphere) : box);
    }
  }


  // Where a receiver's re-shade can draw: its triangles clipped to the
  // shadow box's prism across the light (|x|, |y| ≤ 1 in light clip space,
  // affine: an orthographic light), projected.
  PixelRect reshadeBounds(const View& v, const glm::mat4& clipFromWorld, const glm::mat4& lightClipFromWorld,
                          const Drawable& d) {
    const MeshData& m = *d.mesh;
    struct P {
      glm::vec3 world;
      glm::vec2 light;
    };
    std::vector<P> verts(m.vertices.size());
    for (std::size_t i = 0; i < verts.size(); ++i) {
      const glm::vec3 w(d.worldFromModel * glm::vec4(m.vertices[i].position, 1.0f));
      verts[i] = {w, glm::vec2(lightClipFromWorld * glm::vec4(w, 1.0f))};
    }
    std::vector<glm::vec3> inside;
    std::vector<P> poly, next;
    for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
      poly = {verts[m.indices[t]], verts[m.indices[t + 1]], verts[m.indices[t + 2]]};
      for (int plane = 0; plane < 4 && !poly.empty(); ++plane) {
        auto dist = [&](const P& p) { return 1.0f + (plane & 1 ? -1.0f : 1.0f) * p.light[plane / 2]; };
        next.clear();
        for (std::size_t i = 0; i < poly.size(); ++i) {
          const P& a = poly[i];
          const P& b = poly[(i + 1) % poly.size()];
          const float da = dist(a), db = dist(b);
          if (da >= 0.0f) next.push_back(a);
          if ((da >= 0.0f) != (db >= 0.0f)) {
            const float f = da / (da - db);
            next.push_back({a.world + f * (b.world - a.world), a.light + f * (b.light - a.light)});
          }
        }
        std::swap(poly, next);
      }
      for (const P& p : poly) inside.push_back(p.world);
    }
    return screenBounds(v, clipFromWorld, inside.data(), inside.size(), 3.0f);
  }

  // The pixels a frame must redraw over the retained layer, as disjoint
  // rectangles of whole tiles: the tiles that any dynamic item (a line
  // segment by segment, so that a long trail dirties a thin band along
  // itself) or a receiver's shadow box can touch.
  // A fresh view (see freshViews) is dirty whole.
  std::vector<PixelRect> dirtyRects(const DrawList& list, const std::vector<ViewItems>& perView,
                                    const std::vector<bool>& fresh) {
    TileGrid grid(list.width, list.height);
    auto add = [&](const PixelRect& r) { grid.add(r); };
    std::vector<PixelRect> meshRects;
    for (std::size_t i = 0; i < list.views.size(); ++i) {
      const View& v = list.views[i];
      const int index = static_cast<int>(i);
      if (fresh[i]) {
        add(PixelRect{v.x, v.y, v.x + v.width, v.y + v.height});
        continue;
      }
      const glm::mat4 clipFromWorld = v.camera.clipFromView * v.camera.viewFromWorld;
      for (const Drawable& d : perView[i].items) {
        if (d.dynamic) {
          meshRects.clear();
          meshBounds(v, clipFromWorld, d, meshRects);
          for (const PixelRect& r : meshRects) add(r);
        }
        if (perView[i].shadowMap != nullptr && d.material->receivesShadow && d.material->opacity >= 1.0f)
          add(reshadeBounds(v, clipFromWorld, perView[i].shadow.lightClipFromWorld, d));
      }
      for (const PolylineItem& p : list.polylines)
        if (p.view == index && p.dynamic) addSegmentBounds(p, v, clipFromWorld, 0, grid);
      for (const LabelItem& l : list.labels)
        if (l.view == index && l.dynamic) add(labelBounds(l, list, &v, clipFromWorld));
    }
    for (const LabelItem& l : list.labels)
      if (l.view < 0 && l.dynamic) add(labelBounds(l, list, nullptr, glm::mat4(1.0f)));
    return grid.rects();
  }

  // What layerChanges needs to know of the items' extents.
  ItemBounds itemBounds(const DrawList& list) {
    ItemBounds b;
    b.mesh = [this](const MeshItem& m, const View& v, const glm::mat4& clipFromWorld, std::vector<PixelRect>& out) {
      meshBounds(v, clipFromWorld, Drawable{m.mesh, m.worldFromModel, &m.material, false}, out);
    };
    b.label = [this, &list](const LabelItem& l, const View* v, const glm::mat4& clipFromWorld) {
      return labelBounds(l, list, v, clipFromWorld);
    };
    return b;
  }

  PixelRect labelBounds(const LabelItem& l, const DrawList& list, const View* v, const glm::mat4& clipFromWorld) {
    const glm::vec2 size = v != nullptr ? glm::vec2(v->width, v->height) : glm::vec2(list.width, list.height);
    const glm::mat4* clip = v != nullptr ? &clipFromWorld : nullptr;
    std::vector<GlyphQuad> quads;
    if (labelQuads(l, size, clip, quads) == nullptr || quads.empty()) return {};
    // A dynamic label's static part is in the layer: only the glyphs after
    // it change (the part's glyphs are the label's first ones).
    std::size_t first = 0;
    if (l.dynamic)
      if (const auto part = staticPartOf(l)) {
        std::vector<GlyphQuad> partQuads;
        if (labelQuads(*part, size, clip, partQuads) != nullptr) first = partQuads.size();
      }
    if (first >= quads.size()) return {};
    const PixelRect area = v != nullptr ? PixelRect{v->x, v->y, v->x + v->width, v->y + v->height}
                                        : PixelRect{0, 0, list.width, list.height};
    return intersect(glyphBounds(std::span(quads).subspan(first), v != nullptr ? v->x : 0, v != nullptr ? v->y : 0),
                     area);
  }

  // The whole frame, as the static items' layer and dynamic items would
  // draw it, step for step (see "Retained layers").
  void drawWhole(const DrawList& list, const std::vector<ViewItems>& perView) {
    for (std::size_t i = 0; i < list.views.size(); ++i) {
      const View& v = list.views[i];
      bool overlapsEarlier = false;
      for (std::size_t j = 0; j < i; ++j) overlapsEarlier = overlapsEarlier || overlap(list.views[i], list.views[j]);
      // An inset over a view drawn before clears its own rectangle (a
      // scissored clear is a full-screen quad on llvmpipe: only an inset
      // pays for it).
      std::vector<PixelRect> sampled = drawViewOpaque(list, v, perView[i], overlapsEarlier);
      beginView(list, v, perView[i], nullptr);
      drawViewAfterOpaque(list, static_cast<int>(i), perView[i], std::move(sampled));
    }
    drawImageLabels(list, Items::All, PixelRect{0, 0, list.width, list.height});
  }

  // One unscissored clear of the whole scene: llvmpipe does it per tile as
  // the tile is first rasterized; a scissored clear would be a quad draw.
  // The samples too only for a layer, which draws them whole: llvmpipe
  // fills every tile of a cleared buffer, and elsewhere only the tiles near
  // edges are drawn in samples (each cleared with a scissor first).
  void clearScene(const DrawList& list, bool samplesToo) {
    glDisable(GL_SCISSOR_TEST);
    glViewport(0, 0, list.width, list.height);
    glClearColor(0.0f, 0.0f, 0.0f, 0.0f);
    glDepthMask(GL_TRUE);
    for (const GLuint fbo : {samplesToo ? opaqueFbo : 0u, sceneFbo}) {
      if (fbo == 0) continue;
      glBindFramebuffer(GL_FRAMEBUFFER, fbo);
      glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    }
  }

  // Draws the static items into the scene, keeping the samples after their
  // opaque meshes, and reads their finished image into layerImage.
  void buildLayer(const DrawList& list, const std::vector<ViewItems>& perView) {
    ensureSnapshot();
    clearScene(list, true);
    if (opaqueFbo != 0) {
      // Every sample, kept for the moving meshes drawn in samples over the
      // layer (redrawSamples), wherever they go.
      for (std::size_t i = 0; i < list.views.size(); ++i) {
        beginView(list, list.views[i], perView[i], nullptr, opaqueFbo);
        drawOpaque(perView[i], Items::StaticOnly, Pass::Samples);
      }
      glDisable(GL_SCISSOR_TEST);
      glBindFramebuffer(GL_READ_FRAMEBUFFER, opaqueFbo);
      glBindFramebuffer(GL_DRAW_FRAMEBUFFER, snapshotSamplesFbo);
      glBlitFramebuffer(0, 0, list.width, list.height, 0, 0, list.width, list.height,
                        GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    }
    // The scene as drawViewOpaque draws the static meshes: at one sample,
    // resolved from the samples near their edges.
    std::vector<PixelRect> resolved;
    for (std::size_t i = 0; i < list.views.size(); ++i) {
      beginView(list, list.views[i], perView[i], nullptr);
      drawOpaqueAtCentres(perView[i], Items::StaticOnly);
      if (opaqueFbo == 0) continue;
      const std::vector<PixelRect> tiles = sampleTiles(list, list.views[i], perView[i], Items::StaticOnly);
      resolved.insert(resolved.end(), tiles.begin(), tiles.end());
    }
    for (const PixelRect& r : resolved) resolveOpaque(list, r);
    findLayerEdges(list);
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, sceneFbo);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, snapshotFbo);
    glBlitFramebuffer(0, 0, list.width, list.height, 0, 0, list.width, list.height,
                      GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT, GL_NEAREST);
    for (std::size_t i = 0; i < list.views.size(); ++i) {
      beginView(list, list.views[i], perView[i], nullptr);
      drawRest(list, static_cast<int>(i), perView[i], Items::StaticOnly);
    }
    drawImageLabels(list, Items::StaticOnly, PixelRect{0, 0, list.width, list.height});
    layerImage.width = list.width;
    layerImage.height = list.height;
    layerImage.rgba.resize(static_cast<std::size_t>(list.width) * list.height * 4);
    readBack(list, layerImage, PixelRect{0, 0, list.width, list.height});
    ++stats.layerBuilds;
    static std::atomic<std::uint64_t> epochs{0};
    layerEpoch = ++epochs;
    layerVersion = restorableFrom = 0;
    layerUpdates.clear();
  }

  // The tiles where the resolved opaque layer covers pixels in part (alpha
  // strictly between 0 and 1): read back once per layer.
  void findLayerEdges(const DrawList& list) {
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(list.width) * list.height * 4);
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, sceneFbo);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, list.width, list.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    TileGrid grid(list.width, list.height);
    for (int row = 0; row < list.height; ++row) {
      const int y = list.height - 1 - row;  // GL counts rows from the bottom
      const std::uint8_t* p = &rgba[static_cast<std::size_t>(row) * list.width * 4];
      for (int x = 0; x < list.width; ++x)
        if (const std::uint8_t a = p[x * 4 + 3]; a != 0 && a != 255) grid.add(PixelRect{x, y, x + 1, y + 1});
    }
    layerEdgeRects = grid.rects();
  }

  // A frame over the retained layer: its image, with the dirty rectangles
  // redrawn from the snapshot on.
  // With a history that knows the image (see ImageHistory), only what
  // differs from the layer image is put back: the rectangles the image's
  // last frame wrote, and those the layer's updates since then changed.
  // Returns the rectangles drawn.
  std::vector<PixelRect> drawOverLayer(const DrawList& list, const std::vector<ViewItems>& perView,
                                       const std::vector<bool>& fresh, media::Image& image,
                                       const ImageHistory::State* history) {
    const std::vector<PixelRect> rects = dirtyRects(list, perView, fresh);
    stats.retainedPixels += static_cast<long long>(list.width) * list.height;
    for (const bool f : fresh) stats.freshViews += f ? 1 : 0;
    // A fresh view is read back whole below: its pixels in the layer are
    // not restored first (a follow camera's view, 5 MB at 1080p a frame).
    auto restore = [&](const PixelRect& r) {
      restoredParts.assign(1, r);
      outsideFreshViews(list, fresh, restoredParts);
      for (const PixelRect& part : restoredParts) copyPixels(layerImage, image, part);
    };
    if (history != nullptr && history->epoch == layerEpoch && history->version >= restorableFrom) {
      for (const PixelRect& r : history->written) restore(r);
      for (const auto& [version, changed] : layerUpdates)
        if (version > history->version)
          for (const PixelRect& r : changed) restore(r);
    } else if (std::find(fresh.begin(), fresh.end(), true) != fresh.end()) {
      restore(PixelRect{0, 0, list.width, list.height});
    } else {
      image.rgba = layerImage.rgba;  // same size: copies into the existing storage
    }
    underEverywhere = false;
    underRects = layerEdgeRects;
    redrawRects(list, perView, rects, Items::All, fresh, image);
    underEverywhere = true;
    long long area = 0;
    for (const PixelRect& r : rects) area += static_cast<long long>(r.x1 - r.x0) * (r.y1 - r.y0);
    stats.redrawnPixels += area;
    return rects;
  }

  std::vector<PixelRect> restoredParts;  // drawOverLayer's

  // `rects` less the rectangles of the fresh views (drawn whole).
  void outsideFreshViews(const DrawList& list, const std::vector<bool>& fresh, std::vector<PixelRect>& rects) {
    for (std::size_t i = 0; i < list.views.size(); ++i) {
      if (!fresh[i]) continue;
      const View& v = list.views[i];
      splitParts.clear();
      for (const PixelRect& r : rects) outside(r, PixelRect{v.x, v.y, v.x + v.width, v.y + v.height}, splitParts);
      std::swap(rects, splitParts);
    }
  }
  std::vector<PixelRect> splitParts;  // outsideFreshViews'

  // `r` of `from` into `to` (images of one size).
  static void copyPixels(const media::Image& from, media::Image& to, const PixelRect& r) {
    const std::size_t rowBytes = static_cast<std::size_t>(r.x1 - r.x0) * 4;
    for (int y = r.y0; y < r.y1; ++y) {
      const std::size_t at = (static_cast<std::size_t>(y) * from.width + r.x0) * 4;
      std::memcpy(to.rgba.data() + at, from.rgba.data() + at, rowBytes);
    }
  }

  // The layer brought up to date in place (see layerChanges): its
  // rectangles redrawn from the snapshot with the static items alone, as
  // buildLayer draws them whole. A checkpoint of a growing line then costs
  // about a frame over the layer instead of a frame drawn whole.
  // A fresh view is not drawn: its pixels in the layer become stale.
  void updateLayer(const DrawList& list, const std::vector<ViewItems>& perView, const std::vector<PixelRect>& rects,
                   const std::vector<bool>& fresh) {
    redrawRects(list, perView, rects, Items::StaticOnly, fresh, layerImage);
    ++stats.layerUpdates;
    layerUpdates.emplace_back(++layerVersion, rects);
    if (layerUpdates.size() > kLayerUpdatesKept) {
      restorableFrom = layerUpdates.front().first;  // an image at this version needs only the updates kept
      layerUpdates.pop_front();
    }
  }

  // Redraws `rects` (disjoint) of `image` from the snapshot on: the
  // dynamic opaque meshes when `which` takes them, then every later step.
  // A fresh view (its rectangle among `rects`) is cleared and drawn whole
  // instead, exactly as a whole frame draws it, when `which` takes the
  // dynamic items; a layer's update leaves it alone.
  void copyRects(const DrawList& list, GLuint from, GLuint to, const std::vector<PixelRect>& rects) {
    glDisable(GL_SCISSOR_TEST);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, from);
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, to);
    for (const PixelRect& r : rects) {
      const int y0 = list.height - r.y1, y1 = list.height - r.y0;
      glBlitFramebuffer(r.x0, y0, r.x1, y1, r.x0, y0, r.x1, y1, GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT,
                        GL_NEAREST);
    }
  }

  // `draw` for each view not drawn whole (`fresh`) once per island of
  // `rects` in it (see redrawRects), bound on `fbo` (0: the scene) and
  // scissored to the island, its meshes and lines clipped to the rects.
  template <typename Draw>
  void inIslands(const DrawList& list, const std::vector<ViewItems>& perView, const std::vector<PixelRect>& rects,
                 const std::vector<bool>& fresh, GLuint fbo, Draw draw) {
    std::vector<PixelRect> islandRects;
    for (std::size_t i = 0; i < list.views.size(); ++i) {
      if (fresh[i]) continue;
      const View& v = list.views[i];
      for (const PixelRect& island : separatedIslands(rects, PixelRect{v.x, v.y, v.x + v.width, v.y + v.height})) {
        islandRects.clear();
        for (const PixelRect& r : rects)
          if (overlaps(r, island)) islandRects.push_back(intersect(r, island));
        beginView(list, v, perView[i], &island, fbo);
        drawClips = &islandRects;
        clipView = &v;
        draw(perView[i]);
        drawClips = nullptr;
        clipView = nullptr;
      }
    }
  }

  // The moving meshes that are drawn in samples (arrows, see Pass), over a
  // retained layer, as drawViewOpaque draws them: at one sample over the
  // layer's scene, then in samples over the layer's static samples in the
  // tiles they reach (sampleTiles), island by island (as in redrawRects),
  // resolved there.
  void redrawSamples(const DrawList& list, const std::vector<ViewItems>& perView, const std::vector<bool>& fresh) {
    if (opaqueFbo == 0) return;
    std::vector<PixelRect> reached;  // inside the dirty rectangles: dirtyRects adds the same bounds
    for (std::size_t i = 0; i < list.views.size(); ++i) {
      if (fresh[i]) continue;
      const std::vector<PixelRect> tiles = sampleTiles(list, list.views[i], perView[i], Items::DynamicOnly);
      reached.insert(reached.end(), tiles.begin(), tiles.end());
    }
    if (reached.empty()) return;
    underRects.insert(underRects.end(), reached.begin(), reached.end());  // their edges are over the layer's
    inIslands(list, perView, reached, fresh, 0,
              [&](const ViewItems& items) { drawOpaqueAtCentres(items, Items::DynamicOnly); });
    copyRects(list, snapshotSamplesFbo, opaqueFbo, reached);
    inIslands(list, perView, reached, fresh, opaqueFbo,
              [&](const ViewItems& items) { drawOpaque(items, Items::DynamicOnly, Pass::Samples); });
    for (const PixelRect& r : reached) resolveOpaque(list, r);
  }

  void redrawRects(const DrawList& list, const std::vector<ViewItems>& perView, const std::vector<PixelRect>& rects,
                   Items which, const std::vector<bool>& fresh, media::Image& image) {
    if (rects.empty()) return;
    // The rectangles are disjoint: all copies first, then all draws, so the
    // binned scene is not flushed between them.
    // Unscissored: a blit copies every sample of the rectangle's pixels.
    // Not into a view drawn whole here: the scene is cleared first, with
    // one unscissored clear (a scissored clear of a 1080p view's 1 M pixels
    // is a quad draw: 6–7 ms, with each step finished apart), and those
    // views drawn over it.
    const bool anyFresh = which != Items::StaticOnly && std::find(fresh.begin(), fresh.end(), true) != fresh.end();
    if (!anyFresh) {
      copyRects(list, snapshotFbo, sceneFbo, rects);
    } else {
      clearScene(list, false);
      std::vector<PixelRect> kept = rects;
      outsideFreshViews(list, fresh, kept);
      copyRects(list, snapshotFbo, sceneFbo, kept);
    }
    if (which != Items::StaticOnly) redrawSamples(list, perView, fresh);
    // Then each view drawn once per island of its dirty rectangles (see
    // separatedIslands), scissored to the island's box: the pixels of a box
    // outside the rectangles are drawn over stale samples, but they are
    // neither composited nor read back, and the boxes are disjoint, so each
    // pixel gets the same draws in the same order as in a whole frame. A box
    // reaches a pixel beyond its rectangles (inside the view): llvmpipe tests
    // the scissor per sample, and a multisampled pixel on the scissor's edge
    // seems to lose samples that a whole frame draws (seen, when these steps
    // ran in samples: glass drawn scissor by scissor differed from a whole
    // frame along the row where two met; redrawSamples still draws so).
    PixelRect allBounds{list.width, list.height, 0, 0};
    std::vector<PixelRect> islandRects;
    for (std::size_t i = 0; i < list.views.size(); ++i) {
      const View& v = list.views[i];
      const PixelRect area{v.x, v.y, v.x + v.width, v.y + v.height};
      if (fresh[i]) {
        if (which == Items::StaticOnly) continue;
        std::vector<PixelRect> sampled = drawViewOpaque(list, v, perView[i], false);  // cleared with the scene
        beginView(list, v, perView[i], nullptr);
        drawViewAfterOpaque(list, static_cast<int>(i), perView[i], std::move(sampled));
        allBounds = unite(allBounds, area);
        continue;
      }
      for (const PixelRect& island : separatedIslands(rects, area)) {
        allBounds = unite(allBounds, island);
        islandRects.clear();
        for (const PixelRect& r : rects)
          if (overlaps(r, island)) islandRects.push_back(intersect(r, island));
        beginView(list, v, perView[i], &island);
        drawClips = &islandRects;
        clipView = &v;
        if (which != Items::StaticOnly) drawAfterResolve(perView[i]);
        drawRest(list, static_cast<int>(i), perView[i], which);
        drawClips = nullptr;
        clipView = nullptr;
      }
    }
    for (const PixelRect& r : rects) allBounds = unite(allBounds, r);
    drawImageLabels(list, which, allBounds);
    for (const PixelRect& r : rects) readBack(list, image, r);
  }

  void render(const DrawList& list, media::Image& image, ImageHistory::State* history = nullptr) {
    if (list.width <= 0 || list.height <= 0)
      throw badInput({}, "image size {}x{}: expected positive width and height", list.width, list.height);
    ensureFramebuffers(list.width, list.height, std::max(1, list.msaaSamples));
    // Shadow maps first: binding another framebuffer makes llvmpipe run the
    // scene binned so far, so a shadow pass between the scene's clear and its
    // draws would make the clear a separate trip through all the samples in
    // memory instead of a per-tile fill just before the tile is drawn.
    std::vector<ViewItems> perView(list.views.size());
    std::size_t shadowMapsUsed = 0;
    for (std::size_t i = 0; i < list.views.size(); ++i) {
      ViewItems& vi = perView[i];
      vi.arrowMaterials.reserve(list.arrows.size());
      vi.items = drawablesOf(list, static_cast<int>(i), vi.arrowMaterials);
      if (!list.views[i].light.shadow) continue;
      StageLog::instance().record("shadow-map");
      vi.shadowMap = &shadowMap(shadowMapsUsed++);
      vi.shadow = shadowPass(list.views[i], vi.items, *vi.shadowMap);
    }
    // Wait for the shadow maps to be drawn: a texture that a scene still in
    // flight renders into counts as busy, and binding it for sampling would
    // make llvmpipe flush the scene being binned in the middle of the frame
    // (measured: 10 ms of a 1080p frame, the main scene's tiles making two
    // trips through memory).
    if (shadowMapsUsed > 0) glFinish();
    image.width = list.width;
    image.height = list.height;
    // What the image holds, if its history knows; the history itself
    // forgets until this frame is done (a frame that throws halfway leaves
    // pixels it does not describe).
    const std::size_t bytes = static_cast<std::size_t>(list.width) * list.height * 4;
    ImageHistory::State known;
    if (history != nullptr) {
      if (image.rgba.size() == bytes && history->pixels == image.rgba.data()) known = std::move(*history);
      *history = {};
    }
    image.rgba.resize(bytes);  // reused across frames

    // A layer needs disjoint views (an inset's clear would come between
    // the views' steps) and pays off from the second frame that shares it.
    // When the frame before was drawn over a layer, the camera held still
    // and only static content changed (a growing line reached a checkpoint,
    // a caption changed): a new layer is built at once. Otherwise one is
    // built when a second frame shares it.
    //
    // A view whose camera moved while another held (a follow camera beside
    // a fixed twin) is "fresh": drawn whole inside a frame over the layer,
    // while the views that held use the layer.
    bool overLayer = false;
    std::vector<bool> fresh(list.views.size(), false);
    if (retainLayers && viewsDisjoint(list)) {
      // Whether `key` serves this list: some view held, and the held views'
      // static items are the key's or changed only as layerChanges allows.
      std::optional<std::vector<PixelRect>> changes;
      auto serves = [&](const StaticKey& key) {
        const std::optional<std::vector<bool>> f = freshViews(key, list);
        if (!f || std::find(f->begin(), f->end(), false) == f->end()) return false;
        changes = layerChanges(key, list, *f, itemBounds(list));
        if (changes) fresh = *f;
        return changes.has_value();
      };
      if (layerKey && sameStatic(*layerKey, list)) {
        overLayer = true;
      } else if (layerKey && serves(*layerKey)) {
        if (!changes->empty()) updateLayer(list, perView, *changes, fresh);
        std::vector<bool> stale = fresh;
        layerKey = staticKeyOf(list);
        layerKey->stale = std::move(stale);
        pendingKey.reset();
        overLayer = true;
      } else if ((pendingKey && serves(*pendingKey) && changes->empty()) || lastFrameOverLayer) {
        buildLayer(list, perView);
        layerKey = staticKeyOf(list);
        pendingKey.reset();
        fresh.assign(list.views.size(), false);
        overLayer = true;
      } else {
        pendingKey = staticKeyOf(list);
      }
    }
    lastFrameOverLayer = overLayer;
    if (overLayer) {
      std::vector<PixelRect> drawn = drawOverLayer(list, perView, fresh, image, history != nullptr ? &known : nullptr);
      if (history != nullptr) *history = {layerEpoch, layerVersion, std::move(drawn), image.rgba.data()};
      ++stats.retainedFrames;
    } else {
      releaseSphereCaptures();  // no layer: a camera move, most likely, which they would not survive
      clearScene(list, false);
      drawWhole(list, perView);
      readBack(list, image, PixelRect{0, 0, list.width, list.height});
      ++stats.wholeFrames;
    }
    if (const GLenum err = glGetError(); err != GL_NO_ERROR)
      throw runtimeError({}, "OpenGL error 0x{:x} while rendering a {}x{} image", err, list.width, list.height);

    // Per-frame meshes (arrows' materials aside, e.g. a rebuilt surface)
    // must not pile up across the frames of a video; the retained layer's
    // keep theirs alive through its key.
    for (auto it = meshes.begin(); it != meshes.end();) {
      if (!it->second.used && it->second.keepAlive != cylinder && it->second.keepAlive != cone) {
        release(it->second.gpu);
        it = meshes.erase(it);
      } else {
        it->second.used = false;
        ++it;
      }
    }
  }

  // Vector figures: the scene's depth after render() (one sample, at the
  // pixel centres: see drawOpaqueAtCentres).
  void readDepth(std::vector<float>& depth) {
    const int w = fbWidth, h = fbHeight;
    glBindFramebuffer(GL_READ_FRAMEBUFFER, sceneFbo);
    std::vector<float> bottomUp(static_cast<std::size_t>(w) * h);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
    glReadPixels(0, 0, w, h, GL_DEPTH_COMPONENT, GL_FLOAT, bottomUp.data());
    const GLenum err = glGetError();
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    if (err != GL_NO_ERROR) throw runtimeError({}, "OpenGL error 0x{:x} while reading back a {}x{} depth buffer", err, w, h);
    depth.resize(bottomUp.size());
    for (int y = 0; y < h; ++y)  // GL rows count from the bottom
      std::copy_n(bottomUp.begin() + std::ptrdiff_t(h - 1 - y) * w, w, depth.begin() + std::ptrdiff_t(y) * w);
  }
};

Renderer::Renderer(GlContext& /*context*/, const ShaderLibrary& shaders) : impl_(std::make_unique<Impl>(shaders)) {}
Renderer::~Renderer() = default;
media::Image Renderer::render(const DrawList& list) {
  media::Image image;
  impl_->render(list, image);
  return image;
}
void Renderer::render(const DrawList& list, media::Image& image) { impl_->render(list, image); }
void Renderer::render(const DrawList& list, media::Image& image, ImageHistory& history) {
  if (!history.state_) history.state_ = std::make_unique<ImageHistory::State>();
  impl_->render(list, image, history.state_.get());
}
void Renderer::renderWithDepth(const DrawList& list, media::Image& image, std::vector<float>& depth) {
  // The depth of this list alone, drawn whole: no retained layer in between.
  const bool retain = impl_->retainLayers;
  setRetainLayers(false);
  impl_->render(list, image);
  impl_->readDepth(depth);
  setRetainLayers(retain);
}

void Renderer::setRetainLayers(bool on) {
  impl_->retainLayers = on;
  if (!on) impl_->layerKey.reset(), impl_->pendingKey.reset(), impl_->lastFrameOverLayer = false;
}
const RenderStats& Renderer::stats() const { return impl_->stats; }

}  // namespace rollspin::render
