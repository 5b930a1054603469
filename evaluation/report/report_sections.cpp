#include "evaluation/report/report_sections.hpp"

#include <fmt/format.h>

#include "evaluation/report/figure_files.hpp"
#include "evaluation/report/matrix_figures.hpp"
#include "evaluation/results/paper_tables.hpp"

namespace radarpr {
namespace {

// The figures whose name is `name`, or starts with it when `prefix`.
std::string figures_html(const std::vector<PageFigure>& figures, const std::string& name,
                         bool prefix = false) {
  std::string html;
  for (const auto& figure : figures) {
    if (prefix ? figure.name.starts_with(name) : figure.name == name) {
      html += figure_html(figure);
    }
  }
  return html;
}

// Which label rule, sweep and AUC variant produced Table I: the same matches give a very
// different AUC under another label rule, so the table says which one it shows.
std::string metrics_table_note(const nlohmann::json& summary) {
  const nlohmann::json protocol = summary.value("protocol", nlohmann::json::object());
  const auto get = [&](const char* key) {
    return protocol.contains(key) ? json_text(protocol[key]) : std::string("?");
  };
  const std::string auc =
      protocol.contains("roc_auc") && protocol["roc_auc"] == "pooled_pairs"
          ? "pooled over every accepted pair at every threshold (<code>pooled_pairs</code>)"
          : "the trapezoid over the sweep";
  return fmt::format(
      "<p>ROC AUC: {}, with labels <code>{}</code> and threshold sweep <code>{}</code>; another "
      "label rule gives another AUC from the same matches (see Protocol below).</p>\n",
      auc, html_escape(get("labels")), html_escape(get("sweep")));
}

}  // namespace

std::string json_text(const nlohmann::json& value) {
  if (value.is_string()) return value.get<std::string>();
  if (value.is_number_float()) return fmt::format("{}", value.get<double>());
  return value.dump();
}

std::string protocol_html(const nlohmann::json& protocol) {
  const auto get = [&](const char* key) {
    return protocol.contains(key) ? json_text(protocol[key]) : std::string("?");
  };
  // The keys a record names only when they differ from radarpr's own protocol.
  const bool strict =
      protocol.contains("threshold_comparison") && protocol["threshold_comparison"] == "strict";
  const bool pooled = protocol.contains("roc_auc") && protocol["roc_auc"] == "pooled_pairs";
  const std::string preset =
      protocol.contains("preset")
          ? fmt::format("Protocol preset <code>{}</code>. ", html_escape(get("preset")))
          : std::string();
  return fmt::format(
      "<p>{}Revisit radius {} m; labels <code>{}</code>; threshold sweep <code>{}</code>; a query "
      "is accepted when its top-1 distance {} the threshold. ROC AUC: {}. F1-max: best F1 over "
      "the sweep. Recall@K: share of revisit "
      "queries with a frame within the radius among the K nearest. Matching graphs are drawn at "
      "the F1-max threshold. Counting as in the radarpr specification, "
      "<code>protocols.md</code>.</p>\n<pre>{}</pre>\n",
      preset, html_escape(get("revisit_radius_m")), html_escape(get("labels")),
      html_escape(get("sweep")), strict ? "&lt;" : "&lt;=",
      pooled ? "<code>pooled_pairs</code>, every pair accepted at every threshold pooled (label: "
               "wrong, score: distance), as the ReFeree code computes it"
             : "trapezoid over the sweep with (0,0) and (1,1) added",
      html_escape(protocol.dump(2)));
}

std::vector<PageSection> report_sections(const RunResults& run, const ReportTables& tables,
                                         const std::optional<std::string>& auc_note,
                                         const std::vector<PageFigure>& figures) {
  const nlohmann::json& s = run.summary;
  std::vector<PageSection> sections;

  std::string overview =
      fmt::format("<p>Experiment <code>{}</code>, radarpr {}.</p>\n", html_escape(run.experiment),
                  html_escape(json_text(s["radarpr_version"])));
  if (s.contains("description") && s["description"].is_string() &&
      !s["description"].get<std::string>().empty()) {
    overview += "<p>" + html_escape(s["description"].get<std::string>()) + "</p>\n";
  }
  overview += "<ul>\n";
  for (const auto& dataset : run.datasets) {
    overview += fmt::format("<li><code>{}</code>: {} session</li>\n", html_escape(dataset),
                            run.multi_session(dataset) ? "multi" : "single");
  }
  overview += "</ul>\n";
  sections.push_back({"Overview", overview});

  // Table I with Recall@1 beside the ReFeree paper's two metrics; its files keep the paper's.
  sections.push_back(
      {kPageMetricsTableTitle,
       to_html(metrics_recall_table(run)) + metrics_table_note(s) +
           "<p>R@1: share of the revisit queries whose nearest frame lies within the revisit "
           "radius. Best per column in bold. Also <code>table1.md</code>, "
           "<code>table1.csv</code>, <code>table1.tex</code> (ROC AUC and F1-max, the ReFeree "
           "paper's Table I; R@1 is in <code>table4.*</code>).</p>\n"});
  sections.push_back(
      {kRetrievalTableTitle,
       to_html(tables.retrieval) +
           "<p>PR-AUC: trapezoid over the swept (recall, precision) points. R@1: share of the "
           "revisit queries whose nearest frame lies within the revisit radius. R@100P: the "
           "recall at the highest threshold that accepts no false positive. n/a: undefined "
           "(no revisit, or no threshold without a false positive). Best per column in bold. "
           "Also <code>table4.md</code>, <code>table4.csv</code>, <code>table4.tex</code>.</p>\n"});
  sections.push_back(
      {kSizeTableTitle,
       to_html(tables.sizes) +
           "<p>Payload bytes: the values as stored, in the element type shown. Paper bytes: "
           "elements x 8 + 128, a float64 numpy file, the ReFeree paper's size convention. Also "
           "<code>table2.md</code>, <code>table2.csv</code>, <code>table2.tex</code>.</p>\n"});
  std::string auc_size =
      "<p>Each point is a descriptor configuration's ROC AUC <em>averaged over the datasets of "
      "one session kind</em> (single or multi session); the values plotted:</p>\n" +
      to_html(tables.auc_means) +
      "<p>Also <code>table3.md</code>, <code>table3.csv</code>, <code>table3.tex</code>.</p>\n";
  if (auc_note) {
    auc_size += "<p class=\"warning\">Note: " + html_escape(*auc_note) + ".</p>\n";
  }
  sections.push_back(
      {"ROC AUC against descriptor size (mean per session kind)",
       auc_size + figures_html(figures, "auc_vs_size") + figures_html(figures, "auc_per_kb")});
  std::string curves;
  for (const auto& dataset : run.datasets) {
    curves += fmt::format("<h3>{}</h3>\n", html_escape(dataset)) +
              figures_html(figures, "pr_" + figure_stem(dataset)) +
              figures_html(figures, "roc_" + figure_stem(dataset)) +
              figures_html(figures, "recall_at_n_" + figure_stem(dataset));
  }
  const std::string matrices = matrix_section_html(run, figures);
  if (!matrices.empty()) {
    sections.push_back({"Session matrices: heat maps and box plots per pair", matrices});
  }
  sections.push_back({"Precision-recall, ROC and Recall@N curves", curves});
  sections.push_back(
      {"Matching graphs",
       "<p>Trajectory in x-y (one scale) with the frame index as height (in a multi session the "
       "database session's frames first, then the query session's), and the same seen "
       "from above; at the F1-max threshold each accepted query is joined to its match, green "
       "for a true positive, red for a false positive (with <code>--missed</code>, each missed "
       "revisit in blue to the nearest frame it should have found).</p>\n" +
           figures_html(figures, "graph", /*prefix=*/true)});
  sections.push_back({"Protocol", protocol_html(s.value("protocol", nlohmann::json::object()))});

  std::string ids = "<ul>\n";
  for (const auto& id : run.descriptors) ids += "<li><code>" + html_escape(id) + "</code></li>\n";
  sections.push_back({"Descriptors", ids + "</ul>\n"});

  // The times and the machine change from run to run: the page only points at them, so that a
  // rerun (any thread count, values extracted or read from the cache) reproduces it byte for
  // byte. Results written before timing.json existed kept them in summary.json.
  std::string timing;
  if (run.timing.is_object()) {
    timing =
        "<p>The run time, the machine and each descriptor's extraction time per scan are in <a "
        "href=\"timing.json\">timing.json</a>, kept apart so that this page holds only what a "
        "rerun reproduces.</p>\n";
  } else if (s.contains("machine")) {
    timing = "<p>The run time and the machine are in summary.json.</p>\n";
  } else {
    timing =
        "<p>The run time and the machine were not recorded: these results hold no timing.json "
        "(reference results keep only what a rerun reproduces).</p>\n";
  }
  sections.push_back({"Machine and timing", timing});
  return sections;
}

}  // namespace radarpr
