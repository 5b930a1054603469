#pragma once

#include <filesystem>
#include <optional>
#include <string>

namespace radarpr {

// The gnuplot program to draw with: $RADARPR_GNUPLOT when set (a path, or "off" for none), else
// the first executable `gnuplot` on $PATH.
struct GnuplotLookup {
  std::optional<std::filesystem::path> program;
  std::string why_none;  // when there is no program: "gnuplot is off (RADARPR_GNUPLOT=off)", ...
};
GnuplotLookup look_up_gnuplot();

// look_up_gnuplot().program.
std::optional<std::filesystem::path> find_gnuplot();

// Runs `gnuplot SCRIPT` with `folder` as the working directory (scripts read and write by
// relative path). Returns nothing on success, else what went wrong with gnuplot's stderr.
std::optional<std::string> run_gnuplot(const std::filesystem::path& gnuplot,
                                       const std::filesystem::path& folder,
                                       const std::string& script);

}  // namespace radarpr
