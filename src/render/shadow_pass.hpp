// Shadows: one shadow map per view that has a shadow, rendered before the
// scene (see Renderer::Impl::render), its box fitted to the casters.
// Renderer-internal.
#pragma once

#include <deque>
#include <vector>

#include "render/draw_scope.hpp"
#include "render/gpu_caches.hpp"
#include "render/programs.hpp"

namespace rollspin::render {

// The shadow box is fitted to the casters (see shadowPass), so a small map
// resolves a ball's shadow finely: at 256 texels a ball spans about 200 and
// the soft-shadow filter about 13 in radius.
inline constexpr int kShadowMapSize = 256;

class ShadowMaps {
 public:
  // The n-th shadow map, made on first use; it stays where it is.
  const ShadowMap& at(std::size_t n);

 private:
  std::deque<ShadowMap> maps_;
};

// Renders the view's shadow map of its items; what the receivers need to
// sample it.
ShadowSetup shadowPass(const View& v, const std::vector<Drawable>& items, const ShadowMap& map, GpuCaches& caches,
                       Programs& programs, const VertexStreams& streams);

}  // namespace rollspin::render
