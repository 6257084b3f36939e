// Figure stills: `render --still -o fig.pdf | fig.svg` (or render.format =
// "pdf" / "svg") writes the still's DrawList as a publication figure through
// the vector backend (render/vector_figure). GL draws only the raster parts
// (the shaded meshes), at render.dpi over figure.width_mm; no encoder.
#pragma once

#include <filesystem>
#include <optional>

#include "draw/figure_text.hpp"
#include "media/output_format.hpp"
#include "render/draw_list.hpp"
#include "render/vector_figure.hpp"
#include "scene/scene_spec.hpp"

namespace rollspin::jobs {

// The figure a still's output-format row asks for (rows of kind Figure:
// "pdf", "svg"); nullopt for a raster still.
[[nodiscard]] std::optional<render::FigureFormat> figureFormatOf(const media::OutputFormat& format);

// Checks the figure keys that need the machine (the font is installed, the
// raster fits the renderer's limit) before anything is solved.
void checkFigureSpec(const scene::SceneSpec& spec);

// The body text size of a figure: figure.font_size_pt, else kDefaultFigureTextPt.
inline constexpr double kDefaultFigureTextPt = 8.0;
// No text of a figure prints smaller (journals print 6–7 pt at least).
inline constexpr double kLeastFigureTextPt = 6.0;
[[nodiscard]] double figureTextPt(const scene::SceneSpec& spec);

// True when the scene sets a [figure] key: its PNG still then keeps the
// figure's composition (fitTextToFigure), scaled.
[[nodiscard]] bool setsFigureKeys(const scene::SceneSpec& spec);

// Lays the still's text out for the figure's physical size: sets
// render.font_scale so that the body text, in the DrawList's pixels, is
// figureTextPt at figure.width_mm over render.width (plates, line steps and
// the free slots then follow the printed size), and returns the drawer's
// text policy: a figure's least text size. With --verbose (and `say`),
// prints the size.
[[nodiscard]] draw::FigureText fitTextToFigure(scene::SceneSpec& spec, bool say = true);

// The vector backend's style for the still's list: the page width, the
// font and the body size the list was laid out for.
[[nodiscard]] render::FigureStyle figureStyleOf(const scene::SceneSpec& spec, const render::DrawList& list);

// Renders the raster parts with GL (only when the list has meshes) and
// writes the figure to `out`.
// `metadata`: written into the figure (null: none).
void writeFigureStill(const scene::SceneSpec& spec, const render::DrawList& list, const std::filesystem::path& out,
                      render::FigureFormat format, const std::filesystem::path& shaderDir,
                      const media::OutputMetadata* metadata = nullptr);

}  // namespace rollspin::jobs
