// The renderer's GPU caches (gpu_caches.cpp): a mesh uploaded once with its
// bounds and its runs of triangles, evicted after a frame that did not use
// it; textures with their mipmaps; glyph atlases by whole-pixel size.
#include <gtest/gtest.h>

#include <array>
#include <memory>
#include <vector>

#include "gl_queries.hpp"
#include "render/gpu_caches.hpp"
#include "renderer_fixture.hpp"

namespace rollspin::render {
namespace {

TEST_F(GlContextTest, AMeshIsUploadedOnceWithItsBoundsAndItsTrianglesInRuns) {
  GpuCaches caches;
  const std::shared_ptr<const MeshData> sphere = uvSphere(24, 12);
  const GpuMesh& gpu = caches.mesh(sphere);
  EXPECT_EQ(&caches.mesh(sphere), &gpu);
  EXPECT_EQ(std::size_t(gpu.indexCount), sphere->indices.size());
  EXPECT_NEAR(gpu.lo.x, -1.0f, 1e-6f);
  EXPECT_NEAR(gpu.hi.z, 1.0f, 1e-6f);
  EXPECT_NEAR(gpu.bound.w, 1.0f, 1e-5f);  // the unit sphere's own
  EXPECT_NEAR(glm::length(glm::vec3(gpu.bound)), 0.0f, 1e-6f);
  // The runs cover the index buffer in order, at most 32 triangles each,
  // and each run's box holds its triangles' corners and no more.
  GLsizei next = 0;
  for (const MeshChunk& c : gpu.chunks) {
    EXPECT_EQ(c.firstIndex, next);
    EXPECT_LE(c.indexCount, 3 * 32);
    EXPECT_EQ(c.indexCount % 3, 0);
    glm::vec3 lo(1e9f), hi(-1e9f);
    for (GLsizei i = c.firstIndex; i < c.firstIndex + c.indexCount; ++i) {
      lo = glm::min(lo, sphere->vertices[sphere->indices[std::size_t(i)]].position);
      hi = glm::max(hi, sphere->vertices[sphere->indices[std::size_t(i)]].position);
    }
    EXPECT_EQ(c.lo, lo);
    EXPECT_EQ(c.hi, hi);
    next += c.indexCount;
  }
  EXPECT_EQ(next, gpu.indexCount);
  // The vertices as drawn: position, normal and uv of each, in order.
  std::vector<Vertex> uploaded(sphere->vertices.size());
  TEST_GL(glGetNamedBufferSubData)(gpu.vbo, 0, GLsizeiptr(uploaded.size() * sizeof(Vertex)), uploaded.data());
  EXPECT_EQ(uploaded.back().position, sphere->vertices.back().position);
  EXPECT_EQ(uploaded.back().uv, sphere->vertices.back().uv);
}

TEST_F(GlContextTest, AMeshAFrameDidNotUseIsReleasedAfterItButTheArrowsStay) {
  GpuCaches caches;
  std::shared_ptr<const MeshData> kept = uvSphere(8, 4), dropped = uvSphere(8, 4);
  const GLuint keptArray = caches.mesh(kept).vao, droppedArray = caches.mesh(dropped).vao;
  const GLuint cylinderArray = caches.mesh(caches.cylinder).vao;
  EXPECT_EQ(dropped.use_count(), 2);  // the cache holds it alive
  caches.evictUnused();               // the first frame used all three
  EXPECT_TRUE(TEST_GL(glIsVertexArray)(droppedArray));

  (void)caches.mesh(kept);  // the second frame uses one
  caches.evictUnused();
  EXPECT_TRUE(TEST_GL(glIsVertexArray)(keptArray));
  EXPECT_TRUE(TEST_GL(glIsVertexArray)(cylinderArray));
  EXPECT_FALSE(TEST_GL(glIsVertexArray)(droppedArray));
  EXPECT_EQ(dropped.use_count(), 1);
  // Used again: uploaded anew.
  EXPECT_TRUE(TEST_GL(glIsVertexArray)(caches.mesh(dropped).vao));
}

TEST_F(GlContextTest, AMeshsEdgesAreMadeOnceAndKeepItInUse) {
  GpuCaches caches;
  const std::shared_ptr<const MeshData> sphere = uvSphere(12, 6);
  const MeshEdges& edges = caches.edges(sphere);
  EXPECT_EQ(&caches.edges(sphere), &edges);
  EXPECT_EQ(edges.vertices.size(), meshEdgesOf(*sphere).vertices.size());
  caches.evictUnused();  // edges() uploaded and used the mesh
  EXPECT_EQ(sphere.use_count(), 2);
}

TEST_F(GlContextTest, ATextureIsUploadedOnceWithEveryMipLevel) {
  GpuCaches caches;
  auto image = std::make_shared<TextureImage>();
  image->width = 8;
  image->height = 2;
  for (int i = 0; i < 16; ++i)
    image->rgba.insert(image->rgba.end(), {std::uint8_t(16 * i), std::uint8_t(255 - 16 * i), 7, 255});
  const GLuint name = caches.texture(image);
  EXPECT_EQ(caches.texture(image), name);
  GLint levels = 0, format = 0;
  TEST_GL(glGetTextureParameteriv)(name, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
  TEST_GL(glGetTextureLevelParameteriv)(name, 0, GL_TEXTURE_INTERNAL_FORMAT, &format);
  EXPECT_EQ(levels, 4);  // 8×2, 4×1, 2×1, 1×1
  EXPECT_EQ(format, GL_SRGB8_ALPHA8);
  // Row 0 of the image is row 0 of the texture, byte for byte.
  std::vector<std::uint8_t> back(image->rgba.size());
  TEST_GL(glGetTextureImage)(name, 0, GL_RGBA, GL_UNSIGNED_BYTE, GLsizei(back.size()), back.data());
  EXPECT_EQ(back, image->rgba);
}

TEST_F(GlContextTest, AFontAtlasIsKeptPerWholePixelSizeAndWeight) {
  GpuCaches caches;
  GpuFont& twelve = caches.font(12.4f, false);
  EXPECT_EQ(&caches.font(11.6f, false), &twelve);
  EXPECT_NE(&caches.font(12.0f, true), &twelve);
  EXPECT_NE(&caches.font(13.0f, false), &twelve);
  EXPECT_EQ(twelve.atlas->pixelHeight(), 12.0f);
  GLint width = 0, height = 0;
  TEST_GL(glGetTextureLevelParameteriv)(twelve.texture, 0, GL_TEXTURE_WIDTH, &width);
  TEST_GL(glGetTextureLevelParameteriv)(twelve.texture, 0, GL_TEXTURE_HEIGHT, &height);
  EXPECT_EQ(width, twelve.atlas->atlasWidth());
  EXPECT_EQ(height, twelve.atlas->atlasHeight());
}

}  // namespace
}  // namespace rollspin::render
