#include <algorithm>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/format.h>
#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "cli/common_options.hpp"
#include "cli/number_options.hpp"
#include "cli/verb.hpp"
#include "datasets/polar_png.hpp"
#include "descriptors/descriptor_registry.hpp"
#include "evaluation/parallel.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr::cli {
namespace {

constexpr const char* kExtractDescription =
    R"(print each polar PNG's descriptor as JSON

Decodes each polar PNG (the Oxford layout with 11 metadata columns, or MulRan's native range x
azimuth layout; told apart by the image's shape unless --layout names one) and prints one JSON
object per line, in the order of the files:
  {"file", "layout", "azimuths", "range_bins", "range_resolution_m", "id", "shape": [rows, cols],
   "values": [...]}
for checking a descriptor against another implementation. DESCRIPTOR_ID is a name or an id such
as referee_r:kernel=box,z_q=3 (see radarpr list).)";

struct ExtractArguments {
  std::string id;
  std::vector<std::string> files;
  std::optional<double> range_resolution;
  std::string layout = "auto";
  std::optional<long long> threads;
};

std::string extract_line(const DescriptorInstance& instance, const std::string& file,
                         const ExtractArguments& arguments) {
  PolarPngOptions options;
  // Decode once with a provisional resolution to learn the bin count, then set the real one:
  // the resolution only scales metres and never changes the pixels.
  options.range_resolution_m = arguments.range_resolution.value_or(1.0);
  if (arguments.layout == "oxford") options.layout = PolarPngLayout::oxford;
  if (arguments.layout == "mulran_native") options.layout = PolarPngLayout::mulran_native;
  DecodedPolarPng decoded = read_polar_png(file, options);
  if (!arguments.range_resolution) {
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
      {"file", json_string(file)},  // file names are bytes: a non-UTF-8 one shown as \xNN
      {"layout", to_string(decoded.layout)},
      {"azimuths", decoded.image.azimuth_count()},
      {"range_bins", decoded.image.range_bin_count()},
      {"range_resolution_m", decoded.image.range_resolution_m},
      {"id", instance.id},
      {"shape", {value.rows, value.cols}},
      {"values", value.values},
  };
  return line.dump();
}

int extract(const ExtractArguments& arguments) {
  const DescriptorInstance instance = DescriptorRegistry::global().create_from_id(arguments.id);
  if (!instance.descriptor->is_trained()) {
    throw std::runtime_error(fmt::format(
        "{} is trainable and learns from a sequence before it can extract; run it through "
        "`radarpr run` with a config (it trains on each dataset's database session)",
        instance.id));
  }
  // Files in batches, each batch extracted in parallel and printed in order: the output is the
  // same whatever the thread count, and an error comes after the lines of the files before it.
  const std::size_t batch = 4 * static_cast<std::size_t>(default_thread_count());
  const std::vector<std::string>& files = arguments.files;
  for (std::size_t begin = 0; begin < files.size(); begin += batch) {
    const std::size_t count = std::min(batch, files.size() - begin);
    std::vector<std::optional<std::string>> lines(count);
    auto print_done = [&] {
      for (const auto& line : lines) {
        if (!line) break;
        fmt::print("{}\n", *line);
      }
      std::fflush(stdout);
    };
    try {
      parallel_for(count, 0, [&](std::size_t i) {
        lines[i] = extract_line(instance, files[begin + i], arguments);
      });
    } catch (...) {
      print_done();  // every file before the failing one was extracted
      throw;
    }
    print_done();
  }
  return 0;
}

// The arguments and options of `radarpr extract`, and what it does with them.
VerbAction define_extract(CLI::App& verb) {
  auto arguments = std::make_shared<ExtractArguments>();
  verb.add_option("DESCRIPTOR_ID", arguments->id,
                  "the descriptor and its parameters (see radarpr list)")
      ->required();
  verb.add_option("FILE.png", arguments->files, "polar PNGs, one JSON line each")->required();
  add_number_option(verb, "--range-resolution", arguments->range_resolution,
                    {.minimum = 0.0, .minimum_excluded = true}, "M",
                    "metres per range bin; needed unless the bin count names the "
                    "sensor: 0.0595238 for 3360 bins (MulRan CIR204-H), 0.0432 for "
                    "3768 (Oxford CTS350-X)");
  add_choice_option(verb, "--layout", arguments->layout, {"auto", "oxford", "mulran_native"},
                    "how the PNGs store a scan: auto tells it from the shape (wider "
                    "than high: Oxford, azimuth rows; higher than wide: MulRan's native "
                    "range rows), which a square image cannot tell");
  add_threads_option(verb, arguments->threads);
  return [arguments] { return extract(*arguments); };
}

}  // namespace

Verb extract_verb() {
  return {"extract", kExtractDescription, define_extract};
}

}  // namespace radarpr::cli
