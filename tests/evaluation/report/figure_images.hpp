#pragma once

// What a drawn figure's image files say about themselves: a PDF's page size (from its MediaBox,
// after checking it starts as a PDF and ends with %%EOF; and from `pdfinfo` too when poppler's
// is installed) and a PNG's pixel size (from its IHDR chunk).
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <optional>
#include <regex>
#include <string>
#include <utility>

#include "evaluation/report/gnuplot_runner.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr::testing {

// Width and height in points, or nothing when `pdf` is missing or not a whole PDF.
inline std::optional<std::pair<double, double>> pdf_page(const std::filesystem::path& pdf) {
  const std::string text = read_text(pdf);
  if (text.rfind("%PDF-", 0) != 0) return std::nullopt;
  // A PDF ends with %%EOF (and maybe a line end): a cut-short file does not.
  if (text.find("%%EOF", text.size() > 8 ? text.size() - 8 : 0) == std::string::npos) {
    return std::nullopt;
  }
  std::smatch match;
  if (!std::regex_search(text, match,
                         std::regex(R"(/MediaBox \[ *0 +0 +([0-9.]+) +([0-9.]+) *\])"))) {
    return std::nullopt;
  }
  return std::make_pair(std::stod(match[1]), std::stod(match[2]));
}

// Whether the gnuplot radarpr finds has the pdfcairo terminal (Debian's gnuplot-nox has).
inline bool has_pdfcairo() {
  const auto gnuplot = find_gnuplot();
  if (!gnuplot) return false;
  const std::filesystem::path folder = scratch_folder("pdfcairo_probe");
  std::ofstream(folder / "probe.gp")
      << "if (strstrt(GPVAL_TERMINALS, 'pdfcairo') == 0) exit status 3\n";
  const bool has = !run_gnuplot(*gnuplot, folder, "probe.gp");
  std::filesystem::remove_all(folder);
  return has;
}

inline bool has_pdfinfo() {
  return run_command_line("pdfinfo -v >/dev/null 2>&1").exit_code == 0;
}

// pdfinfo's "Page size:" line ("252 x 340 pts"), or nothing when it refuses the file.
inline std::optional<std::string> pdfinfo_page_size(const std::filesystem::path& pdf) {
  const CommandResult result = run_command_line("pdfinfo '" + pdf.string() + "' 2>&1");
  if (result.exit_code != 0) return std::nullopt;
  std::smatch match;
  if (!std::regex_search(result.output, match,
                         std::regex(R"(Page size: +([0-9.]+ x [0-9.]+) pts)"))) {
    return std::nullopt;
  }
  return match[1].str();
}

// Width and height in pixels, or nothing when `png` is not a PNG.
inline std::optional<std::pair<std::uint32_t, std::uint32_t>> png_size(
    const std::filesystem::path& png) {
  const std::string bytes = read_text(png);
  if (bytes.size() < 24 || bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0 ||
      bytes.compare(12, 4, "IHDR") != 0) {
    return std::nullopt;
  }
  const auto big_endian = [&bytes](std::size_t at) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i) {
      value = (value << 8) | static_cast<unsigned char>(bytes[at + i]);
    }
    return value;
  };
  return std::make_pair(big_endian(16), big_endian(20));
}

}  // namespace radarpr::testing
