#include "evaluation/report/html_page.hpp"

#include <fmt/format.h>

#include "evaluation/results/table.hpp"

namespace radarpr {
namespace {

constexpr const char* kStyle = R"(
body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em;
       color: #222; background: #fff; line-height: 1.4; }
h1 { font-size: 1.6em; } h2 { border-bottom: 1px solid #ccc; padding-bottom: 0.2em; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em; font-size: 0.9em;
        display: block; overflow-x: auto; max-width: 100%; }  /* wide tables scroll */
th, td { border: 1px solid #ccc; padding: 0.25em 0.6em; }
th { background: #f2f2f2; } td.num, th.num { text-align: right; }
figure { margin: 1em 0 2em; } figure svg { max-width: 100%; height: auto; display: block; }
figcaption { font-size: 0.9em; color: #444; }
.missing { border: 1px dashed #c00; padding: 1em; color: #900; }
.warning { border-left: 4px solid #b60; padding: 0.3em 0.8em; background: #fff6e6; }
pre { background: #f6f6f6; padding: 0.6em; overflow-x: auto; font-size: 0.85em; }
code { font-size: 0.9em; }
)";

// Prefixes every id and every local reference to one (#id, url(#id)) in gnuplot's SVG. gnuplot
// writes ids as ` id='x'` or ` id="x"` (after a space, which keeps "grid=" and the like out).
std::string prefix_ids(std::string svg, const std::string& prefix) {
  for (const std::string from : {" id='", " id=\"", "href='#", "href=\"#", "url(#"}) {
    const std::string to = from + prefix;
    for (std::size_t at = svg.find(from); at != std::string::npos;
         at = svg.find(from, at + to.size())) {
      svg.replace(at, from.size(), to);
    }
  }
  return svg;
}

}  // namespace

std::string figure_html(const PageFigure& figure, const std::string& id_prefix) {
  const std::string caption = fmt::format(
      "<figcaption>{} <br>Data <code>figures/{}.csv</code>, script <code>figures/{}.gp</code>, "
      "images <code>figures/{}.svg</code> and <code>.png</code>.</figcaption>",
      html_escape(figure.caption), html_escape(figure.name), html_escape(figure.name),
      html_escape(figure.name));
  if (!figure.svg) {
    return fmt::format(
        "<figure id=\"{}\"><div class=\"missing\">Not drawn (gnuplot was not available or "
        "failed): run <code>gnuplot {}.gp</code> in <code>figures/</code>.</div>{}</figure>\n",
        html_escape(figure.name), html_escape(figure.name), caption);
  }
  const std::string& svg = *figure.svg;
  const auto start = svg.find("<svg");
  const std::string body = start == std::string::npos ? svg : svg.substr(start);
  return fmt::format("<figure id=\"{}\">\n{}\n{}</figure>\n", html_escape(figure.name),
                     prefix_ids(body, id_prefix), caption);
}

std::string html_page(const std::string& title, const std::vector<PageSection>& sections) {
  std::string html = fmt::format(
      "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      "<meta name=\"viewport\" content=\"width=device-width, initial-scale=1\">\n"
      "<title>{}</title>\n<style>{}</style>\n</head>\n<body>\n<h1>{}</h1>\n",
      html_escape(title), kStyle, html_escape(title));
  html += "<nav><ul>\n";
  for (std::size_t i = 0; i < sections.size(); ++i) {
    html += fmt::format("<li><a href=\"#section-{}\">{}</a></li>\n", i,
                        html_escape(sections[i].heading));
  }
  html += "</ul></nav>\n";
  for (std::size_t i = 0; i < sections.size(); ++i) {
    html += fmt::format("<section id=\"section-{}\">\n<h2>{}</h2>\n{}</section>\n", i,
                        html_escape(sections[i].heading), sections[i].html);
  }
  return html + "</body>\n</html>\n";
}

}  // namespace radarpr
