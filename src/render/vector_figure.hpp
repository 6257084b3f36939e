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
#include "media/output_metadata.hpp"
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
  media::Image opaque;             // opaque meshes over nothing, straight alpha
  std::vector<float> opaqueDepth;  // their window depth in [0, 1], top row first (empty: all 1)
  media::Image translucent;        // translucent meshes, alpha 0 where an opaque mesh is in front
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

// What a figure's layout puts where, in page points (origin top left, y
// down), from the same placement as writeFigure: for checking that text stays
// on its plate and labels off arrows and paths (tests, `--layout-json`).
struct FigureBox {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
};
struct FigureLayout {
  double widthPt = 0.0, heightPt = 0.0;
  struct Text {
    std::string text;
    FigureBox box;           // advance width × the font's ascent + descent
    glm::dvec2 anchor{0.0};  // the label's anchor (projected), before its offset
    bool free = false;       // a world-anchored label (axis, pole, mark number): on no plate
    int view = -1;
    double sizePt = 0.0;  // the printed em size (figure.font_size_pt for body text)
  };
  // A segment with the half width of what is drawn along it.
  struct Segment {
    glm::dvec2 a{0.0}, b{0.0};
    double halfWidth = 0.0;
  };
  std::vector<FigureBox> views;
  std::vector<FigureBox> plates;  // the text blocks' plates, and a view that draws only text (the title's band)
  std::vector<Text> texts;
  std::vector<Segment> arrows;  // each arrow as its shaft and its head
  std::vector<Segment> paths;   // the polylines labels keep off (PolylineItem::labelsKeepOff)
  // What the layout left out (DrawList::leftOut), each with the least
  // width and the largest body size at which it is kept (jobs/figure_job;
  // nullopt: none tried keeps it, or not searched).
  struct LeftOut {
    std::string text;
    std::optional<double> keptAtWidthMm, keptAtFontPt;
  };
  std::vector<LeftOut> leftOut;
};
[[nodiscard]] FigureLayout figureLayout(const DrawList& list, const FigureStyle& style);
// The layout as JSON (one object; boxes as [x0, y0, x1, y1]).
[[nodiscard]] std::string figureLayoutJson(const FigureLayout& layout);

// Writes the figure (temporary name, then rename). Runtime error when cairo
// cannot write it.
// `metadata`: also the title, description and scene (media/output_metadata.hpp;
// null: none). SOURCE_DATE_EPOCH, when set, is the PDF's creation date.
void writeFigure(const std::filesystem::path& out, FigureFormat format, const DrawList& list,
                 const FigureRasters& rasters, const FigureStyle& style,
                 const media::OutputMetadata* metadata = nullptr);

}  // namespace rollspin::render
