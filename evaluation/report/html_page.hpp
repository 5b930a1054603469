#pragma once

#include <string>
#include <vector>

namespace radarpr {

// A figure as the page shows it: its SVG file (figures/<name>.svg) as an image, or, when it was
// not drawn, a note naming the data and script files.
struct PageFigure {
  std::string name;
  std::string caption;
  bool drawn = false;  // figures/<name>.svg exists, drawn by this report
  bool pdf = false;    // figures/<name>.pdf too (a gnuplot with pdfcairo)
  // The image shows `caption` as its title (the screen style): the page then does not repeat it.
  bool titled = false;
};

struct PageSection {
  std::string heading;
  std::string html;  // trusted markup built by the report (text in it is already escaped)
};

// One page: inline CSS, no script, no reference outside the results folder. Figures are linked
// from figures/ (not inlined: a study's page would otherwise carry every SVG twice, megabytes),
// so the page and its figures/ folder, opened from disk, render in any browser with no network.
// An SVG loaded as an image also runs no script and fetches nothing, whatever its text holds.
std::string html_page(const std::string& title, const std::vector<PageSection>& sections);

// A figure block: the image figures/<name>.svg with its caption, or the "not drawn" note.
std::string figure_html(const PageFigure& figure);

}  // namespace radarpr
