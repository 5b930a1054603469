#include "benchmarks/bench_report.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <map>
#include <stdexcept>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "benchmarks/speed_targets.hpp"

namespace radarpr::bench {
namespace {

const CaseResult* find_case(const BenchRun& run, CaseKind kind, const std::string& scan,
                            const std::string& descriptor) {
  for (const CaseResult& result : run.results) {
    if (result.bench.kind == kind && result.bench.scan == scan &&
        result.bench.descriptor == descriptor && result.measurement.error.empty()) {
      return &result;
    }
  }
  return nullptr;
}

const CaseResult* find_stage(const BenchRun& run, const std::string& scan,
                             const std::string& descriptor, Stage stage) {
  for (const CaseResult& result : run.results) {
    if (result.bench.kind == CaseKind::stage && result.bench.scan == scan &&
        result.bench.descriptor == descriptor && result.bench.stage == stage &&
        result.measurement.error.empty()) {
      return &result;
    }
  }
  return nullptr;
}

const CaseResult* find_search_case(const BenchRun& run, CaseKind kind, const BenchCase& like,
                                   bool same_session = false) {
  for (const CaseResult& result : run.results) {
    if (result.bench.kind == kind && result.bench.descriptor == like.descriptor &&
        result.bench.database_size == like.database_size && result.measurement.error.empty() &&
        (!same_session || result.bench.session == like.session)) {
      return &result;
    }
  }
  return nullptr;
}

double counter(const Measurement& measurement, const char* name) {
  const auto found = measurement.counters.find(name);
  return found == measurement.counters.end() ? 0.0 : found->second;
}

// Three significant digits without an exponent (times in tables).
std::string number(double value) {
  const double magnitude = std::abs(value);
  if (magnitude >= 100.0) return fmt::format("{:.0f}", value);
  if (magnitude >= 10.0) return fmt::format("{:.1f}", value);
  if (magnitude >= 1.0) return fmt::format("{:.2f}", value);
  if (magnitude == 0.0) return "0";
  const int decimals = 2 - static_cast<int>(std::floor(std::log10(magnitude)));
  return fmt::format("{:.{}f}", value, decimals);
}

std::string milliseconds(std::optional<double> seconds) {
  return seconds ? number(*seconds * 1e3) : "-";
}

std::string size_text(std::size_t n) {
  if (n >= 1000 && n % 1000 == 0) {
    int exponent = 0;
    std::size_t rest = n;
    while (rest % 10 == 0) {
      rest /= 10;
      ++exponent;
    }
    if (rest == 1) return fmt::format("10^{}", exponent);
  }
  return fmt::format("{}", n);
}

nlohmann::json optional_json(std::optional<double> value) {
  return value ? nlohmann::json(*value) : nlohmann::json(nullptr);
}

std::string met_text(std::optional<bool> met) {
  if (!met) return "-";
  return *met ? "met" : "**not met**";
}

}  // namespace

std::vector<ExtractionRow> extraction_rows(const BenchRun& run) {
  std::vector<ExtractionRow> rows;
  for (const CaseResult& result : run.results) {
    if (result.bench.kind != CaseKind::extraction || !result.measurement.error.empty()) continue;
    const BenchCase& bench = result.bench;
    ExtractionRow row;
    row.descriptor = bench.descriptor;
    row.scan = bench.scan;
    row.total = result.measurement.cpu_seconds;
    row.payload_bytes = counter(result.measurement, "payload_bytes");
    row.paper_bytes = counter(result.measurement, "paper_bytes");
    if (const CaseResult* decode = find_case(run, CaseKind::png_decode, bench.scan, "")) {
      row.png_decode = decode->measurement.cpu_seconds;
    }
    if (const CaseResult* floor = find_case(run, CaseKind::floor, bench.scan, "")) {
      if (floor->measurement.cpu_seconds > 0.0) {
        row.floor_multiple = row.total / floor->measurement.cpu_seconds;
      }
    }
    double staged = 0.0;
    if (const CaseResult* s = find_stage(run, bench.scan, bench.descriptor, Stage::preparation)) {
      row.preparation = s->measurement.cpu_seconds;
      row.preparation_what = s->bench.what;
      staged += *row.preparation;
    }
    if (const CaseResult* s = find_stage(run, bench.scan, bench.descriptor, Stage::features)) {
      row.features = s->measurement.cpu_seconds;
      staged += *row.features;
    }
    if (const CaseResult* s = find_stage(run, bench.scan, bench.descriptor, Stage::descriptor)) {
      row.descriptor_stage = s->measurement.cpu_seconds;
    } else {
      row.descriptor_stage = std::max(0.0, row.total - staged);
      row.descriptor_derived = staged > 0.0;
    }
    rows.push_back(row);
  }
  return rows;
}

std::vector<RetrievalRow> retrieval_rows(const BenchRun& run) {
  std::vector<RetrievalRow> rows;
  for (const CaseResult& result : run.results) {
    if (result.bench.kind != CaseKind::retrieval || !result.measurement.error.empty()) continue;
    const BenchCase& bench = result.bench;
    RetrievalRow row;
    row.strategy = bench.strategy;
    row.descriptor = bench.descriptor;
    row.dimension = bench.dimension;
    row.database_size = bench.database_size;
    row.session = bench.session;
    row.queries_timed = bench.queries_timed;
    row.queries_total = bench.queries_total;
    if (const CaseResult* build = find_search_case(run, CaseKind::index_build, bench)) {
      row.index_build = build->measurement.real_seconds;
    }
    const double timed = result.measurement.real_seconds;
    const double build = row.index_build.value_or(0.0);
    row.extrapolated = bench.queries_timed < bench.queries_total && bench.pairs_timed > 0;
    // A sampled call still builds the whole index once; only the searching scales with pairs.
    row.total = row.extrapolated ? build + std::max(0.0, timed - build) *
                                               static_cast<double>(bench.pairs_total) /
                                               static_cast<double>(bench.pairs_timed)
                                 : timed;
    if (bench.queries_total > 0) {
      row.per_query = std::max(0.0, row.total - build) / static_cast<double>(bench.queries_total);
    }
    // Per pair of values, against the product of the same session's shapes (a single session's
    // queries multiplied only against their prefixes, block by block, as the search does), else
    // against the multi-session product.
    const CaseResult* product = find_search_case(run, CaseKind::matrix_product, bench, true);
    if (product == nullptr) product = find_search_case(run, CaseKind::matrix_product, bench);
    if (product != nullptr) {
      const double product_seconds = product->measurement.real_seconds;
      if (product_seconds > 0.0 && bench.pairs_timed > 0 && product->bench.pairs_timed > 0) {
        row.over_matrix_product =
            (timed / static_cast<double>(bench.pairs_timed)) /
            (product_seconds / static_cast<double>(product->bench.pairs_timed));
      } else if (product_seconds > 0.0 && bench.session == "multi") {
        row.over_matrix_product = timed / product_seconds;
      }
    }
    if (const double peak = counter(result.measurement, "peak_rss_bytes"); peak > 0.0) {
      row.peak_memory_bytes = peak;
      row.values_bytes = counter(result.measurement, "values_bytes");
    }
    rows.push_back(row);
  }
  return rows;
}

std::vector<StartupRow> startup_rows(const BenchRun& run) {
  std::vector<StartupRow> rows;
  for (const CaseResult& result : run.results) {
    const bool floor = result.bench.kind == CaseKind::process_floor;
    if ((result.bench.kind != CaseKind::startup && !floor) || !result.measurement.error.empty()) {
      continue;
    }
    const BenchCase& bench = result.bench;
    StartupRow row;
    row.floor = floor;
    row.descriptor = bench.descriptor;
    row.scan = bench.scan;
    if (floor) {
      row.command = bench.scan.empty() ? std::string("radarpr_png_decode_floor")
                                       : fmt::format("radarpr_png_decode_floor {}.png", bench.scan);
    } else {
      row.command = bench.descriptor.empty()
                        ? std::string("radarpr --version")
                        : fmt::format("radarpr extract {} {}.png", bench.descriptor, bench.scan);
    }
    row.wall = result.measurement.real_seconds;
    row.process_cpu = counter(result.measurement, "process_cpu_seconds");
    const CaseResult* decode = find_case(run, CaseKind::png_decode, bench.scan, "");
    const CaseResult* extract = find_case(run, CaseKind::extraction, bench.scan, bench.descriptor);
    if (floor && !bench.scan.empty() && decode != nullptr) {
      row.in_process = decode->measurement.cpu_seconds;
    } else if (!bench.descriptor.empty() && decode != nullptr && extract != nullptr) {
      row.in_process = decode->measurement.cpu_seconds + extract->measurement.cpu_seconds;
    }
    if (row.in_process && *row.in_process > 0.0) row.over_in_process = row.wall / *row.in_process;
    rows.push_back(row);
  }
  return rows;
}

namespace {

bool names(const SpeedTarget& target, const std::string& descriptor) {
  if (target.descriptor.ends_with('*')) {
    return descriptor.starts_with(target.descriptor.substr(0, target.descriptor.size() - 1));
  }
  return descriptor == target.descriptor;
}

void check_extraction(const SpeedTarget& target, const BenchRun& run,
                      const std::vector<ExtractionRow>& rows, TargetCheck& check) {
  for (const ExtractionRow& row : rows) {
    if (!names(target, row.descriptor) || row.scan != target.where) continue;
    double measured = 0.0;
    std::string text;
    if (target.measure == TargetMeasure::extraction_milliseconds) {
      measured = row.total * 1e3;
      text = fmt::format("{} ms", milliseconds(row.total));
    } else if (target.measure == TargetMeasure::extraction_over_floor) {
      const CaseResult* floor = find_case(run, CaseKind::floor, row.scan, "");
      if (floor == nullptr || !row.floor_multiple) continue;
      measured = *row.floor_multiple;
      text = fmt::format("{} ms vs {} ms plain pass ({}x)", milliseconds(row.total),
                         milliseconds(floor->measurement.cpu_seconds), number(measured));
    } else {  // extraction_over_png_decode
      if (!row.png_decode || *row.png_decode <= 0.0) continue;
      measured = row.total / *row.png_decode;
      text = fmt::format("{} ms vs {} ms decode ({:.2f}x)", milliseconds(row.total),
                         milliseconds(row.png_decode), measured);
    }
    check.measured += (check.measured.empty() ? "" : "; ") + text;
    check.met = check.met.value_or(true) && measured <= target.limit;
  }
}

void check_retrieval(const SpeedTarget& target, const BenchRun& run,
                     const std::vector<RetrievalRow>& rows, TargetCheck& check) {
  if (target.measure == TargetMeasure::search_over_product) {
    // Every configuration the target names, each at its largest measured database.
    std::map<std::string, const RetrievalRow*> largest;
    for (const RetrievalRow& row : rows) {
      if (!names(target, row.descriptor) || row.session != target.where ||
          !row.over_matrix_product) {
        continue;
      }
      const RetrievalRow*& kept = largest[row.descriptor];
      if (kept == nullptr || row.database_size > kept->database_size) kept = &row;
    }
    for (const auto& [id, row] : largest) {
      check.measured += fmt::format("{}{}: {:.2f}x at N = {}", check.measured.empty() ? "" : "; ",
                                    id, *row->over_matrix_product, size_text(row->database_size));
      check.met = check.met.value_or(true) && *row->over_matrix_product <= target.limit;
    }
    return;
  }
  for (const RetrievalRow& row : rows) {
    if (!names(target, row.descriptor) || row.session != target.where ||
        row.database_size != target.database_size) {
      continue;
    }
    std::string seconds =
        fmt::format("{} s{}", number(row.total), row.extrapolated ? " (extrapolated)" : "");
    bool met = row.total <= target.limit;
    if (target.measure == TargetMeasure::search_within_memory) {
      seconds = fmt::format("{} s{}", number(row.total),
                            row.extrapolated ? fmt::format(" extrapolated from {} of {} queries",
                                                           row.queries_timed, row.queries_total)
                                             : std::string());
      if (row.peak_memory_bytes) {
        seconds += fmt::format(", peak memory {:.2f} GB", *row.peak_memory_bytes / 1e9);
      }
      if (row.values_bytes && *row.values_bytes > 0.0) {
        seconds += fmt::format(" ({:.1f} GB of values memory-mapped)", *row.values_bytes / 1e9);
      }
      met = row.peak_memory_bytes.has_value() && *row.peak_memory_bytes <= target.limit * 1e9;
    }
    check.measured += (check.measured.empty() ? "" : "; ") +
                      (target.descriptor.ends_with('*') ? row.descriptor + ": " : "") + seconds;
    check.met = check.met.value_or(true) && met;
  }
  if (target.measure == TargetMeasure::search_within_memory && !check.met) {
    const std::string wanted =
        fmt::format("/{}/{}/{}", target.descriptor, target.database_size, target.where);
    for (const SkippedCase& skipped : run.skipped) {
      if (skipped.name.ends_with(wanted)) {
        check.measured = "left out: " + skipped.reason;
        check.met = false;
      }
    }
    for (const CaseResult& result : run.results) {
      if (result.bench.kind == CaseKind::retrieval && result.bench.name.ends_with(wanted) &&
          !result.measurement.error.empty()) {
        check.measured = "failed: " + result.measurement.error;
        check.met = false;
      }
    }
  }
}

void check_startup(const SpeedTarget& target, const std::vector<StartupRow>& rows,
                   TargetCheck& check) {
  for (const StartupRow& row : rows) {
    if (row.floor || row.descriptor != target.descriptor || row.scan != target.where) continue;
    if (target.measure == TargetMeasure::startup_milliseconds) {
      check.measured = fmt::format("{} ms ({} ms of CPU)", milliseconds(row.wall),
                                   milliseconds(row.process_cpu));
      check.met = row.wall * 1e3 <= target.limit;
    } else if (row.over_in_process) {  // startup_over_extraction
      check.measured =
          fmt::format("{} ms vs {} ms in a running process ({:.2f}x)", milliseconds(row.wall),
                      milliseconds(row.in_process), *row.over_in_process);
      check.met = *row.over_in_process <= target.limit;
      // The floor of that multiple on this machine: a process that does nothing but decode the
      // same PNG, against the same in-process decode + extraction.
      for (const StartupRow& floor : rows) {
        if (!floor.floor || floor.scan != row.scan) continue;
        check.measured +=
            fmt::format("; the minimal program that only decodes the same PNG: {} ms ({:.2f}x)",
                        milliseconds(floor.wall), floor.wall / *row.in_process);
      }
    }
  }
}

}  // namespace

std::vector<TargetCheck> check_targets(const BenchRun& run) {
  const std::vector<ExtractionRow> extraction = extraction_rows(run);
  const std::vector<RetrievalRow> retrieval = retrieval_rows(run);
  const std::vector<StartupRow> startup = startup_rows(run);
  std::vector<TargetCheck> checks;
  for (const SpeedTarget& target : speed_targets()) {
    TargetCheck check{std::string(target.part), std::string(target.wording), "", std::nullopt};
    if (target.part == "extraction") {
      check_extraction(target, run, extraction, check);
    } else if (target.part == "start-up") {
      check_startup(target, startup, check);
    } else {
      check_retrieval(target, run, retrieval, check);
    }
    checks.push_back(std::move(check));
  }
  return checks;
}

nlohmann::json report_json(const BenchRun& run) {
  nlohmann::json json;
  json["machine"] = to_json(run.machine);
  json["settings"] = {{"quick", run.quick},
                      {"min_seconds_per_repetition", run.length.min_seconds},
                      {"repetitions", run.length.repetitions},
                      {"filter", run.filter},
                      {"threads", run.threads}};
  json["scans"] = nlohmann::json::array();
  for (const ScanSummary& scan : run.scans) {
    json["scans"].push_back({{"label", scan.label},
                             {"radar", scan.radar},
                             {"source", scan.source},
                             {"real", scan.real},
                             {"azimuths", scan.azimuths},
                             {"range_bins", scan.range_bins},
                             {"png_bytes", scan.png_bytes}});
  }
  json["results"] = nlohmann::json::array();
  for (const CaseResult& result : run.results) {
    const BenchCase& b = result.bench;
    const Measurement& m = result.measurement;
    nlohmann::json entry{{"name", b.name},
                         {"kind", to_string(b.kind)},
                         {"real_seconds", m.real_seconds},
                         {"cpu_seconds", m.cpu_seconds},
                         {"real_seconds_each", m.real_seconds_each},
                         {"cpu_seconds_each", m.cpu_seconds_each},
                         {"repetitions", m.repetitions},
                         {"iterations", m.iterations},
                         {"counters", m.counters}};
    if (!b.scan.empty()) entry["scan"] = b.scan;
    if (!b.descriptor.empty()) entry["descriptor"] = b.descriptor;
    if (b.kind == CaseKind::stage) {
      entry["stage"] = to_string(b.stage);
      entry["what"] = b.what;
    }
    if (!b.strategy.empty()) {
      entry["strategy"] = b.strategy;
      entry["database_size"] = b.database_size;
      entry["dimension"] = b.dimension;
    }
    if (!b.session.empty()) entry["session"] = b.session;
    if (b.queries_total > 0) {
      entry["queries_timed"] = b.queries_timed;
      entry["queries_total"] = b.queries_total;
      entry["pairs_timed"] = b.pairs_timed;
      entry["pairs_total"] = b.pairs_total;
    }
    if (!m.error.empty()) entry["error"] = m.error;
    json["results"].push_back(entry);
  }
  json["extraction"] = nlohmann::json::array();
  for (const ExtractionRow& row : extraction_rows(run)) {
    json["extraction"].push_back({{"descriptor", row.descriptor},
                                  {"scan", row.scan},
                                  {"png_decode_seconds", optional_json(row.png_decode)},
                                  {"preparation_seconds", optional_json(row.preparation)},
                                  {"features_seconds", optional_json(row.features)},
                                  {"descriptor_seconds", row.descriptor_stage},
                                  {"descriptor_derived", row.descriptor_derived},
                                  {"total_seconds", row.total},
                                  {"floor_multiple", optional_json(row.floor_multiple)},
                                  {"payload_bytes", row.payload_bytes},
                                  {"paper_bytes", row.paper_bytes}});
  }
  json["retrieval"] = nlohmann::json::array();
  for (const RetrievalRow& row : retrieval_rows(run)) {
    json["retrieval"].push_back({{"strategy", row.strategy},
                                 {"descriptor", row.descriptor},
                                 {"dimension", row.dimension},
                                 {"database_size", row.database_size},
                                 {"session", row.session},
                                 {"index_build_seconds", optional_json(row.index_build)},
                                 {"total_seconds", row.total},
                                 {"per_query_seconds", row.per_query},
                                 {"queries_timed", row.queries_timed},
                                 {"extrapolated", row.extrapolated},
                                 {"over_matrix_product", optional_json(row.over_matrix_product)}});
  }
  json["startup"] = nlohmann::json::array();
  for (const StartupRow& row : startup_rows(run)) {
    json["startup"].push_back({{"command", row.command},
                               {"floor", row.floor},
                               {"wall_seconds", row.wall},
                               {"process_cpu_seconds", row.process_cpu},
                               {"in_process_seconds", optional_json(row.in_process)},
                               {"over_in_process", optional_json(row.over_in_process)}});
  }
  json["targets"] = nlohmann::json::array();
  for (const TargetCheck& target : check_targets(run)) {
    json["targets"].push_back(
        {{"part", target.part},
         {"target", target.target},
         {"measured", target.measured},
         {"met", target.met ? nlohmann::json(*target.met) : nlohmann::json(nullptr)}});
  }
  json["skipped"] = nlohmann::json::array();
  for (const SkippedCase& skipped : run.skipped) {
    json["skipped"].push_back({{"name", skipped.name}, {"reason", skipped.reason}});
  }
  return json;
}

std::string report_markdown(const BenchRun& run) {
  const MachineDescription& machine = run.machine;
  std::string md = "# radarpr benchmarks\n\n";
  if (!machine.optimised) {
    md += fmt::format(
        "> **WARNING: not an optimised build ({}).** These timings do not describe radarpr; "
        "rebuild with -DCMAKE_BUILD_TYPE=Release.\n\n",
        machine.build_type.empty() ? "no build type" : machine.build_type);
  }
  md += fmt::format(
      "Measured {} on {} ({} logical cores, {:.1f} GiB), {}; {}, {} build; radarpr {}.\n",
      machine.date_utc, machine.cpu_model, machine.logical_cores, machine.memory_gib,
      machine.operating_system, machine.compiler, machine.build_type, machine.radarpr_version);
  if (machine.load_average.size() >= 3) {
    md += fmt::format("Load average at the start: {:.2f}, {:.2f}, {:.2f}.\n",
                      machine.load_average[0], machine.load_average[1], machine.load_average[2]);
  }
  md += fmt::format(
      "Each benchmark: {} repetitions on one scan, {} in retrieval ({} threads), each of at least "
      "{} s; medians{}{}. On a shared machine repetitions differ by 10-20%; bench.json has each of "
      "them.\n",
      run.length.cheap_repetitions, run.length.repetitions, run.threads,
      number(run.length.min_seconds), run.quick ? "; quick mode" : "",
      run.filter.empty() ? "" : fmt::format("; filter `{}`", run.filter));

  md += "\n## Scans\n\n| Scan | Radar | Source | PNG bytes |\n|---|---|---|---:|\n";
  for (const ScanSummary& scan : run.scans) {
    md +=
        fmt::format("| {} | {} | {} | {} |\n", scan.label, scan.radar, scan.source, scan.png_bytes);
  }

  const std::vector<ExtractionRow> extraction = extraction_rows(run);
  if (!extraction.empty()) {
    md +=
        "\n## Extraction: one scan, one thread (ms of CPU, medians)\n\n"
        "| Descriptor | Scan | PNG decode | Preparation | Cen 2018 features | Descriptor | "
        "Extraction | x plain pass | Scans/s | Payload B | Paper B |\n"
        "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const ExtractionRow& row : extraction) {
      md += fmt::format(
          "| {} | {} | {} | {} | {} | {}{} | {} | {} | {} | {:.0f} | {:.0f} |\n", row.descriptor,
          row.scan, milliseconds(row.png_decode), milliseconds(row.preparation),
          milliseconds(row.features), row.descriptor_derived ? "~" : "",
          milliseconds(row.descriptor_stage), milliseconds(row.total),
          row.floor_multiple ? number(*row.floor_multiple) : "-",
          row.total > 0.0 ? number(1.0 / row.total) : "-", row.payload_bytes, row.paper_bytes);
    }
    md += "\nPlain pass (one sum over the scan's bytes): ";
    bool first = true;
    for (const ScanSummary& scan : run.scans) {
      if (const CaseResult* floor = find_case(run, CaseKind::floor, scan.label, "")) {
        md += fmt::format("{}{} ms on {}", first ? "" : ", ",
                          milliseconds(floor->measurement.cpu_seconds), scan.label);
        first = false;
      }
    }
    md +=
        ".\n\"Extraction\" is timed on its own; the stages are timed separately, so they add up "
        "to it only roughly. \"-\" under Preparation: the descriptor has no separate preparation "
        "(it is part of Descriptor); \"~\": Descriptor derived as Extraction minus the timed "
        "stages. PNG decode is the scan's file read and decoded by read_polar_png, shared by "
        "every descriptor of an experiment. Paper B: the elements as a float64 numpy file.\n";
    for (const ExtractionRow& row : extraction) {
      if (!row.preparation_what.empty() && row.scan == run.scans.front().label) {
        md += fmt::format("Preparation of {}: {}.\n", row.descriptor, row.preparation_what);
      }
    }
  }

  const std::vector<RetrievalRow> retrieval = retrieval_rows(run);
  if (!retrieval.empty()) {
    md +=
        "\n## Retrieval: top-1 over synthetic drives (wall clock, every core, medians)\n\n"
        "| Strategy | Descriptor | Floats | N | Session | Index build (s) | Search, all "
        "queries (s) | Per query (ms) | Queries timed | vs Eigen product |\n"
        "|---|---|---:|---:|---|---:|---:|---:|---:|---:|\n";
    for (const RetrievalRow& row : retrieval) {
      md +=
          fmt::format("| {} | {} | {} | {} | {} | {} | {}{} | {} | {} | {} |\n", row.strategy,
                      row.descriptor, row.dimension, size_text(row.database_size), row.session,
                      row.index_build ? number(*row.index_build) : "-", number(row.total),
                      row.extrapolated ? "*" : "", number(row.per_query * 1e3),
                      row.queries_timed == row.queries_total ? std::string("all")
                                                             : fmt::format("{}", row.queries_timed),
                      row.over_matrix_product ? fmt::format("{:.2f}x", *row.over_matrix_product)
                                              : std::string("-"));
    }
    md +=
        "\nmulti: N queries of a second session against N values; single: query i against its "
        "frames 0..i-50 of the same session. Values: a drive of 4 laps of a closed route, smooth "
        "in 8 latent dimensions mapped into the descriptor's floats, plus noise (lap to lap "
        "revisits, like loop closures). \"*\": extrapolated from the timed queries (index build "
        "once, search in proportion to the pairs). Index build: the search keys and a FLANN "
        "KD-tree over them (kdtree, key_then_rerank: what indexing these keys costs; the search "
        "itself decides whether trees pay off), prepare_distances over the database "
        "(exhaustive); exhaustive_l2 builds none. Per query: (search - index build) / N. vs "
        "Eigen product: the timed search over the float products of the same shapes on the same "
        "cores, per pair of values (single session: the timed queries, per block of 512 "
        "database values, multiplied against it only when their prefix reaches into it, as the "
        "search multiplies them).\n";
    for (const RetrievalRow& row : retrieval) {
      if (!row.peak_memory_bytes) continue;
      md += fmt::format(
          "\n{} {} at N = {}, {} session: the values ({:.1f} GB, more than the memory budget) "
          "were written to a .npy file, memory-mapped, and the search streamed from the map, a "
          "block of database values at a time; {} queries spread over the session were timed "
          "against their whole prefixes, once, and the total is extrapolated from them in "
          "proportion to the pairs (\"*\"), not measured. Peak resident memory of the process "
          "during the search: {:.2f} GB.\n",
          row.strategy, row.descriptor, size_text(row.database_size), row.session,
          row.values_bytes.value_or(0.0) / 1e9, row.queries_timed, *row.peak_memory_bytes / 1e9);
    }
  }
  const std::vector<StartupRow> startup = startup_rows(run);
  if (!startup.empty()) {
    md +=
        "\n## Start-up: one whole radarpr process (wall clock, medians)\n\n"
        "| Command | Wall (ms) | CPU of the process (ms) | The same work in a running process "
        "(ms) | x that |\n|---|---:|---:|---:|---:|\n";
    for (const StartupRow& row : startup) {
      md += fmt::format("| `{}` | {} | {} | {} | {} |\n", row.command, milliseconds(row.wall),
                        milliseconds(row.process_cpu), milliseconds(row.in_process),
                        row.over_in_process ? fmt::format("{:.2f}x", *row.over_in_process) : "-");
    }
    md +=
        "\nEach process is started, run to its end with its output discarded, and waited for: "
        "loading the program and its shared libraries is part of it. CPU of the process: its own "
        "user and system time. The same work in a running process: the PNG decode plus the "
        "extraction, one thread, as timed above. radarpr_png_decode_floor is the floor: a minimal "
        "program of radarpr's build that loads libpng and the C library only, started with "
        "nothing to do, and decoding the same PNG (against the PNG decode alone).\n";
  }
  if (!run.skipped.empty()) {
    md += "\nLeft out:\n";
    for (const SkippedCase& skipped : run.skipped) {
      md += fmt::format("- `{}`: {}\n", skipped.name, skipped.reason);
    }
  }

  md += "\n## Targets\n\n| Part | Target | Measured | |\n|---|---|---|---|\n";
  for (const TargetCheck& target : check_targets(run)) {
    md += fmt::format("| {} | {} | {} | {} |\n", target.part, target.target,
                      target.measured.empty() ? "not measured in this run" : target.measured,
                      met_text(target.met));
  }
  return md;
}

void write_report(const BenchRun& run, const std::filesystem::path& folder) {
  std::filesystem::create_directories(folder);
  const auto write = [](const std::filesystem::path& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    if (!out) throw std::runtime_error("cannot write " + path.string());
  };
  write(folder / "bench.json", report_json(run).dump(2) + "\n");
  write(folder / "bench.md", report_markdown(run));
}

}  // namespace radarpr::bench
