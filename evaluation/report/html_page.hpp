#pragma once

#include <optional>
#include <string>
#include <vector>

namespace radarpr {

// A figure as the page shows it: the SVG inlined, or, when it was not drawn, a note naming the
// data and script files.
struct PageFigure {
  std::string name;
  std::string caption;
  std::optional<std::string> svg;  // the file's text
};

struct PageSection {
  std::string heading;
  std::string html;  // trusted markup built by the report (text in it is already escaped)
};

// One self-contained page: inline CSS, inline SVG, no script, no external reference. Opened from
// disk it renders in any browser with no network.
std::string html_page(const std::string& title, const std::vector<PageSection>& sections);

// A figure block. The SVG loses its XML prologue and gets its ids prefixed with `id_prefix`, so
// that gnuplot's identical ids (gpPt0, gnuplot_canvas...) stay unique across inlined figures.
std::string figure_html(const PageFigure& figure, const std::string& id_prefix);

}  // namespace radarpr
