#include "evaluation/report/figure_files.hpp"

#include <algorithm>
#include <cmath>
#include <map>

#include <fmt/format.h>

namespace radarpr {
namespace {

constexpr int kWidth = 900;
constexpr int kHeight = 640;

// A gnuplot single-quoted string: a quote is doubled, nothing else is special.
std::string gp_string(const std::string& text) {
  std::string result = "'";
  for (char c : text) result += c == '\'' ? std::string("''") : std::string(1, c);
  return result + "'";
}

std::string csv_text(const std::string& text) {
  std::string result = "\"";
  for (char c : text) result += c == '"' ? std::string("\"\"") : std::string(1, c);
  return result + "\"";
}

// The lines every script shares: CSV input, SVG output, then the same plot again as PNG
// (pngcairo when this gnuplot has it, else the libgd png terminal). `plot` is the full
// plot/splot command; `settings` the axes and labels.
std::string script(const std::string& name, const std::string& what, const std::string& settings,
                   const std::string& plot) {
  return fmt::format(
      "# radarpr figure: {what}.\n"
      "# Run `gnuplot {name}.gp` in this folder: it reads {name}.csv (blocks separated by two\n"
      "# blank lines, selected with `index`) and writes {name}.svg and {name}.png.\n"
      "set datafile separator comma\n"
      "set terminal svg size {w},{h} font 'sans,12' background rgb 'white' noenhanced\n"
      "set output '{name}.svg'\n"
      "{settings}"
      "{plot}\n"
      "if (strstrt(GPVAL_TERMINALS, 'pngcairo') > 0) {{\n"
      "  set terminal pngcairo size {w},{h} font 'sans,11' background rgb 'white' noenhanced\n"
      "}} else {{\n"
      "  set terminal png size {w},{h} background rgb 'white' noenhanced\n"
      "}}\n"
      "set output '{name}.png'\n"
      "replot\n"
      "unset output\n",
      fmt::arg("what", what), fmt::arg("name", name), fmt::arg("w", kWidth), fmt::arg("h", kHeight),
      fmt::arg("settings", settings), fmt::arg("plot", plot));
}

// The sweep point at the F1-max threshold (the curve holds it exactly; nearest to be safe).
const SweepPoint* f1_point(const CurveSeries& series) {
  if (!series.f1_max_threshold || series.curve->empty()) return nullptr;
  return &*std::min_element(series.curve->begin(), series.curve->end(),
                            [&](const SweepPoint& a, const SweepPoint& b) {
                              return std::abs(a.threshold - *series.f1_max_threshold) <
                                     std::abs(b.threshold - *series.f1_max_threshold);
                            });
}

enum class CurveKind { pr, roc };

FigureFiles curve_figure(CurveKind kind, const std::string& name, const std::string& title,
                         const std::vector<CurveSeries>& series) {
  const bool pr = kind == CurveKind::pr;
  FigureFiles figure{name, title, "", ""};
  figure.csv = pr ? "recall,precision,threshold,series\n" : "fpr,tpr,threshold,series\n";
  std::string plots;
  std::string points_block;
  int block = 0;
  std::vector<std::size_t> with_point;  // series index of each F1-max row
  for (std::size_t s = 0; s < series.size(); ++s) {
    const CurveSeries& line = series[s];
    std::string rows;
    // ROC AUC integrates from (0,0) to (1,1) (protocols.md): the figure shows those ends too.
    if (!pr) rows += fmt::format("0,0,,{}\n", csv_text(line.title));
    for (const auto& p : *line.curve) {
      if (pr && !p.precision) continue;  // nothing accepted: precision undefined
      rows += pr ? fmt::format("{},{},{},{}\n", p.recall, *p.precision, p.threshold,
                               csv_text(line.title))
                 : fmt::format("{},{},{},{}\n", p.fpr, p.recall, p.threshold, csv_text(line.title));
    }
    if (!pr) rows += fmt::format("1,1,,{}\n", csv_text(line.title));
    if (rows.empty()) continue;
    figure.csv += (block ? "\n\n" : "") + rows;
    const std::string key =
        pr ? fmt::format("{} (F1-max {})", line.title,
                         line.f1_max ? fmt::format("{:.3f}", *line.f1_max) : "n/a")
           : fmt::format("{} (AUC {})", line.title,
                         line.roc_auc ? fmt::format("{:.3f}", *line.roc_auc) : "n/a");
    plots += fmt::format("{}'{}.csv' skip 1 index {} using 1:2 with lines lw 2 lc {} title {}",
                         plots.empty() ? "" : ", \\\n     ", name, block, s + 1, gp_string(key));
    ++block;
    if (const SweepPoint* p = f1_point(line); p != nullptr && (!pr || p->precision)) {
      points_block +=
          pr ? fmt::format("{},{},{},{}\n", p->recall, *p->precision, p->threshold,
                           csv_text(line.title))
             : fmt::format("{},{},{},{}\n", p->fpr, p->recall, p->threshold, csv_text(line.title));
      with_point.push_back(s);
    }
  }
  if (!points_block.empty()) {
    figure.csv += (block ? "\n\n" : "") + points_block;
    for (std::size_t i = 0; i < with_point.size(); ++i) {
      plots += fmt::format(
          ", \\\n     '{}.csv' skip 1 index {} every ::{}::{} using 1:2 with points pt 7 ps 1.6 "
          "lc {} {}",
          name, block, i, i, with_point[i] + 1, i == 0 ? "title 'F1-max'" : "notitle");
    }
  }
  // The ROC chance diagonal goes first so that the curves draw over it.
  const std::string lead =
      pr ? "plot " : "plot x with lines dt 2 lc rgb 'gray70' notitle, \\\n     ";
  plots = plots.empty() ? "set label 1 'no data' at graph 0.5, graph 0.5 center\nplot NaN notitle"
                        : lead + plots;
  const std::string settings = fmt::format(
      "set title {}\nset xlabel {}\nset ylabel {}\nset xrange [0:1]\nset yrange [0:1.02]\n"
      "set key {} box opaque\nset grid\n",
      gp_string(title), gp_string(pr ? "recall" : "false positive rate"),
      gp_string(pr ? "precision" : "true positive rate (recall)"),
      pr ? "bottom left" : "bottom right");
  figure.script = script(name, pr ? "precision-recall curves" : "ROC curves", settings, plots);
  return figure;
}

}  // namespace

std::string figure_stem(const std::string& text) {
  std::string stem;
  for (char c : text) {
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '_' || c == '.' || c == '=' || c == '-';
    stem += safe ? c : '_';
  }
  return stem;
}

FigureFiles pr_figure(const std::string& name, const std::string& title,
                      const std::vector<CurveSeries>& series) {
  return curve_figure(CurveKind::pr, name, title, series);
}

FigureFiles roc_figure(const std::string& name, const std::string& title,
                       const std::vector<CurveSeries>& series) {
  return curve_figure(CurveKind::roc, name, title, series);
}

FigureFiles matching_graph_figure(const std::string& name, const std::string& title,
                                  const ResultRow& row, const DatasetTrajectory& trajectory,
                                  bool include_missed) {
  // Height: the frame index; a multi session stacks the query session above the database.
  std::size_t database_frames = 0;
  for (const auto& p : trajectory.database)
    database_frames = std::max(database_frames, p.frame + 1);
  for (const auto& e : row.graph) database_frames = std::max(database_frames, e.match + 1);
  const std::size_t query_offset = row.multi_session ? database_frames : 0;
  FigureFiles figure{name, title, "x,y,z,dx,dy,dz,kind\n", ""};
  std::vector<std::string> blocks;
  std::string plots;
  auto add_block = [&](const std::string& rows, const std::string& plot) {
    if (rows.empty()) return;
    plots += fmt::format("{}'{}.csv' skip 1 index {} {}", plots.empty() ? "splot " : ", \\\n      ",
                         name, blocks.size(), plot);
    blocks.push_back(rows);
  };
  auto path_rows = [](const std::vector<TrajectoryPoint>& points, std::size_t offset,
                      const char* kind) {
    std::string rows;
    for (const auto& p : points) {
      rows += fmt::format("{},{},{},0,0,0,{}\n", p.x, p.y, p.frame + offset, kind);
    }
    return rows;
  };
  add_block(path_rows(trajectory.query, query_offset, row.multi_session ? "query path" : "path"),
            fmt::format("using 1:2:3 with lines lw 1 lc rgb 'gray55' title '{}'",
                        row.multi_session ? "query trajectory" : "trajectory"));
  add_block(path_rows(trajectory.database, 0, "database path"),
            "using 1:2:3 with lines lw 1 lc rgb 'gray75' title 'database trajectory'");
  std::map<std::string, std::string> rows_of;
  std::map<std::string, std::size_t> count_of;
  for (const auto& e : row.graph) {
    const double qz = static_cast<double>(e.query + query_offset);
    const double mz = static_cast<double>(e.match);
    rows_of[e.label] += fmt::format("{},{},{},{},{},{},{}\n", e.query_x, e.query_y, qz,
                                    e.match_x - e.query_x, e.match_y - e.query_y, mz - qz, e.label);
    ++count_of[e.label];
  }
  add_block(rows_of["tp"], fmt::format("using 1:2:3:4:5:6 with vectors nohead lw 1 lc rgb "
                                       "'#1a9641' title 'TP ({})'",
                                       count_of["tp"]));
  add_block(rows_of["fp"], fmt::format("using 1:2:3:4:5:6 with vectors nohead lw 1 lc rgb "
                                       "'#d7191c' title 'FP ({})'",
                                       count_of["fp"]));
  if (include_missed) {
    add_block(rows_of["fn"], fmt::format("using 1:2:3 with points pt 6 ps 0.8 lc rgb '#2c7bb6' "
                                         "title 'missed revisit ({})'",
                                         count_of["fn"]));
  }
  for (std::size_t b = 0; b < blocks.size(); ++b) figure.csv += (b ? "\n\n" : "") + blocks[b];
  if (plots.empty()) {
    plots =
        "set label 1 'no accepted query (F1-max undefined)' at screen 0.5, screen 0.5 "
        "center\nsplot NaN notitle";
  }
  const std::string settings = fmt::format(
      "set title {}\nset xlabel 'x [m]'\nset ylabel 'y [m]'\nset zlabel {} rotate parallel\n"
      "set view 60, 35\nset ticslevel 0\nset key top left box opaque\nset grid\n",
      gp_string(title),
      gp_string(row.multi_session ? "frame (database, then query session)" : "frame"));
  figure.script = script(name, "matching graph at the F1-max threshold", settings, plots);
  return figure;
}

FigureFiles auc_size_figure(const std::string& name, const RunResults& run) {
  // (session kind, descriptor, payload bytes) -> AUCs over the datasets of that kind.
  struct Point {
    std::string label;
    double bytes = 0.0;
    double auc_sum = 0.0;
    int datasets = 0;
  };
  std::map<std::tuple<bool, std::string, double>, Point> points;
  std::vector<std::tuple<bool, std::string, double>> order;
  for (const auto& row : run.rows) {
    if (!row.roc_auc) continue;
    const auto key = std::make_tuple(row.multi_session, row.descriptor, row.payload_bytes);
    if (!points.contains(key)) order.push_back(key);
    Point& p = points[key];
    p.label = row.label;
    p.bytes = row.payload_bytes;
    p.auc_sum += *row.roc_auc;
    ++p.datasets;
  }
  FigureFiles figure{name, "ROC AUC against descriptor payload size", "", ""};
  figure.csv = "payload_bytes,roc_auc,session,descriptor,datasets\n";
  std::string plots;
  int block = 0;
  double low = 0.0, high = 0.0;
  for (const bool multi : {false, true}) {
    // Configurations that land on the same spot (same size, same AUC to 3 decimals) share one
    // point and one label, "a / b", instead of printing their labels over each other.
    std::vector<std::pair<std::string, Point>> spots;  // key "bytes|auc" -> merged point
    for (const auto& key : order) {
      if (std::get<0>(key) != multi) continue;
      const Point& p = points[key];
      const std::string spot = fmt::format("{}|{:.3f}", p.bytes, p.auc_sum / p.datasets);
      const auto same =
          std::find_if(spots.begin(), spots.end(), [&](const auto& s) { return s.first == spot; });
      if (same == spots.end()) {
        spots.emplace_back(spot, p);
      } else {
        same->second.label += " / " + p.label;
      }
    }
    std::string rows;
    for (const auto& [spot, p] : spots) {
      rows += fmt::format("{},{},{},{},{}\n", p.bytes, p.auc_sum / p.datasets,
                          multi ? "multi" : "single", csv_text(p.label), p.datasets);
      low = low == 0.0 ? p.bytes : std::min(low, p.bytes);
      high = std::max(high, p.bytes);
    }
    if (rows.empty()) continue;
    figure.csv += (block ? "\n\n" : "") + rows;
    plots += fmt::format(
        "{}'{}.csv' skip 1 index {} using 1:2 with points pt {} ps 1.8 lc rgb '{}' title {}, \\\n"
        "     '' skip 1 index {} using 1:2:4 with labels left offset char 1,{} font ',9' "
        "textcolor rgb '{}' notitle",
        plots.empty() ? "plot " : ", \\\n     ", name, block, multi ? 9 : 7,
        multi ? "#d95f02" : "#1b9e77",
        gp_string(multi ? "multi session (mean over datasets)"
                        : "single session (mean over datasets)"),
        block, multi ? "-0.6" : "0.6", multi ? "#d95f02" : "#1b9e77");
    ++block;
  }
  if (plots.empty()) {
    plots = "set label 1 'no defined ROC AUC' at graph 0.5, graph 0.5 center\nplot NaN notitle";
    low = 1.0;
    high = 10.0;
  }
  // A log axis needs a positive range; a decade of margin each side leaves room for labels.
  const std::string settings = fmt::format(
      "set title {}\nset logscale x\nset xrange [{}:{}]\nset yrange [0:1.05]\n"
      "set xlabel 'payload bytes (log scale)'\nset ylabel 'ROC AUC'\n"
      "set key bottom right box opaque\nset grid\n",
      gp_string(figure.caption), std::max(low, 1.0) / 3.0, high * 6.0);
  figure.script = script(name, "ROC AUC against descriptor size", settings, plots);
  return figure;
}

}  // namespace radarpr
