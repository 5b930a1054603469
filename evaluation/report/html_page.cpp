#include "evaluation/report/html_page.hpp"

#include <fmt/format.h>

#include "evaluation/results/table.hpp"

namespace radarpr {
namespace {

constexpr const char* kStyle = R"(
body { font-family: sans-serif; max-width: 1100px; margin: 2em auto; padding: 0 1em;
       color: #222; background: #fff; line-height: 1.4; }
h1 { font-size: 1.6em; } h2 { border-bottom: 1px solid #ccc; padding-bottom: 0.2em; }
table { border-collapse: collapse; margin: 0.5em 0 1.5em; font-size: 0.8em;
        display: block; overflow-x: auto; max-width: 100%; }  /* scroll only if still too wide */
th, td { border: 1px solid #ccc; padding: 0.2em 0.35em; }
td.num, th.num { white-space: nowrap; }  /* "F1-max", "0.912": one line, the columns narrow */
th { background: #f2f2f2; } td.num, th.num { text-align: right; }
figure { margin: 1em 0 2em; } figure img { max-width: 100%; height: auto; display: block; }
figcaption { font-size: 0.9em; color: #444; }
.missing { border: 1px dashed #c00; padding: 1em; color: #900; }
.warning { border-left: 4px solid #b60; padding: 0.3em 0.8em; background: #fff6e6; }
pre { background: #f6f6f6; padding: 0.6em; overflow-x: auto; font-size: 0.85em; }
code { font-size: 0.9em; }
)";

// A figure file's name as a relative URL path segment: figure names are safe names (letters,
// digits, "_-.=+", all allowed in a path segment), and anything else is percent-encoded all the
// same, so a name can never end the attribute or leave figures/.
std::string url_path_segment(const std::string& name) {
  std::string encoded;
  for (const unsigned char c : name) {
    const bool unreserved = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                            (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.' ||
                            c == '~' || c == '=' || c == '+';
    encoded += unreserved ? std::string(1, static_cast<char>(c)) : fmt::format("%{:02X}", c);
  }
  return encoded;
}

}  // namespace

std::string figure_html(const PageFigure& figure) {
  // The title once: in the image when it carries it, else in the caption.
  const std::string title =
      figure.drawn && figure.titled ? std::string() : html_escape(figure.caption) + " <br>";
  const std::string caption = fmt::format(
      "<figcaption>{}Data <code>figures/{}.csv</code>, script <code>figures/{}.gp</code>, "
      "images <code>figures/{}.svg</code>, <code>.png</code>{}.</figcaption>",
      title, html_escape(figure.name), html_escape(figure.name), html_escape(figure.name),
      figure.pdf ? " and <code>.pdf</code>" : "");
  if (!figure.drawn) {
    return fmt::format(
        "<figure id=\"{}\"><div class=\"missing\">Not drawn (gnuplot was not available or "
        "failed): run <code>gnuplot {}.gp</code> in <code>figures/</code>.</div>{}</figure>\n",
        html_escape(figure.name), html_escape(figure.name), caption);
  }
  return fmt::format("<figure id=\"{}\">\n<img src=\"figures/{}.svg\" alt=\"{}\">\n{}</figure>\n",
                     html_escape(figure.name), html_escape(url_path_segment(figure.name)),
                     html_escape(figure.caption), caption);
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
