#include "evaluation/report/figure_drawing.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <fmt/format.h>

#include "evaluation/report/gnuplot_runner.hpp"

namespace radarpr {

namespace fs = std::filesystem;

void write_text_file(const fs::path& path, const std::string& content) {
  std::ofstream file(path, std::ios::binary);
  file << content;
  file.close();
  if (!file) throw std::runtime_error(fmt::format("{}: cannot write the file", path.string()));
}

std::string read_text_file(const fs::path& path) {
  std::ifstream file(path, std::ios::binary);
  std::stringstream text;
  text << file.rdbuf();
  return text.str();
}

std::vector<PageFigure> write_figures(const fs::path& folder,
                                      const std::vector<FigureFiles>& figures,
                                      const std::filesystem::path& final_folder,
                                      std::vector<std::string>& warnings) {
  fs::create_directories(folder);
  const auto gnuplot = find_gnuplot();
  if (!gnuplot) {
    warnings.push_back(fmt::format(
        "gnuplot not found: figures' data and scripts written to {}, install gnuplot to draw "
        "them",
        final_folder.string()));
  }
  std::vector<PageFigure> page;
  for (const auto& figure : figures) {
    write_text_file(folder / (figure.name + ".csv"), figure.csv);
    write_text_file(folder / (figure.name + ".gp"), figure.script);
    PageFigure shown{figure.name, figure.caption, std::nullopt};
    if (gnuplot) {
      const auto error = run_gnuplot(*gnuplot, folder, figure.name + ".gp");
      if (error) {
        warnings.push_back(
            fmt::format("{}: {}", (final_folder / (figure.name + ".gp")).string(), *error));
      } else if (fs::exists(folder / (figure.name + ".svg"))) {
        shown.svg = read_text_file(folder / (figure.name + ".svg"));
      }
    }
    page.push_back(std::move(shown));
  }
  return page;
}

}  // namespace radarpr
