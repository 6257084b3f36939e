// VectorFigure — a DrawList as a publication figure (PDF or SVG) through
// cairo: polylines, arrows and the inset's frame as vector paths, labels as
// real text (fontconfig + FreeType; cairo embeds a subset of the font), and
// only the shaded meshes as images, rendered by the GL renderer (FigureRasters)
// with alpha, so the page has no raster background. A depth-tested line is
// cut where the renderer's depth buffer puts an opaque mesh in front of it,
// and the translucent meshes (glass) are laid over the lines, as the GL
// image does. The DrawList stays plain data; this is a second backend.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "media/image_view.hpp"
#include "render/draw_list.hpp"

namespace rollspin::render {

enum class FigureFormat { Pdf, Svg };

struct FigureStyle {
  double widthPt = 120.0 / 25.4 * 72.0;  // page width; the height keeps the DrawList's aspect
  std::string font = "DejaVu Sans";      // fontconfig family of the labels
  // Body text: the labels of size bodyTextPx (DrawList pixels) are set at
  // bodyTextPt and the others in proportion. nullopt: as in the raster still.
  std::optional<double> bodyTextPt;
  float bodyTextPx = 16.0f;
  bool transparent = true;  // false: each view's backdrop gradient behind it
};

// What the GL renderer drew of a DrawList's meshes for a figure, at
// width × height pixels (the figure's resolution; the DrawList's views
// scaled). Empty images: no such meshes.
struct FigureRasters {
  int width = 0, height = 0;
  media::Image opaque;              // opaque meshes over nothing, straight alpha
  std::vector<float> opaqueDepth;   // their window depth in [0, 1], top row first (empty: all 1)
  media::Image translucent;         // translucent meshes, alpha 0 where an opaque mesh is in front
};

// The meshes the figure takes as raster, as a DrawList of their own at
// width × height: the views scaled, no backdrop, no lines, arrows or text.
enum class MeshLayer {
  Opaque,            // opacity 1
  Translucent,       // opacity < 1, as drawn
  TranslucentDepth,  // opacity < 1 drawn opaque, one sample: their nearest depth
};
[[nodiscard]] DrawList meshLayerOf(const DrawList& list, MeshLayer layer, int width, int height);
[[nodiscard]] bool hasMeshes(const DrawList& list, MeshLayer layer);

// Clears the translucent image where an opaque mesh is nearer than the
// nearest translucent surface (the GL renderer depth-tests glass against
// the opaque meshes).
void hideBehindOpaque(media::Image& translucent, const std::vector<float>& translucentDepth,
                      const std::vector<float>& opaqueDepth);

// The figure font's ascent + descent per em (regular face): a label of
// sizePx pixels is set at sizePx / this em.
[[nodiscard]] double figureFontHeightPerEm(const std::string& family);

// BadInput at `where` when fontconfig has no font of that family.
void checkFigureFont(const std::string& family, const SourceLoc& where);

// Writes the figure (temporary name, then rename). Runtime error when cairo
// cannot write it.
void writeFigure(const std::filesystem::path& out, FigureFormat format, const DrawList& list,
                 const FigureRasters& rasters, const FigureStyle& style);

}  // namespace rollspin::render
