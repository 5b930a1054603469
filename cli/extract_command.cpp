#include <cstdio>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "cli/commands.hpp"
#include "datasets/polar_png.hpp"
#include "descriptors/descriptor_registry.hpp"

namespace radarpr::cli {

const char* const kExtractHelp =
    R"(usage: radarpr extract DESCRIPTOR_ID FILE.png ... [--range-resolution M]

Decodes each polar PNG (Oxford layout with 11 metadata columns, or MulRan's native range x
azimuth layout; detected from the image) and prints one JSON object per line:
  {"file", "layout", "id", "shape": [rows, cols], "values": [...]}
for checking a descriptor against another implementation. DESCRIPTOR_ID is a name or an id such
as referee_r:kernel=box,z_q=3 (see radarpr list).

  --range-resolution M   metres per range bin. Default: 0.0595238 for 3360 bins (MulRan
                         CIR204-H), 0.0432 for 3768 bins (Oxford CTS350-X); other widths need it.
  --plugin PATH          load a descriptor plugin first, for a DESCRIPTOR_ID it registers
                         (repeatable; $RADARPR_PLUGINS is loaded too)
)";

namespace {

// Sensors whose bin count identifies them (datasets.md); others must be told.
std::optional<double> known_range_resolution(int range_bins) {
  if (range_bins == 3360) return 200.0 / 3360.0;
  if (range_bins == 3768) return 0.0432;
  return std::nullopt;
}

}  // namespace

int extract_command(const std::vector<std::string>& args) {
  std::vector<std::string> positional;
  std::optional<double> range_resolution;
  for (std::size_t i = 0; i < args.size(); ++i) {
    if (args[i] == "--help" || args[i] == "-h") {
      fmt::print("{}", kExtractHelp);
      return 0;
    } else if (args[i] == "--range-resolution") {
      if (i + 1 >= args.size()) throw UsageError("--range-resolution needs a value");
      try {
        range_resolution = std::stod(args[++i]);
      } catch (const std::exception&) {
        throw UsageError(fmt::format("--range-resolution: '{}' is not a number", args[i]));
      }
      if (!(*range_resolution > 0.0)) throw UsageError("--range-resolution must be > 0");
    } else if (args[i].starts_with("-")) {
      throw UsageError(fmt::format("unknown option '{}'", args[i]));
    } else {
      positional.push_back(args[i]);
    }
  }
  if (positional.size() < 2) throw UsageError("extract needs a DESCRIPTOR_ID and a FILE.png");

  const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(positional[0]);
  if (!instance.descriptor->is_trained()) {
    throw std::runtime_error(fmt::format(
        "{} is trainable and learns from a sequence before it can extract; run it through "
        "`radarpr run` with a config (it trains on each dataset's database session)",
        instance.id));
  }
  for (std::size_t f = 1; f < positional.size(); ++f) {
    const std::string& file = positional[f];
    PolarPngOptions options;
    // Decode once with a provisional resolution to learn the bin count, then set the real one:
    // the resolution only scales metres and never changes the pixels.
    options.range_resolution_m = range_resolution.value_or(1.0);
    DecodedPolarPng decoded = read_polar_png(file, options);
    if (!range_resolution) {
      const auto known = known_range_resolution(decoded.image.range_bin_count());
      if (!known) {
        throw std::runtime_error(
            fmt::format("{}: {} range bins match no known sensor; pass --range-resolution", file,
                        decoded.image.range_bin_count()));
      }
      decoded.image.range_resolution_m = *known;
    }
    const DescriptorValue value = instance.descriptor->extract(decoded.image);
    const nlohmann::json line{
        {"file", file},
        {"layout", to_string(decoded.layout)},
        {"azimuths", decoded.image.azimuth_count()},
        {"range_bins", decoded.image.range_bin_count()},
        {"range_resolution_m", decoded.image.range_resolution_m},
        {"id", instance.id},
        {"shape", {value.rows, value.cols}},
        {"values", value.values},
    };
    fmt::print("{}\n", line.dump());
    std::fflush(stdout);
  }
  return 0;
}

}  // namespace radarpr::cli
