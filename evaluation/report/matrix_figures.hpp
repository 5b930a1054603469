#pragma once

#include <string>
#include <vector>

#include "evaluation/report/figure_files.hpp"
#include "evaluation/report/html_page.hpp"
#include "evaluation/results/results_reader.hpp"

namespace radarpr {

// The figures of the session matrices a run holds (summary.json "matrices"): per matrix and
// descriptor a heat map of Recall@1 and one of ROC AUC (query session down, database session
// across; an undefined value and the diagonal left blank), and per matrix and metric a box plot
// of the per-pair values, one box per descriptor. Names start with "matrix_". None without a
// matrix. Throws ResultsError for a malformed "matrices" entry or a pair without its rows.
std::vector<FigureFiles> matrix_figures(const RunResults& run,
                                        FigureStyle style = FigureStyle::screen);

// The report page's section on the matrices (empty when there are none): the figures
// matrix_figures made, per matrix.
std::string matrix_section_html(const RunResults& run, const std::vector<PageFigure>& figures);

}  // namespace radarpr
