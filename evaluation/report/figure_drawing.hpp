#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "evaluation/report/figure_files.hpp"
#include "evaluation/report/html_page.hpp"

namespace radarpr {

// Writes each figure's csv and gp into `folder` (a staging folder that becomes `final_folder`,
// the name warnings use) and, when gnuplot is found, draws its svg, png and (with pdfcairo) pdf
// there. Never throws for a plotting problem: a missing gnuplot is one warning, a failed
// script one warning naming it; the data is written either way. Throws std::runtime_error
// when the folder cannot be written.
std::vector<PageFigure> write_figures(const std::filesystem::path& folder,
                                      const std::vector<FigureFiles>& figures,
                                      const std::filesystem::path& final_folder,
                                      std::vector<std::string>& warnings);

// Removes the images (svg, png, pdf) in `folder` that were not drawn this time: the figure's data
// and script were just rewritten, so an image from an earlier drawing no longer shows them. A
// file that cannot be removed is a warning naming it.
void remove_stale_images(const std::filesystem::path& folder,
                         const std::vector<PageFigure>& figures,
                         std::vector<std::string>& warnings);

// Writes `content` to `path`, throwing std::runtime_error naming the file on failure.
void write_text_file(const std::filesystem::path& path, const std::string& content);

}  // namespace radarpr
