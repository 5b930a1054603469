#include "evaluation/report/figure_style.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include <fmt/format.h>

#include "evaluation/report/figure_files.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

// One IEEE column; the PNG at 300 dpi, its fonts and lines scaled from 72 dpi to match the PDF.
constexpr double kColumnWidthIn = 3.5;
constexpr int kPaperPngDpi = 300;
constexpr double kPngScale = kPaperPngDpi / 72.0;
// The SVG at 100 px per inch; gnuplot's SVG font size is in px, so 8 pt is 11.1 px there.
constexpr int kSvgPxPerIn = 100;

// The paper key's text inside the plot: 7 pt, about 3.9 pt a character; it may take this many.
constexpr std::size_t kInsideKeyChars = 22;
constexpr std::size_t kInsideKeyRows = 5;
constexpr double kKeyRowIn = 11.0 / 72.0;
// Below the plot: the tick labels and the axis label, 8 pt each with their gaps (0.51 in as
// drawn by pdfcairo and pngcairo), and a gap above the key.
constexpr double kAxisLabelsIn = 0.58;
// The key below the plot starts this far from the left edge (as a fraction of the column).
// Anchored at the left, not centred: gnuplot centres the key by a width it estimates from the
// 8 pt terminal font, wider than the 7 pt key text, which pushed the first column off the page.
constexpr double kKeyLeft = 0.04;
// A 7 pt character as drawn (DejaVu Sans, the titles' mix of letters, digits and _=,): about
// 5 pt; the room a row has for its title after the line sample and the margins: 211 pt.
constexpr double kKeyCharPt = 5.0;
constexpr double kKeyTextRoomPt = 211.0;
constexpr double kKeyFontPt = 7.0;
constexpr double kKeyMinFontPt = 5.0;
// gnuplot's pitch between key columns, from its 8 pt estimate: (characters + 7) * 5.6 pt.
constexpr double kKeyColumnCharPt = 5.6;
constexpr double kKeyColumnExtraChars = 7.0;
constexpr double kKeyRoomPt = (1.0 - kKeyLeft) * kColumnWidthIn * 72.0;
constexpr std::size_t kMaxKeyColumns = 3;
// The same on the screen canvas, in px (12 px text).
constexpr double kScreenKeyRowPx = 19.0;
constexpr double kScreenAxisLabelsPx = 70.0;

}  // namespace

std::string paper_key(const std::string& corner, const std::vector<std::string>& titles,
                      FigureCanvas& canvas) {
  std::size_t longest = 0;
  for (const auto& title : titles) longest = std::max(longest, title.size());
  if (longest <= kInsideKeyChars && titles.size() <= kInsideKeyRows) {
    return fmt::format(
        "inside {} vertical Left reverse box opaque samplen 1.5 spacing 0.9 font ',7'", corner);
  }
  return key_below(titles, FigureStyle::paper, canvas);
}

std::string styled_key(FigureStyle style, const std::string& paper_corner,
                       const std::vector<std::string>& titles, FigureCanvas& canvas) {
  return style == FigureStyle::paper ? paper_key(paper_corner, titles, canvas)
                                     : "outside right top vertical Left reverse box";
}

std::string key_below(const std::vector<std::string>& titles, FigureStyle style,
                      FigureCanvas& canvas) {
  // Placed by hand, bottom margin and key alike: gnuplot's own `outside below` lets the key run
  // into the x axis label.
  if (style == FigureStyle::paper) {
    std::size_t longest = 0;
    for (const auto& title : titles) longest = std::max(longest, title.size());
    // As many columns as fit the column width side by side (short titles), else one, its font
    // made smaller (down to 5 pt) for a title longer than a row holds at 7 pt.
    const double pitch_pt =
        (static_cast<double>(longest) + kKeyColumnExtraChars) * kKeyColumnCharPt;
    const std::size_t columns =
        std::clamp<std::size_t>(static_cast<std::size_t>(kKeyRoomPt / pitch_pt), 1,
                                std::min(kMaxKeyColumns, std::max<std::size_t>(titles.size(), 1)));
    const std::size_t key_rows = (titles.size() + columns - 1) / columns;
    const double text_pt = static_cast<double>(longest) * kKeyCharPt;
    const double font_pt =
        text_pt <= kKeyTextRoomPt
            ? kKeyFontPt
            : std::max(kKeyMinFontPt, std::floor(kKeyFontPt * kKeyTextRoomPt / text_pt * 2) / 2);
    const double key_in = (static_cast<double>(key_rows) + 0.3) * kKeyRowIn;
    canvas.paper_height_in += key_in;
    return fmt::format(
        "at screen {}, screen {:.4f} left top vertical maxcols {} maxrows {} Left reverse nobox "
        "samplen 1.5 spacing 0.9 font ',{}'\nset bmargin at screen {:.4f}",
        kKeyLeft, key_in / canvas.paper_height_in, columns, key_rows, font_pt,
        (key_in + kAxisLabelsIn) / canvas.paper_height_in);
  }
  const double rows = static_cast<double>(titles.size()) + 0.3;
  const double key_px = rows * kScreenKeyRowPx;
  canvas.screen_height += static_cast<int>(key_px);
  const double height = canvas.screen_height;
  return fmt::format(
      "at screen 0.5, screen {:.4f} center top vertical maxcols 1 Left reverse box\n"
      "set bmargin at screen {:.4f}",
      key_px / height, (key_px + kScreenAxisLabelsPx) / height);
}

std::string figure_script(const std::string& name, const std::string& what,
                          const std::string& title, const std::string& settings,
                          const std::string& plot, FigureStyle style, const FigureCanvas& canvas) {
  // The name is written into the script unquoted-safe ('name.csv', a comment): only names made
  // by figure_stem (letters, digits, _ . = -) may get there, whatever a results folder holds.
  if (name.empty() || figure_stem(name) != name || name.front() == '-') {
    throw std::logic_error("figure name '" + printable(name) + "' is not a safe file name");
  }
  const bool paper = style == FigureStyle::paper;
  std::string svg, png, png_gd, pdf;
  if (paper) {
    const double h = canvas.paper_height_in;
    // Every font size scaled, the key's and labels' 7 pt too (a bare 'sans,11' made them 7 px).
    svg = fmt::format("size {},{} font 'sans,8' fontscale {:.3f}",
                      static_cast<int>(kColumnWidthIn * kSvgPxPerIn),
                      static_cast<int>(h * kSvgPxPerIn), kSvgPxPerIn / 72.0);
    // Lines as in the PDF, where a line width of 1 is 0.5 pt.
    png = fmt::format(
        "size {},{} font 'sans,8' fontscale {:.3f} linewidth {:.3f} pointscale {:.3f}",
        static_cast<int>(kColumnWidthIn * kPaperPngDpi), static_cast<int>(h * kPaperPngDpi),
        kPngScale, kPngScale / 2.0, kPngScale / 2.0);
    png_gd = fmt::format("size {},{}", static_cast<int>(kColumnWidthIn * kPaperPngDpi),
                         static_cast<int>(h * kPaperPngDpi));
    // pdfcairo halves font sizes by default (fontscale 0.5): 8 pt is asked for at scale 1.
    pdf = fmt::format("size {}in,{:.2f}in font 'sans,8' fontscale 1", kColumnWidthIn, h);
  } else {
    svg = fmt::format("size {},{} font 'sans,12'", canvas.screen_width, canvas.screen_height);
    png = fmt::format("size {},{} font 'sans,11'", canvas.screen_width, canvas.screen_height);
    png_gd = fmt::format("size {},{}", canvas.screen_width, canvas.screen_height);
    pdf = fmt::format("size {}in,{}in font 'sans,10' fontscale 1", canvas.screen_width / 100.0,
                      canvas.screen_height / 100.0);
  }
  return fmt::format(
      "# radarpr figure ({style} style): {what}.\n"
      "# Run `gnuplot {name}.gp` in this folder: it reads {name}.csv (blocks separated by two\n"
      "# blank lines, selected with `index`) and writes {name}.svg, {name}.png and {name}.pdf.\n"
      "set datafile separator comma\n"
      "set terminal svg {svg} background rgb 'white' noenhanced\n"
      "set output '{name}.svg'\n"
      "{title}"
      "{settings}"
      "{plot}\n"
      "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {{\n"
      "  set terminal pngcairo {png}\n"
      "}} else {{\n"
      "  set terminal png {png_gd}\n"
      "}}\n"
      "set output '{name}.png'\n"
      "replot\n"
      "# A gnuplot without cairo draws no PDF (the SVG and PNG are there).\n"
      "if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {{\n"
      "  set terminal pdfcairo {pdf} noenhanced\n"
      "  set output '{name}.pdf'\n"
      "  replot\n"
      "}}\n"
      "unset output\n",
      fmt::arg("style", to_string(style)), fmt::arg("what", what), fmt::arg("name", name),
      fmt::arg("svg", svg), fmt::arg("png", png + " background rgb 'white' noenhanced"),
      fmt::arg("png_gd", png_gd + " background rgb 'white' noenhanced"), fmt::arg("pdf", pdf),
      fmt::arg("title", paper ? std::string() : "set title " + gnuplot_string(title) + "\n"),
      fmt::arg("settings", settings), fmt::arg("plot", plot));
}

}  // namespace radarpr
