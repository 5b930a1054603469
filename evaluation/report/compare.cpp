#include "evaluation/report/compare.hpp"

#include <unistd.h>

#include <algorithm>
#include <map>

#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "evaluation/path_inside.hpp"
#include "evaluation/report/figure_drawing.hpp"
#include "evaluation/report/html_page.hpp"
#include "evaluation/report/report_sections.hpp"
#include "evaluation/results/paper_tables.hpp"
#include "evaluation/results/results_error.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

// A comparison replaces its folder whole: inside a results folder it reads it would change that
// run's folder, and holding one (an earlier comparison with a run moved into it) it would delete
// it. Links count by where they lead.
void refuse_overlap(const fs::path& out, const fs::path& target,
                    const std::vector<fs::path>& folders) {
  for (const fs::path& folder : folders) {
    if (is_inside(target, folder)) {
      throw ResultsError(
          fmt::format("{}: is inside the results folder {} it compares; choose a --out outside it",
                      out.string(), folder.string()));
    }
    if (is_inside(folder, target)) {
      throw ResultsError(fmt::format(
          "{}: holds the results folder {} it compares, and would replace it; choose another "
          "--out",
          out.string(), folder.string()));
    }
  }
}

// A comparison folder may be replaced only when it is empty or was written by compare, and never
// overlaps the results folders it reads.
fs::path resolve_comparison_folder(const fs::path& out, const std::vector<fs::path>& folders) {
  fs::path target = fs::absolute(out).lexically_normal();
  if (!target.has_filename()) target = target.parent_path();
  if (target == target.root_path()) {
    throw ResultsError(fmt::format("{}: a comparison needs a folder of its own", out.string()));
  }
  refuse_overlap(out, target, folders);
  if (fs::exists(target) && (!fs::is_directory(target) ||
                             (!fs::is_empty(target) && !fs::exists(target / "compare.json")))) {
    throw ResultsError(fmt::format(
        "{}: exists and is not an earlier comparison (no compare.json); refusing to replace it "
        "(choose another --out, or remove it first)",
        out.string()));
  }
  return target;
}

std::vector<std::string> all_datasets(const std::vector<RunResults>& runs) {
  std::vector<std::string> datasets;
  for (const auto& run : runs) {
    for (const auto& d : run.datasets) {
      if (std::find(datasets.begin(), datasets.end(), d) == datasets.end()) datasets.push_back(d);
    }
  }
  return datasets;
}

Table comparison_table(const std::vector<RunResults>& runs, const std::vector<std::string>& labels,
                       const std::vector<std::string>& datasets) {
  Table table;
  table.header = {"run", "descriptor"};
  table.numeric = {false, false};
  std::vector<std::size_t> metric_columns;
  for (const auto& dataset : datasets) {
    table.header.push_back(dataset + " AUC");
    table.header.push_back(dataset + " F1-max");
    table.header.push_back(dataset + " R@1");
    table.numeric.insert(table.numeric.end(), {true, true, true});
    for (std::size_t back = 3; back >= 1; --back) {
      metric_columns.push_back(table.header.size() - back);
    }
  }
  for (std::size_t r = 0; r < runs.size(); ++r) {
    for (const auto& id : runs[r].descriptors) {
      std::vector<TableCell> row{{labels[r]}, {id}};
      for (const auto& dataset : datasets) {
        const ResultRow* result = runs[r].find(dataset, id);
        if (result != nullptr) row[1].text = result->label;
        // A dataset this run does not have: empty, never bold.
        row.push_back({result ? metric_text(result->roc_auc) : ""});
        row.push_back({result ? metric_text(result->f1_max) : ""});
        row.push_back({result ? metric_text(result->recall_at_1) : ""});
      }
      table.rows.push_back(std::move(row));
    }
  }
  bold_best(table, metric_columns);
  return table;
}

std::vector<FigureFiles> comparison_figures(const std::vector<RunResults>& runs,
                                            const std::vector<std::string>& labels,
                                            const std::vector<std::string>& datasets) {
  std::vector<std::string> descriptor_ids;
  for (const auto& run : runs) {
    for (const auto& id : run.descriptors) {
      if (std::find(descriptor_ids.begin(), descriptor_ids.end(), id) == descriptor_ids.end()) {
        descriptor_ids.push_back(id);
      }
    }
  }
  std::vector<FigureFiles> figures;
  for (const auto& dataset : datasets) {
    const bool common = std::all_of(runs.begin(), runs.end(), [&](const RunResults& run) {
      return std::find(run.datasets.begin(), run.datasets.end(), dataset) != run.datasets.end();
    });
    if (!common) continue;
    std::vector<CurveSeries> series;
    for (std::size_t r = 0; r < runs.size(); ++r) {
      for (const auto& id : runs[r].descriptors) {
        const ResultRow* row = runs[r].find(dataset, id);
        if (row == nullptr) continue;
        // A descriptor keeps its colour across runs, a run its dash type across descriptors.
        const auto colour = static_cast<std::size_t>(
            std::find(descriptor_ids.begin(), descriptor_ids.end(), id) - descriptor_ids.begin());
        series.push_back({labels[r] + ": " + row->label, &row->curve, row->f1_max_threshold,
                          row->f1_max, row->roc_auc, colour, static_cast<int>(r % 8) + 1});
      }
    }
    const std::string stem = figure_stem(dataset);
    figures.push_back(
        pr_figure("pr_" + stem, dataset + ": precision-recall, all runs", series, KeyPlace::below));
    figures.push_back(
        roc_figure("roc_" + stem, dataset + ": ROC, all runs", series, KeyPlace::below));
  }
  return figures;
}

std::vector<PageSection> comparison_sections(const std::vector<RunResults>& runs,
                                             const std::vector<std::string>& labels,
                                             const Table& table,
                                             const std::vector<std::string>& mismatches,
                                             const std::vector<PageFigure>& figures) {
  std::string list = "<ul>\n";
  for (std::size_t r = 0; r < runs.size(); ++r) {
    list += fmt::format(
        "<li><strong>{}</strong>: <code>{}</code>, radarpr {}, {} descriptors, {} "
        "datasets</li>\n",
        html_escape(labels[r]), html_escape(runs[r].folder.string()),
        html_escape(json_text(runs[r].summary["radarpr_version"])), runs[r].descriptors.size(),
        runs[r].datasets.size());
  }
  list += "</ul>\n";
  for (const auto& mismatch : mismatches) {
    list += "<p class=\"warning\">Warning: " + html_escape(mismatch) + ".</p>\n";
  }
  std::vector<PageSection> sections{{"Runs", list}};
  sections.push_back({"ROC AUC, F1-max and Recall@1, all runs",
                      to_html(table) +
                          "<p>Best per column in bold; an empty cell: the run has "
                          "no such dataset. Also <code>compare.md</code>, "
                          "<code>compare.csv</code>, <code>compare.tex</code>.</p>\n"});
  std::string html;
  for (const auto& figure : figures) html += figure_html(figure);
  if (figures.empty()) html = "<p>No dataset is common to every run: no curves overlaid.</p>\n";
  sections.push_back({"Curves of the datasets every run has", html});
  std::string protocols;
  for (std::size_t r = 0; r < runs.size(); ++r) {
    protocols += fmt::format("<h3>{}</h3>\n", html_escape(labels[r])) +
                 protocol_html(runs[r].summary.value("protocol", nlohmann::json::object()));
  }
  sections.push_back({"Protocols", protocols});
  return sections;
}

// A dataset's entry in a run's config (summary.json "config"."datasets"), or null.
nlohmann::json dataset_config(const RunResults& run, const std::string& dataset) {
  const nlohmann::json& config = run.summary.value("config", nlohmann::json::object());
  if (!config.is_object() || !config.contains("datasets") || !config["datasets"].is_array()) {
    return nullptr;
  }
  for (const auto& entry : config["datasets"]) {
    if (entry.is_object() && entry.value("name", "") == dataset) return entry;
  }
  return nullptr;
}

}  // namespace

std::vector<std::string> dataset_mismatches(const std::vector<RunResults>& runs,
                                            const std::vector<std::string>& labels) {
  std::vector<std::string> mismatches;
  for (const auto& dataset : all_datasets(runs)) {
    std::optional<std::size_t> first;  // the first run with this dataset: the reference
    for (std::size_t r = 0; r < runs.size(); ++r) {
      if (std::find(runs[r].datasets.begin(), runs[r].datasets.end(), dataset) ==
          runs[r].datasets.end()) {
        continue;
      }
      if (!first) {
        first = r;
        continue;
      }
      const auto reference = dataset_config(runs[*first], dataset);
      const auto other = dataset_config(runs[r], dataset);
      if (reference != other) {
        mismatches.push_back(fmt::format(
            "dataset '{}' differs between runs '{}' and '{}' (their summary.json config: {} vs "
            "{}); its rows and curves compare different data",
            dataset, labels[*first], labels[r], reference.dump(), other.dump()));
      }
    }
  }
  return mismatches;
}

std::vector<std::string> comparison_labels(const std::vector<RunResults>& runs) {
  std::vector<std::string> labels;
  for (const auto& run : runs) labels.push_back(run.experiment);
  auto disambiguate = [&](auto&& rename) {
    std::map<std::string, int> count;
    for (const auto& l : labels) ++count[l];
    for (std::size_t r = 0; r < runs.size(); ++r) {
      if (count[labels[r]] > 1) labels[r] = rename(r);
    }
  };
  disambiguate([&](std::size_t r) {
    fs::path folder = fs::absolute(runs[r].folder).lexically_normal();
    if (!folder.has_filename()) folder = folder.parent_path();
    return fmt::format("{} ({})", runs[r].experiment, folder.filename().string());
  });
  disambiguate([&](std::size_t r) { return fmt::format("{} #{}", labels[r], r + 1); });
  return labels;
}

ReportOutcome write_comparison(const std::vector<fs::path>& folders, const fs::path& out) {
  if (folders.empty()) throw ResultsError("compare: at least one results folder expected");
  std::vector<RunResults> runs;
  for (const auto& folder : folders) runs.push_back(read_run_results(folder));
  const fs::path target = resolve_comparison_folder(out, folders);
  const auto labels = comparison_labels(runs);
  const auto datasets = all_datasets(runs);

  ReportOutcome outcome;
  const auto mismatches = dataset_mismatches(runs, labels);
  outcome.warnings = mismatches;
  const fs::path staging =
      target.parent_path() / fmt::format("{}.partial.{}", target.filename().string(), ::getpid());
  try {
    remove_stale_staging(target.parent_path(), target.filename().string() + ".partial.");
    fs::remove_all(staging);
    fs::create_directories(staging);
    const auto figures = comparison_figures(runs, labels, datasets);
    const auto shown =
        write_figures(staging / "figures", figures, target / "figures", outcome.warnings);
    outcome.figures = figures.size();
    for (const auto& figure : shown) outcome.drawn += figure.drawn ? 1 : 0;
    const Table table = comparison_table(runs, labels, datasets);
    write_text_file(staging / "compare.md", to_markdown(table));
    write_text_file(staging / "compare.csv", to_csv(table));
    write_text_file(staging / "compare.tex", to_latex(table));
    nlohmann::json record{{"radarpr_version", runs.front().summary["radarpr_version"]}};
    for (std::size_t r = 0; r < runs.size(); ++r) {
      record["runs"].push_back({{"label", labels[r]},
                                {"folder", fs::absolute(runs[r].folder).lexically_normal()},
                                {"experiment", runs[r].experiment}});
    }
    make_json_utf8(record);
    write_text_file(staging / "compare.json", record.dump(2) + "\n");
    write_text_file(staging / "index.html",
                    html_page("radarpr comparison",
                              comparison_sections(runs, labels, table, mismatches, shown)));
    if (fs::exists(target)) fs::remove_all(target);
    fs::rename(staging, target);
  } catch (const std::exception& error) {
    std::error_code ignored;
    fs::remove_all(staging, ignored);
    throw ResultsError(
        fmt::format("{}: cannot write the comparison ({})", target.string(), error.what()));
  }
  return outcome;
}

}  // namespace radarpr
