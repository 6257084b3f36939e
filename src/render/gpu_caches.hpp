// The renderer's GPU caches, in one place: meshes (with their runs of
// triangles and their edges), textures and glyph atlases, uploaded on first
// use and kept across frames, keyed by the shared data they came from. A
// mesh that a frame's list no longer names is evicted after that frame.
// Renderer-internal.
#pragma once

#include <glm/glm.hpp>

#include <map>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "render/coverage_edges.hpp"
#include "render/draw_list.hpp"
#include "render/font_atlas.hpp"
#include "render/gl_objects.hpp"
#include "render/mesh_builders.hpp"

namespace rollspin::render {

// A run of a mesh's triangles, consecutive in its index buffer, and the
// bounding box of their corners in model coordinates.
struct MeshChunk {
  GLsizei firstIndex = 0, indexCount = 0;
  glm::vec3 lo{0.0f}, hi{0.0f};
};

struct GpuMesh {
  GlObject vao, vbo, ebo;
  GLsizei indexCount = 0;
  glm::vec4 bound{0.0f};          // a bounding sphere in model coordinates: centre, radius
  glm::vec3 lo{0.0f}, hi{0.0f};   // the bounding box in model coordinates
  std::vector<MeshChunk> chunks;  // the triangles in runs of kChunkTriangles, in index order
};

// A glyph atlas and its texture.
struct GpuFont {
  std::unique_ptr<FontAtlas> atlas;
  GlObject texture;
};

class GpuCaches {
 public:
  // The mesh's GPU copy, uploaded on first use; marked used by this frame.
  const GpuMesh& mesh(const std::shared_ptr<const MeshData>& m);
  // Its outline edges (coverage_edges.hpp), made on first use.
  const MeshEdges& edges(const std::shared_ptr<const MeshData>& m);
  GLuint texture(const std::shared_ptr<const TextureImage>& t);
  // The atlas of the font at sizePx rounded to whole pixels.
  GpuFont& font(float sizePx, bool bold);
  // After a frame: the meshes it did not use are released (per-frame meshes,
  // a rebuilt surface say, must not pile up across a video's frames); the
  // arrows' own two always stay.
  void evictUnused();

  // An arrow's shaft and head.
  const std::shared_ptr<MeshData> cylinder = unitCylinder(24), cone = unitCone(32);

 private:
  struct CachedMesh {
    std::shared_ptr<const MeshData> keepAlive;
    GpuMesh gpu;
    bool used = false;  // by the current frame; unused entries are evicted after it
    std::optional<MeshEdges> edges;
  };
  struct CachedTexture {
    std::shared_ptr<const TextureImage> keepAlive;
    GlObject id;
  };
  std::map<const MeshData*, CachedMesh> meshes_;
  std::map<const TextureImage*, CachedTexture> textures_;
  std::map<std::pair<int, bool>, GpuFont> fonts_;
};

}  // namespace rollspin::render
