#include "evaluation/report/figure_drawing.hpp"

#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>

#include <fmt/format.h>

#include "evaluation/parallel.hpp"
#include "evaluation/report/gnuplot_runner.hpp"

namespace radarpr {

namespace fs = std::filesystem;

void write_text_file(const fs::path& path, const std::string& content) {
  std::ofstream file(path, std::ios::binary);
  file << content;
  file.close();
  if (!file) throw std::runtime_error(fmt::format("{}: cannot write the file", path.string()));
}

namespace {

// cairo writes the time of drawing into a PDF ("/CreationDate (D:20261128210304Z)"), so the same
// report drawn twice would differ. The entry is blanked with spaces of the same length (blank
// space is valid between a dictionary's entries, and no byte offset in the file moves), so that a
// figure's PDF, like its SVG and PNG, depends on its data alone.
void remove_pdf_date(const fs::path& pdf) {
  std::string text;
  {
    std::ifstream file(pdf, std::ios::binary);
    if (!file) return;
    text.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
  }
  const auto at = text.find("/CreationDate (");
  const auto end = at == std::string::npos ? at : text.find(')', at);
  if (end == std::string::npos) return;
  text.replace(at, end + 1 - at, end + 1 - at, ' ');
  write_text_file(pdf, text);
}

}  // namespace

std::vector<PageFigure> write_figures(const fs::path& folder,
                                      const std::vector<FigureFiles>& figures,
                                      const std::filesystem::path& final_folder,
                                      std::vector<std::string>& warnings) {
  fs::create_directories(folder);
  const GnuplotLookup lookup = look_up_gnuplot();
  const auto& gnuplot = lookup.program;
  if (!gnuplot) {
    warnings.push_back(fmt::format("{}: figures' data and scripts written to {}, not drawn",
                                   lookup.why_none, final_folder.string()));
  }
  // One gnuplot process per figure, several at once (default_thread_count()); each figure's
  // files and outcome are its own, so the result is the same in any order.
  std::vector<PageFigure> page(figures.size());
  std::vector<std::optional<std::string>> errors(figures.size());
  parallel_for(figures.size(), 0, [&](std::size_t i) {
    const FigureFiles& figure = figures[i];
    write_text_file(folder / (figure.name + ".csv"), figure.csv);
    write_text_file(folder / (figure.name + ".gp"), figure.script);
    page[i] = PageFigure{figure.name, figure.caption, false};
    // figure_script titles the image in the screen style only, with this one line.
    page[i].titled = figure.script.find("\nset title ") != std::string::npos;
    if (!gnuplot) return;
    errors[i] = run_gnuplot(*gnuplot, folder, figure.name + ".gp");
    page[i].drawn = !errors[i] && fs::exists(folder / (figure.name + ".svg"));
    page[i].pdf = page[i].drawn && fs::exists(folder / (figure.name + ".pdf"));
    if (page[i].pdf) remove_pdf_date(folder / (figure.name + ".pdf"));
  });
  for (std::size_t i = 0; i < figures.size(); ++i) {
    if (errors[i]) {
      warnings.push_back(
          fmt::format("{}: {}", (final_folder / (figures[i].name + ".gp")).string(), *errors[i]));
    }
  }
  return page;
}

void remove_stale_images(const fs::path& folder, const std::vector<PageFigure>& figures,
                         std::vector<std::string>& warnings) {
  for (const auto& figure : figures) {
    for (const char* extension : {".svg", ".png", ".pdf"}) {
      // A PDF is drawn only by a gnuplot with pdfcairo: one drawn earlier by another is stale.
      const bool drawn = std::string(extension) == ".pdf" ? figure.pdf : figure.drawn;
      if (drawn) continue;
      const fs::path image = folder / (figure.name + extension);
      std::error_code error;
      fs::remove(image, error);
      if (error) {
        warnings.push_back(
            fmt::format("{}: an image older than its data, and it cannot be "
                        "removed ({})",
                        image.string(), error.message()));
      }
    }
  }
}

}  // namespace radarpr
