#pragma once

#include <string>
#include <vector>

#include "evaluation/config/report_config.hpp"  // FigureStyle

namespace radarpr {

// The figure's canvas: screen pixels (SVG and PNG; the PDF at 100 px per inch), or, in the paper
// style, the column width and this height in inches.
struct FigureCanvas {
  int screen_width = 900;
  int screen_height = 640;
  double paper_height_in = 2.6;
};

// The paper style's key: inside the plot at `corner` ("left bottom", "right bottom", ...) when
// its `titles` fit there (a few short ones), else below the plot with the canvas made taller for
// its rows. 7 pt text. Returns the `set key` arguments (and, below, a bottom margin setting
// after them on a line of its own).
std::string paper_key(const std::string& corner, const std::vector<std::string>& titles,
                      FigureCanvas& canvas);

// The key of a figure whose paper key goes inside at `paper_corner`: paper_key in the paper
// style, beside the plot on the right in the screen style. Returns the `set key` arguments.
std::string styled_key(FigureStyle style, const std::string& paper_corner,
                       const std::vector<std::string>& titles, FigureCanvas& canvas);

// A key below the plot, the canvas made taller for its rows; in either style. Screen: one title a
// line. Paper: from the left edge, in as many columns as the column width holds for the longest
// title (one for long titles, their font made smaller when a row cannot hold them at 7 pt).
// Returns the `set key` arguments and, on a line of its own, the bottom margin that keeps the
// axis label clear of it.
std::string key_below(const std::vector<std::string>& titles, FigureStyle style,
                      FigureCanvas& canvas);

// The one header and trailer of every figure script: `settings` (axes, labels, key; no title, no
// terminal) and `plot` (the full plot/splot command), drawn to <name>.svg, then the same plot as
// <name>.png (pngcairo when this gnuplot has it, else libgd's png) and <name>.pdf (pdfcairo, when
// this gnuplot has it), in the style's sizes and fonts. The title goes into the image in the
// screen style only (a paper's caption carries it). Throws std::logic_error for a name that is
// not a figure_stem.
std::string figure_script(const std::string& name, const std::string& what,
                          const std::string& title, const std::string& settings,
                          const std::string& plot, FigureStyle style, const FigureCanvas& canvas);

}  // namespace radarpr
