#include "render/gpu_caches.hpp"

#include <algorithm>
#include <cmath>

#include "core/stage_log.hpp"

namespace rollspin::render {

namespace {

// Small enough that a run of a sphere's band spans a few degrees of it, large
// enough that testing the runs costs little beside drawing them.
constexpr std::size_t kChunkTriangles = 32;

GpuMesh upload(const MeshData& m) {
  GpuMesh g;
  g.vao = GlObject::generate(GlKind::VertexArray);
  g.vbo = GlObject::generate(GlKind::Buffer);
  g.ebo = GlObject::generate(GlKind::Buffer);
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

}  // namespace

const GpuMesh& GpuCaches::mesh(const std::shared_ptr<const MeshData>& m) {
  auto it = meshes_.find(m.get());
  if (it == meshes_.end()) it = meshes_.emplace(m.get(), CachedMesh{m, upload(*m), false, std::nullopt}).first;
  it->second.used = true;
  return it->second.gpu;
}

const MeshEdges& GpuCaches::edges(const std::shared_ptr<const MeshData>& m) {
  mesh(m);
  CachedMesh& cached = meshes_.at(m.get());
  if (!cached.edges) cached.edges = meshEdgesOf(*m);
  return *cached.edges;
}

GLuint GpuCaches::texture(const std::shared_ptr<const TextureImage>& t) {
  auto it = textures_.find(t.get());
  if (it != textures_.end()) return it->second.id;
  GlObject id = GlObject::generate(GlKind::Texture);
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
  return textures_.emplace(t.get(), CachedTexture{t, std::move(id)}).first->second.id;
}

GpuFont& GpuCaches::font(float sizePx, bool bold) {
  const auto key = std::make_pair(static_cast<int>(std::lround(sizePx)), bold);
  auto it = fonts_.find(key);
  if (it != fonts_.end()) return it->second;
  GpuFont f;
  StageLog::instance().record("font");
  f.atlas = std::make_unique<FontAtlas>(defaultFontFile(bold), static_cast<float>(key.first));
  f.texture = GlObject::generate(GlKind::Texture);
  glBindTexture(GL_TEXTURE_2D, f.texture);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, f.atlas->atlasWidth(), f.atlas->atlasHeight(), 0, GL_RED, GL_UNSIGNED_BYTE,
               f.atlas->coverage().data());
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return fonts_.emplace(key, std::move(f)).first->second;
}

void GpuCaches::evictUnused() {
  for (auto it = meshes_.begin(); it != meshes_.end();) {
    if (!it->second.used && it->second.keepAlive != cylinder && it->second.keepAlive != cone) {
      it = meshes_.erase(it);
    } else {
      it->second.used = false;
      ++it;
    }
  }
}

}  // namespace rollspin::render
