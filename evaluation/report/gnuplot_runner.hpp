#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace radarpr {

// The gnuplot program to draw with: $RADARPR_GNUPLOT when set (a path; "off" or a missing file
// means none), else the first executable `gnuplot` on $PATH. Empty when there is none.
std::optional<std::filesystem::path> find_gnuplot();

// Runs `gnuplot SCRIPT` with `folder` as the working directory (scripts read and write by
// relative path). Returns nothing on success, else what went wrong with gnuplot's stderr.
std::optional<std::string> run_gnuplot(const std::filesystem::path& gnuplot,
                                       const std::filesystem::path& folder,
                                       const std::string& script);

}  // namespace radarpr
