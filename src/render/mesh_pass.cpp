// The mesh pass: the lit meshes of a view (its MeshItems and its arrows),
// the opaque ones in samples or at one sample, the receivers' re-shade in
// the shadow box, the translucent ones (see drawRest). A sphere drawn at
// one sample is handed to the ray cast (sphere_pass.cpp).
#include "render/mesh_pass.hpp"

#include <glm/gtc/matrix_inverse.hpp>

#include <algorithm>

#include "render/mesh_builders.hpp"

namespace rollspin::render {

namespace {

// Whether `d` is drawn as a ray-cast sphere: at one sample (with more, the
// samples antialias its triangles' edges), whole (no cut-away, not the
// re-shade's clipped part), in a view whose camera sphereBounds
// understands; its screen rectangle if so.
std::optional<PixelRect> impostorRect(const Drawable& d, const DrawScope& scope, bool clipToShadowBox) {
  const Material& m = *d.material;
  if (!d.sphere || scope.samples != 1 || clipToShadowBox || scope.view == nullptr ||
      m.cutPlane != glm::vec4(0.0f, 0.0f, 0.0f, 1.0f))
    return std::nullopt;
  return sphereBounds(*scope.view, glm::vec3(d.worldFromModel[3]), glm::length(glm::vec3(d.worldFromModel[0])),
                      kImpostorMarginPx);
}

}  // namespace

std::array<glm::vec3, 8> boxCorners(const glm::vec3& lo, const glm::vec3& hi, const glm::mat4& transform) {
  std::array<glm::vec3, 8> corners;
  for (int k = 0; k < 8; ++k)
    corners[std::size_t(k)] =
        glm::vec3(transform * glm::vec4(k & 1 ? hi.x : lo.x, k & 2 ? hi.y : lo.y, k & 4 ? hi.z : lo.z, 1.0f));
  return corners;
}

ClipDistances::ClipDistances() {
  for (GLenum plane = 0; plane < 5; ++plane) glEnable(GL_CLIP_DISTANCE0 + plane);
}
ClipDistances::~ClipDistances() {
  for (GLenum plane = 0; plane < 5; ++plane) glDisable(GL_CLIP_DISTANCE0 + plane);
}

// The view's camera and light are read from the view itself.
void setMeshUniforms(Program& mesh, const Drawable& d, const DrawScope& scope, bool clipToShadowBox) {
  const Material& m = *d.material;
  const View& v = *scope.view;
  mesh.set("clipFromWorld", scope.clipFromWorld);
  mesh.set("lightClipFromWorld", scope.shadow.lightClipFromWorld);
  mesh.set("towardLight", glm::normalize(v.light.towardLight));
  mesh.set("lightColor", v.light.color);
  mesh.set("ambient", v.light.ambient);
  mesh.set("cameraPosition", v.camera.position);
  mesh.set("albedoTexture", 0);
  mesh.set("shadowMap", 1);
  mesh.set("shadowFilterRadius", scope.shadow.filterRadius);
  mesh.set("cutPlane", m.cutPlane);
  mesh.set("cutCone", m.cutCone);
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

std::vector<Drawable> drawablesOf(const DrawList& list, int view, std::vector<Material>& arrowMaterials,
                                  GpuCaches& caches) {
  std::vector<Drawable> out;
  for (const MeshItem& m : list.meshes)
    if (m.view == view && m.mesh) out.push_back({m.mesh, m.worldFromModel, &m.material, m.dynamic, m.sphere});
  for (const ArrowItem& a : list.arrows) {
    if (a.view != view) continue;
    if (glm::length(a.tip - a.origin) <= 0.0f) continue;
    const ArrowParts parts = arrowParts(a.origin, a.tip, a.shaftRadius);
    Material& mat = arrowMaterials.emplace_back();
    mat.color = a.color;
    mat.specular = kArrowSpecular;
    mat.shininess = kArrowShininess;
    out.push_back({caches.cylinder, parts.shaft, &mat, a.dynamic, false, true});
    out.push_back({caches.cone, parts.head, &mat, a.dynamic, false, true});
  }
  // Every mesh the list names stays cached, also one a retained frame does
  // not draw (evicting it would re-upload it at the next layer build).
  for (const Drawable& d : out) caches.mesh(d.mesh);
  return out;
}

void MeshPass::draw(const Drawable& d, const DrawScope& scope, bool shadowOn, Cull cull, const MeshDrawing& with,
                    bool clipToShadowBox) {
  Programs& programs = with.programs;
  GpuCaches& caches = with.caches;
  const Material& m = *d.material;
  int pattern = m.pattern == Pattern::Checker ? 1 : m.pattern == Pattern::SolidChecker ? 3 : 0;
  if (m.pattern == Pattern::Texture && m.texture) {
    pattern = 2;
    glActiveTexture(GL_TEXTURE0);
    glBindTexture(GL_TEXTURE_2D, caches.texture(m.texture));
  }
  const std::optional<PixelRect> impostor = impostorRect(d, scope, clipToShadowBox);
  // Depth alone (drawOpaqueAtCentres) needs no shading; a ray-cast
  // sphere's depth comes from its fragment stage.
  // (A porthole is cut in the depth pass too: the shading program, whose
  // colour the pass does not write.)
  const bool coneCut = m.cutCone.w > 0.0f && !impostor;
  Program& mesh = scope.depthOnly && !impostor && !coneCut
                      ? programs.depth
                      : programs.mesh(pattern, shadowOn && m.lit, m.lit, m.specular > 0.0f, impostor ? 1 : 0,
                                      d.litPerVertex, false, coneCut);
  mesh.use();
  setMeshUniforms(mesh, d, scope, clipToShadowBox);
  if (impostor) {
    spheres_.draw(
        d, scope, mesh, *impostor, pattern, shadowOn && m.lit,
        SphereDrawing{programs, with.streams, with.captures, with.stats, with.targets.width, with.targets.height});
    return;
  }
  if (cull == Cull::None) {
    glDisable(GL_CULL_FACE);
  } else {
    glEnable(GL_CULL_FACE);
    glCullFace(cull == Cull::Back ? GL_BACK : GL_FRONT);
  }
  const GpuMesh& g = caches.mesh(d.mesh);
  glBindVertexArray(g.vao);
  if (scope.clips == nullptr || g.chunks.size() < 2) {
    glDrawElements(GL_TRIANGLES, g.indexCount, GL_UNSIGNED_INT, nullptr);
    return;
  }
  // Inside a retained frame's rectangles, only the runs of triangles whose
  // screen bounds reach one: llvmpipe transforms, sets up and bins every
  // triangle of a draw however much the scissor leaves of it (a surface's
  // thousands for its re-shade box, the Bloch glass's for the twin's
  // arrows). The runs left out cover no pixel of the rectangles, and the
  // rest are drawn in their order: the rectangles' bytes do not change.
  runs_.draw(g, scope.clipFromWorld * d.worldFromModel, scope, with.stats);
}

void MeshRuns::draw(const GpuMesh& g, const glm::mat4& clipFromModel, const DrawScope& scope, RenderStats& stats) {
  RunsOfParts& kept = kept_;
  kept.clear();
  for (const MeshChunk& c : g.chunks) {
    const std::array<glm::vec3, 8> corners = boxCorners(c.lo, c.hi);
    if (reachesAny(*scope.clips, screenBounds(*scope.view, clipFromModel, corners.data(), 8, 2.0f)))
      kept.add(c.firstIndex, c.firstIndex + c.indexCount);
  }
  // The runs go to GL in one call: a draw call costs llvmpipe more than a
  // run of triangles.
  counts_.clear();
  offsets_.clear();
  for (const RunsOfParts::Run& r : kept.runs()) {
    counts_.push_back(static_cast<GLsizei>(r.end - r.begin));
    offsets_.push_back(reinterpret_cast<const void*>(r.begin * sizeof(std::uint32_t)));
    stats.meshIndicesDrawn += static_cast<long long>(r.end - r.begin);
  }
  stats.meshIndicesInRects += g.indexCount;
  if (!counts_.empty())
    glMultiDrawElements(GL_TRIANGLES, counts_.data(), GL_UNSIGNED_INT, offsets_.data(),
                        static_cast<GLsizei>(counts_.size()));
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
//
// Not in a static layer (the shadow moves with the ball), right after the
// resolve: before the ray-cast spheres, whose edges blend over the
// shadowed surface (drawn after them, a re-shade would miss the pixels
// that a sphere's edge covers in part, and leave them lit).
void MeshPass::drawReshades(const ViewItems& viewItems, const DrawScope& scope, const MeshDrawing& with) {
  if (viewItems.shadowMap == nullptr) return;
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  {
    const ClipDistances clipped;
    for (const Drawable& d : viewItems.items) {
      if (d.material->opacity < 1.0f || !d.material->receivesShadow) continue;
      glEnable(GL_POLYGON_OFFSET_FILL);
      glPolygonOffset(-1.0f, -4.0f);
      glEnable(GL_BLEND);
      glBlendFuncSeparate(GL_DST_ALPHA, GL_ZERO, GL_ZERO, GL_ONE);
      draw(d, scope, true, d.material->cull, with, true);
      glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
      glDisable(GL_BLEND);
      glDisable(GL_POLYGON_OFFSET_FILL);
    }
  }
  glDisable(GL_CULL_FACE);
}

// The opaque meshes; receivers without the shadow filter (see drawReshades).
void MeshPass::drawOpaque(const ViewItems& viewItems, const DrawScope& scope, Items which, Pass pass,
                          const MeshDrawing& with) {
  glDisable(GL_BLEND);
  glDepthMask(GL_TRUE);
  {
    const ClipDistances clipped;
    for (const Drawable& d : viewItems.items)
      if (d.material->opacity >= 1.0f && takes(which, d.dynamic) &&
          inSamplesPass(d, with.targets) == (pass == Pass::Samples))
        draw(d, scope, false, d.material->cull, with);
  }
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
void MeshPass::drawOpaqueAtCentres(const ViewItems& viewItems, const DrawScope& scope, Items which,
                                   const MeshDrawing& with) {
  DrawScope asSamples = scope;
  asSamples.samples = with.targets.samples;
  asSamples.depthOnly = which == Items::DynamicOnly && with.targets.opaqueFbo != 0;
  if (asSamples.depthOnly) glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
  drawOpaque(viewItems, asSamples, which, Pass::Samples, with);
  if (asSamples.depthOnly) glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
}

}  // namespace rollspin::render
