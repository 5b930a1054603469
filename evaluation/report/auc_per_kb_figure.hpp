#pragma once

#include <string>
#include <vector>

#include "evaluation/config/report_config.hpp"
#include "evaluation/report/figure_files.hpp"
#include "evaluation/results/auc_size.hpp"

namespace radarpr {

// Information density (the ReFeree poster's case for tiny descriptors): each point of the
// AUC-against-size figure as a bar of its mean ROC AUC per kilobyte (1,024 bytes) of payload, on
// a log axis, in its descriptor's colour, the value written above it. Points without a defined
// AUC are left out. Drawn when the config asks for it (report.auc_per_kb).
FigureFiles auc_per_kb_figure(const std::string& name, const std::vector<AucSizePoint>& points,
                              FigureStyle style = FigureStyle::screen);

}  // namespace radarpr
