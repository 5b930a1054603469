#include "evaluation/report/report.hpp"

#include <unistd.h>

#include <fmt/format.h>
#include <fmt/ranges.h>

#include "evaluation/config/config_error.hpp"
#include "evaluation/report/auc_per_kb_figure.hpp"
#include "evaluation/report/figure_drawing.hpp"
#include "evaluation/report/html_page.hpp"
#include "evaluation/report/matrix_figures.hpp"
#include "evaluation/report/recall_curve_figure.hpp"
#include "evaluation/report/report_sections.hpp"
#include "evaluation/results/auc_size.hpp"
#include "evaluation/results/paper_tables.hpp"
#include "evaluation/results/results_error.hpp"
#include "evaluation/results/results_reader.hpp"
#include "evaluation/results/results_writer.hpp"
#include "evaluation/results/staging_folder.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

std::vector<CurveSeries> dataset_series(const RunResults& run, const std::string& dataset) {
  std::vector<CurveSeries> series;
  for (std::size_t d = 0; d < run.descriptors.size(); ++d) {
    const ResultRow* row = run.find(dataset, run.descriptors[d]);
    if (row == nullptr) continue;
    // The descriptor's colour, dash type and marker are the same in every figure of the report.
    series.push_back({row->label, &row->curve, row->f1_max_threshold, row->f1_max, row->roc_auc, d,
                      static_cast<int>(d % 5) + 1});
  }
  return series;
}

// What the matching graphs need from the recorded protocol: the revisit radius and the recency
// exclusion (for a missed revisit's nearest loop frame).
MatchingGraphContext graph_context(const RunResults& run) {
  MatchingGraphContext context;
  const nlohmann::json& protocol = run.summary.value("protocol", nlohmann::json::object());
  if (protocol.contains("revisit_radius_m") && protocol["revisit_radius_m"].is_number()) {
    context.revisit_radius_m = protocol["revisit_radius_m"].get<double>();
  }
  const bool seconds =
      protocol.contains("exclude_recent_seconds") && protocol["exclude_recent_seconds"].is_number();
  context.exclude_recent_frames = std::nullopt;
  if (!seconds && protocol.contains("exclude_recent_frames") &&
      protocol["exclude_recent_frames"].is_number_unsigned()) {
    context.exclude_recent_frames = protocol["exclude_recent_frames"].get<std::size_t>();
  }
  return context;
}

// "≤" or, under a strict threshold comparison, "<".
const char* context_comparison(const RunResults& run) {
  const nlohmann::json& protocol = run.summary.value("protocol", nlohmann::json::object());
  return protocol.value("threshold_comparison", "inclusive") == "strict" ? "<" : "\u2264";
}

// The run's largest Recall@K: how far its rankings reach when summary.json does not say.
std::size_t recorded_largest_k(const RunResults& run) {
  std::size_t k = 1;
  const nlohmann::json& protocol = run.summary.value("protocol", nlohmann::json::object());
  if (protocol.contains("recall_at_k") && protocol["recall_at_k"].is_array()) {
    for (const auto& value : protocol["recall_at_k"]) {
      if (value.is_number_unsigned()) k = std::max(k, value.get<std::size_t>());
    }
  }
  return k;
}

// A dataset's Recall@N figure; its caption says where and why a curve stops before max_n.
FigureFiles recall_figure(const RunResults& run, const std::string& dataset, std::size_t max_n,
                          FigureStyle style) {
  std::vector<RecallSeries> series;
  std::size_t deepest = 0;
  for (std::size_t d = 0; d < run.descriptors.size(); ++d) {
    const ResultRow* row = run.find(dataset, run.descriptors[d]);
    if (row == nullptr) continue;
    series.push_back({row->label, recall_at_n(*row, max_n, recorded_largest_k(run)), d,
                      static_cast<int>(d % 5) + 1});
    deepest = std::max(deepest, series.back().curve.ranked_frames);
  }
  std::string caption = fmt::format(
      "{}: Recall@N, the share of revisit queries with a frame within the revisit radius among "
      "their N nearest (N = 1 to {}; Recall@1 as in the tables)",
      dataset, max_n);
  std::vector<std::string> reranked, shallow;
  for (const auto& line : series) {
    if (!line.curve.stops_early) continue;
    (line.curve.ranked_frames < deepest ? reranked : shallow)
        .push_back(fmt::format("{} at N = {}", line.title, line.curve.ranked_frames));
  }
  if (!reranked.empty()) {
    caption += fmt::format(
        ". Stopping early: {}; these descriptors re-rank only the candidates their key "
        "pre-search hands over (their `candidates` parameter), so a correct frame beyond them "
        "is never ranked",
        fmt::join(reranked, ", "));
  }
  if (!shallow.empty()) {
    caption += fmt::format(
        ". Stopping early: {}; the run ranked only that many nearest frames (its largest "
        "Recall@K; the config's report.recall_curve_n ranks more)",
        fmt::join(shallow, ", "));
  }
  return recall_at_n_figure("recall_at_n_" + figure_stem(dataset), caption, series, max_n, style);
}

std::vector<FigureFiles> report_figures(const RunResults& run,
                                        const std::vector<AucSizePoint>& auc_points,
                                        const ReportOptions& options, FigureStyle style,
                                        const ReportConfig& recorded) {
  const auto recall_curve_n = static_cast<std::size_t>(recorded.recall_curve_n);
  std::vector<FigureFiles> figures{auc_size_figure("auc_vs_size", auc_points, style)};
  if (recorded.auc_per_kb) figures.push_back(auc_per_kb_figure("auc_per_kb", auc_points, style));
  for (auto& figure : matrix_figures(run, style)) figures.push_back(std::move(figure));
  for (std::size_t d = 0; d < run.datasets.size(); ++d) {
    const std::string& dataset = run.datasets[d];
    const auto series = dataset_series(run, dataset);
    const std::string stem = figure_stem(dataset);
    figures.push_back(
        pr_figure("pr_" + stem, dataset + ": precision-recall", series, KeyPlace::right, style));
    figures.push_back(roc_figure("roc_" + stem, dataset + ": ROC", series, KeyPlace::right, style));
    figures.push_back(recall_figure(run, dataset, recall_curve_n, style));
  }
  MatchingGraphContext context = graph_context(run);
  context.include_missed = options.include_missed;
  context.style = style;
  for (std::size_t d = 0; d < run.datasets.size(); ++d) {
    for (const auto& id : run.descriptors) {
      const ResultRow* row = run.find(run.datasets[d], id);
      if (row == nullptr) continue;
      context.threshold_text =
          row->f1_max_threshold
              ? std::optional(fmt::format("F1-max threshold: d {} {:.4g}", context_comparison(run),
                                          *row->f1_max_threshold))
              : std::nullopt;
      const std::string stem =
          figure_stem(run.datasets[d]) + "__" + figure_stem(descriptor_folder_name(id));
      const std::string at = fmt::format(
          "{}, {}: matching graph at the F1-max threshold ({})", run.datasets[d], row->label,
          row->f1_max_threshold ? fmt::format("{:.4g}", *row->f1_max_threshold) : "undefined");
      context.top_view = false;
      figures.push_back(
          matching_graph_figure("graph_" + stem, at, *row, run.trajectories[d], context));
      context.top_view = true;
      figures.push_back(matching_graph_figure("graphxy_" + stem, at + ", top view", *row,
                                              run.trajectories[d], context));
    }
  }
  return figures;
}

void write_table(const fs::path& folder, const std::string& stem, const Table& table) {
  write_text_file(folder / (stem + ".md"), to_markdown(table));
  write_text_file(folder / (stem + ".csv"), to_csv(table));
  write_text_file(folder / (stem + ".tex"), to_latex(table));
}

}  // namespace

ReportConfig recorded_report_config(const fs::path& results_folder, const nlohmann::json& summary) {
  if (!summary.contains("config") || !summary["config"].is_object() ||
      !summary["config"].contains("report")) {
    return {};
  }
  const nlohmann::json& report = summary["config"]["report"];
  try {
    if (!report.is_object()) throw ConfigError("report", "must be an object");
    return parse_report_config(ConfigReader(report, "report"));
  } catch (const ConfigError& error) {
    throw ResultsError(fmt::format("{}: the recorded config's {}",
                                   (results_folder / "summary.json").string(), error.what()));
  }
}

ReportOutcome write_report(const fs::path& results_folder, const ReportOptions& options) {
  const RunResults run = read_run_results(results_folder);  // throws before anything is written
  const ReportConfig recorded = recorded_report_config(results_folder, run.summary);
  const FigureStyle style = options.style.value_or(recorded.style);
  ReportOutcome outcome;
  const fs::path staging = results_folder / fmt::format(".report.partial.{}", ::getpid());
  try {
    fs::remove_all(staging);
    fs::create_directories(staging);
    remove_stale_staging(results_folder, ".report.partial.");
    const auto auc_points = auc_size_points(run);
    if (const auto note = auc_size_unequal_note(auc_points)) {
      outcome.warnings.push_back(
          fmt::format("{}: {}", (results_folder / "figures" / "auc_vs_size.csv").string(), *note));
    }
    const auto figures = report_figures(run, auc_points, options, style, recorded);
    const auto shown =
        write_figures(staging / "figures", figures, results_folder / "figures", outcome.warnings);
    outcome.figures = figures.size();
    for (const auto& figure : shown) outcome.drawn += figure.drawn ? 1 : 0;
    const Table table1 = metrics_table(run);
    const Table table2 = size_table(run);
    const Table table3 = auc_size_table(auc_points);
    const Table table4 = retrieval_table(run);
    write_table(staging, "table1", table1);
    write_table(staging, "table2", table2);
    write_table(staging, "table3", table3);
    write_table(staging, "table4", table4);
    write_text_file(staging / "index.html",
                    html_page(fmt::format("{}: radarpr report", run.experiment),
                              report_sections(run, {table1, table2, table3, table4},
                                              auc_size_unequal_note(auc_points), shown)));
    publish_staged(staging, results_folder);
    remove_stale_images(results_folder / "figures", shown, outcome.warnings);
  } catch (const std::exception& error) {
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    throw ResultsError(
        fmt::format("{}: cannot write the report ({})", results_folder.string(), error.what()));
  }
  return outcome;
}

}  // namespace radarpr
