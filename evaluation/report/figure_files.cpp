#include "evaluation/report/figure_files.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <utility>

#include <fmt/format.h>

#include "evaluation/report/figure_style.hpp"
#include "evaluation/report/point_labels.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

constexpr int kWidth = 900;
constexpr int kHeight = 640;
// Curve points closer than this (in both coordinates) to the previous one drawn are left out.
constexpr double kCurveStep = 1e-3;

// The series column of a figure's data: always quoted (gnuplot reads the file, and a quoted
// field keeps one row per line whatever the label holds).
std::string csv_text(const std::string& text) {
  return csv_field(text, CsvQuoting::always);
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

std::string colour_of(std::size_t index) {
  const auto& palette = figure_palette();
  return palette[index % palette.size()];
}

// The F1-max points are drawn in their curve's colour; the key shows one neutral marker for all.
std::string f1_marker(FigureStyle style) {
  return style == FigureStyle::paper ? "pt 7 ps 0.9" : "pt 7 ps 1.6";
}

// A curve's own marker, by its colour index: open shapes (the filled circle marks F1-max).
int curve_marker(std::size_t colour) {
  static constexpr int kMarkers[] = {4, 6, 8, 12, 10, 14, 1, 2, 3};
  return kMarkers[colour % std::size(kMarkers)];
}

// Markers every this many drawn points; a different interval per series, so that two identical
// curves show their markers at different places (the later one does not hide the earlier).
std::size_t marker_interval(std::size_t rows, std::size_t series) {
  return std::max<std::size_t>(2, rows / 7) + 3 * series;
}

FigureFiles curve_figure(CurveKind kind, const std::string& name, const std::string& title,
                         const std::vector<CurveSeries>& series, KeyPlace key_place,
                         FigureStyle style) {
  const bool pr = kind == CurveKind::pr;
  const bool paper = style == FigureStyle::paper;
  const std::string kF1Marker = f1_marker(style);
  FigureFiles figure{name, title, "", ""};
  figure.csv = pr ? "recall,precision,threshold,series\n" : "fpr,tpr,threshold,series\n";
  std::string plots;
  std::string points_block;
  int block = 0;
  std::vector<std::size_t> with_point;  // series index of each F1-max row
  std::vector<std::string> key_titles;
  for (std::size_t s = 0; s < series.size(); ++s) {
    const CurveSeries& line = series[s];
    std::string rows;
    // ROC AUC integrates from (0,0) to (1,1) (protocols.md): the figure shows those ends too.
    if (!pr) rows += fmt::format("0,0,,{}\n", csv_text(line.title));
    std::vector<const SweepPoint*> drawn;
    for (const auto& p : *line.curve) {
      if (!pr || p.precision) drawn.push_back(&p);  // PR: nothing accepted, precision undefined
    }
    std::optional<std::pair<double, double>> kept;
    std::size_t kept_rows = pr ? 0 : 2;
    for (std::size_t i = 0; i < drawn.size(); ++i) {
      const SweepPoint& p = *drawn[i];
      const double x = pr ? p.recall : p.fpr, y = pr ? *p.precision : p.recall;
      // Thinned: a point within 1e-3 (under a pixel) of the last one kept adds nothing to the
      // line; the ends are always kept, the F1-max points are a block of their own.
      if (kept && i + 1 < drawn.size() && std::abs(x - kept->first) <= kCurveStep &&
          std::abs(y - kept->second) <= kCurveStep) {
        continue;
      }
      kept = std::make_pair(x, y);
      ++kept_rows;
      rows += fmt::format("{},{},{},{}\n", x, y, p.threshold, csv_text(line.title));
    }
    if (!pr) rows += fmt::format("1,1,,{}\n", csv_text(line.title));
    if (rows.empty()) continue;
    figure.csv += (block ? "\n\n" : "") + rows;
    const std::string key =
        pr ? fmt::format("{} (F1-max {})", line.title,
                         line.f1_max ? fmt::format("{:.3f}", *line.f1_max) : "n/a")
           : fmt::format("{} (AUC {})", line.title,
                         line.roc_auc ? fmt::format("{:.3f}", *line.roc_auc) : "n/a");
    // Colour, dash type and marker apart: curves stay told apart in grey print, and identical
    // ones stay visible.
    plots += fmt::format(
        "{}'{}.csv' skip 1 index {} using 1:2 with linespoints lw {} dt {} pt {} ps {} pi {} lc "
        "rgb '{}' title {}",
        plots.empty() ? "" : ", \\\n     ", name, block, paper ? "2.5" : "3", line.dash,
        curve_marker(line.colour), paper ? "0.6" : "1.2", marker_interval(kept_rows, s),
        colour_of(line.colour), gnuplot_string(key));
    key_titles.push_back(key);
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
          ", \\\n     '{}.csv' skip 1 index {} every ::{}::{} using 1:2 with points {} lc rgb "
          "'{}' notitle",
          name, block, i, i, kF1Marker, colour_of(series[with_point[i]].colour));
    }
    plots += fmt::format(", \\\n     NaN with points {} lc rgb 'black' title 'F1-max'", kF1Marker);
    key_titles.push_back("F1-max");
  }
  // The ROC chance diagonal goes first so that the curves draw over it.
  const std::string lead =
      pr ? "plot " : "plot x with lines lw 1.5 dt 2 lc rgb 'gray60' title 'chance', \\\n     ";
  if (!pr) key_titles.push_back("chance");
  plots = plots.empty() ? "set label 1 'no data' at graph 0.5, graph 0.5 center\nplot NaN notitle"
                        : lead + plots;
  const bool below = key_place == KeyPlace::below;
  // Wider with the key at the right, taller with it below: the plot keeps its size.
  FigureCanvas canvas{below ? kWidth : kWidth + 300, kHeight, 2.6};
  // Paper: the key inside, in the corner the curves leave empty (PR bottom left, ROC bottom
  // right), when it fits.
  const std::string key =
      below && !paper ? key_below(key_titles, style, canvas)
                      : styled_key(style, pr ? "left bottom" : "right bottom", key_titles, canvas);
  // ROC: square, the chance diagonal at 45 degrees.
  const std::string settings = fmt::format(
      "set xlabel {}\nset ylabel {}\nset xrange [0:1]\nset yrange [0:1.02]\n{}"
      "set key {}\nset grid\n",
      gnuplot_string(pr ? "recall" : "false positive rate"),
      gnuplot_string(pr ? "precision" : "true positive rate (recall)"),
      pr ? "" : "set size square\n", key);
  figure.script = figure_script(name, pr ? "precision-recall curves" : "ROC curves", title,
                                settings, plots, style, canvas);
  return figure;
}

}  // namespace

const std::vector<std::string>& figure_palette() {
  static const std::vector<std::string> palette = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                                   "#e69f00", "#56b4e9", "#882255", "#999933",
                                                   "#332288", "#44aa99", "#aa4499", "#117733"};
  return palette;
}

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
                      const std::vector<CurveSeries>& series, KeyPlace key, FigureStyle style) {
  return curve_figure(CurveKind::pr, name, title, series, key, style);
}

FigureFiles roc_figure(const std::string& name, const std::string& title,
                       const std::vector<CurveSeries>& series, KeyPlace key, FigureStyle style) {
  return curve_figure(CurveKind::roc, name, title, series, key, style);
}

namespace {

// A tick step of 1, 2 or 5 times a power of ten giving at most `ticks` intervals over `span`.
double nice_step(double span, int ticks) {
  if (!(span > 0.0)) return 1.0;
  const double raw = span / ticks;
  const double decade = std::pow(10.0, std::floor(std::log10(raw)));
  for (const double factor : {1.0, 2.0, 5.0, 10.0}) {
    if (factor * decade >= raw) return factor * decade;
  }
  return 10.0 * decade;
}

// Where a missed revisit's line goes: the eligible frame nearest the query (the loop it should
// have found), not the frame it wrongly retrieved. Eligible: every database frame in a multi
// session; in a single session the frames at least `exclude_recent_frames` older, or, when the
// recency window is in seconds (no timestamps in the results), those no newer than the retrieved
// frame (which was eligible). Nothing when no such frame lies within the radius.
std::optional<TrajectoryPoint> nearest_loop_frame(const GraphEdge& missed, const ResultRow& row,
                                                  const DatasetTrajectory& trajectory,
                                                  const MatchingGraphContext& context) {
  const auto& frames = row.multi_session ? trajectory.database : trajectory.query;
  std::optional<TrajectoryPoint> nearest;
  double best = context.revisit_radius_m * context.revisit_radius_m;
  for (const auto& frame : frames) {
    if (!row.multi_session) {
      const bool eligible = context.exclude_recent_frames
                                ? frame.frame + *context.exclude_recent_frames <= missed.query
                                : frame.frame <= missed.match;
      if (!eligible) continue;
    }
    const double dx = frame.x - missed.query_x, dy = frame.y - missed.query_y;
    const double d2 = dx * dx + dy * dy;
    if (d2 <= best) {
      best = d2;
      nearest = frame;
    }
  }
  return nearest;
}

}  // namespace

FigureFiles matching_graph_figure(const std::string& name, const std::string& title,
                                  const ResultRow& row, const DatasetTrajectory& trajectory,
                                  const MatchingGraphContext& context) {
  const bool paper = context.style == FigureStyle::paper;
  const bool top = context.top_view;
  // Height (3-D): the frame index; a multi session stacks the query session above the database.
  std::size_t database_frames = 0;
  for (const auto& p : trajectory.database)
    database_frames = std::max(database_frames, p.frame + 1);
  for (const auto& e : row.graph) database_frames = std::max(database_frames, e.match + 1);
  const std::size_t query_offset = row.multi_session ? database_frames : 0;
  FigureFiles figure{name, title, "x,y,z,dx,dy,dz,kind\n", ""};
  std::vector<std::string> blocks;
  std::string plots;
  const std::string columns = top ? "using 1:2" : "using 1:2:3";
  const std::string vectors = top ? "using 1:2:4:5" : "using 1:2:3:4:5:6";
  auto add_block = [&](const std::string& rows, const std::string& plot) {
    if (rows.empty()) return;
    plots += fmt::format("{}'{}.csv' skip 1 index {} {}",
                         plots.empty() ? (top ? "plot " : "splot ") : ", \\\n      ", name,
                         blocks.size(), plot);
    blocks.push_back(rows);
  };
  double low_x = 0.0, high_x = 0.0, low_y = 0.0, high_y = 0.0;
  bool any = false;
  auto path_rows = [&](const std::vector<TrajectoryPoint>& points, std::size_t offset,
                       const char* kind) {
    std::string rows;
    for (const auto& p : points) {
      rows += fmt::format("{},{},{},0,0,0,{}\n", p.x, p.y, p.frame + offset, kind);
      low_x = any ? std::min(low_x, p.x) : p.x;
      high_x = any ? std::max(high_x, p.x) : p.x;
      low_y = any ? std::min(low_y, p.y) : p.y;
      high_y = any ? std::max(high_y, p.y) : p.y;
      any = true;
    }
    return rows;
  };
  // The database session a wide light line, the query session a thin dark dashed one: two
  // styles that stay apart where the drives overlap. One key entry each.
  add_block(path_rows(trajectory.database, 0, "database path"),
            columns + " with lines lw 4 lc rgb '#c8c8c8' title 'database trajectory'");
  add_block(path_rows(trajectory.query, query_offset, row.multi_session ? "query path" : "path"),
            fmt::format("{} with lines lw 1 dt {} lc rgb '#404040' title '{}'", columns,
                        row.multi_session ? 2 : 1,
                        row.multi_session ? "query trajectory" : "trajectory"));
  std::map<std::string, std::string> rows_of;
  std::map<std::string, std::size_t> count_of;
  std::size_t missed_without_loop = 0;
  for (const auto& e : row.graph) {
    const double qz = static_cast<double>(e.query + query_offset);
    double mx = e.match_x, my = e.match_y, mz = static_cast<double>(e.match);
    if (e.label == "fn") {
      if (!context.include_missed) continue;
      const auto loop = nearest_loop_frame(e, row, trajectory, context);
      if (!loop) {
        ++missed_without_loop;
        continue;
      }
      mx = loop->x;
      my = loop->y;
      mz = static_cast<double>(loop->frame);
    }
    rows_of[e.label] += fmt::format("{},{},{},{},{},{},{}\n", e.query_x, e.query_y, qz,
                                    mx - e.query_x, my - e.query_y, mz - qz, e.label);
    ++count_of[e.label];
  }
  // TP thin and translucent (gnuplot's #AARRGGBB: AA = transparency), so that the FP lines and
  // missed loops drawn over them stay readable.
  add_block(rows_of["tp"],
            fmt::format("{} with vectors nohead lw {} lc rgb '#a01a9641' title 'TP ({})'", vectors,
                        paper ? "1" : "0.8", count_of["tp"]));
  if (context.include_missed) {
    add_block(rows_of["fn"],
              fmt::format("{} with vectors nohead lw 1.5 dt 3 lc rgb '#2c7bb6' title 'missed "
                          "revisit ({})'",
                          vectors, count_of["fn"]));
  }
  add_block(rows_of["fp"], fmt::format("{} with vectors nohead lw {} lc rgb '#d7191c' title "
                                       "'FP ({})'",
                                       vectors, paper ? "2" : "1.5", count_of["fp"]));
  for (std::size_t b = 0; b < blocks.size(); ++b) figure.csv += (b ? "\n\n" : "") + blocks[b];
  if (missed_without_loop > 0) {
    figure.csv += fmt::format(
        "# note: {} missed revisits have no eligible frame within {} m "
        "in the trajectory: not drawn\n",
        missed_without_loop, context.revisit_radius_m);
  }
  if (plots.empty()) {
    plots = fmt::format(
        "set label 1 'no accepted query (F1-max undefined)' at screen 0.5, screen 0.5 "
        "center\n{} NaN notitle",
        top ? "plot" : "splot");
  }
  // x and y at one scale; ticks 1-2-5 apart, at most 4 intervals per axis, so that the labels
  // of the two horizontal axes never meet at the corner.
  const double step = nice_step(std::max(high_x - low_x, high_y - low_y), paper ? 3 : 4);
  // In 3-D the y ticks start one step in: its first label would sit where the x axis ends.
  const double first_y = (std::floor(low_y / step) + (top ? 0.0 : 1.0)) * step;
  std::string settings = fmt::format(
      "set xlabel 'x [m]'\nset ylabel 'y [m]'\nset xtics {}\nset ytics {}, {}\nset grid\n", step,
      first_y, step);
  const std::string key_look = paper ? " samplen 1.5 spacing 0.9 font ',7'" : "";
  if (top) {
    settings += fmt::format(
        "set size ratio -1\nset key outside right top vertical Left reverse "
        "box{}\n",
        key_look);
  } else {
    settings += fmt::format(
        "set zlabel {} rotate parallel\nset view 60, 35\nset view equal xy\nset ticslevel 0\n"
        "set xtics offset 0,-0.5\nset ytics offset {}\n{}"
        "set key at screen 0.01, screen {} left top Left reverse box opaque{}\n",
        // Along the paper column's short z axis a longer name runs into the key (the report's
        // page says the database's frames come first).
        gnuplot_string(row.multi_session && !paper ? "frame (database, then query session)"
                                                   : "frame"),
        // The paper column's 8 pt labels are large beside its small plot: the y labels and
        // both axis names further out, clear of the x labels at the corner they share.
        paper ? "2.5,0" : "1,-0.5", paper ? "set xlabel offset -3,-1\nset ylabel offset 2,0\n" : "",
        paper ? "0.99" : "0.93", key_look);
  }
  if (context.threshold_text) {
    settings += "set key title " + gnuplot_string(*context.threshold_text) + "\n";
  }
  figure.script =
      figure_script(name,
                    top ? "matching graph at the F1-max threshold, top view"
                        : "matching graph at the F1-max threshold",
                    title, settings, plots, context.style,
                    FigureCanvas{top ? kWidth + 300 : kWidth, kHeight, top ? 2.6 : 3.2});
  return figure;
}

namespace {

// An integer in Unicode superscript digits (UTF-8): -3 -> "⁻³".
std::string superscript(int value) {
  static const char* const kDigits[] = {"\u2070", "\u00b9", "\u00b2", "\u00b3", "\u2074",
                                        "\u2075", "\u2076", "\u2077", "\u2078", "\u2079"};
  std::string text = value < 0 ? "\u207b" : "";
  for (const char c : std::to_string(value < 0 ? -value : value)) text += kDigits[c - '0'];
  return text;
}

}  // namespace

FigureFiles auc_size_figure(const std::string& name, const std::vector<AucSizePoint>& points,
                            FigureStyle style) {
  const bool paper = style == FigureStyle::paper;
  FigureFiles figure{name,
                     "ROC AUC against descriptor payload size: per session kind, the mean over "
                     "its datasets",
                     "", ""};
  figure.csv = "payload_bytes,mean_roc_auc,session,descriptor,datasets_averaged,datasets_run\n";
  if (const auto note = auc_size_unequal_note(points)) figure.csv += "# note: " + *note + "\n";
  std::string plots;
  int block = 0;
  double low_bytes = 0.0, high_bytes = 0.0, low_auc = 1.0, high_auc = 0.0;
  std::vector<std::size_t> titled;  // descriptors already in the key
  std::vector<std::string> key_titles;
  std::vector<const AucSizePoint*> labelled;
  // Single: a filled circle; multi: an open square around where a circle would be.
  const std::string single_marker = paper ? "pt 7 ps 1.0" : "pt 7 ps 1.8";
  const std::string multi_marker = paper ? "pt 4 ps 1.5 lw 2" : "pt 4 ps 2.6 lw 2";
  bool kinds[2] = {false, false};
  // One block per point: its own colour (the descriptor's) and marker (the session kind's);
  // drawn descriptor by descriptor so that the key lists them in config order.
  std::vector<AucSizePoint> ordered = points;
  std::stable_sort(ordered.begin(), ordered.end(), [](const auto& a, const auto& b) {
    return a.descriptor_index < b.descriptor_index;
  });
  for (const auto& p : ordered) {
    if (!p.mean_auc) continue;
    figure.csv += fmt::format("{}{},{},{},{},{},{}\n", block ? "\n\n" : "", p.payload_bytes,
                              *p.mean_auc, p.multi_session ? "multi" : "single", csv_text(p.label),
                              p.datasets_averaged, p.datasets_run);
    const bool first = std::find(titled.begin(), titled.end(), p.descriptor_index) == titled.end();
    if (first) {
      titled.push_back(p.descriptor_index);
      key_titles.push_back(p.label);
    }
    kinds[p.multi_session ? 1 : 0] = true;
    // Single: a filled circle; multi: an open square around where a circle would be, so that a
    // configuration scoring alike in both kinds shows both markers.
    plots +=
        fmt::format("{}'{}.csv' skip 1 index {} using 1:2 with points {} lc rgb '{}' {}",
                    plots.empty() ? "plot " : ", \\\n     ", name, block,
                    p.multi_session ? multi_marker : single_marker, colour_of(p.descriptor_index),
                    first ? "title " + gnuplot_string(p.label) : std::string("notitle"));
    ++block;
    labelled.push_back(&p);
    low_bytes = low_bytes == 0.0 ? p.payload_bytes : std::min(low_bytes, p.payload_bytes);
    high_bytes = std::max(high_bytes, p.payload_bytes);
    low_auc = std::min(low_auc, *p.mean_auc);
    high_auc = std::max(high_auc, *p.mean_auc);
  }
  if (plots.empty()) {
    plots = "set label 1 'no defined ROC AUC' at graph 0.5, graph 0.5 center\nplot NaN notitle";
    low_bytes = 1.0;
    high_bytes = 10.0;
    low_auc = 0.0;
    high_auc = 1.0;
  } else {
    if (kinds[0]) {
      plots += fmt::format(
          ", \\\n     NaN with points {} lc rgb 'black' title 'single session (mean over "
          "datasets)'",
          single_marker);
      key_titles.push_back("single session (mean over datasets)");
    }
    if (kinds[1]) {
      plots += fmt::format(
          ", \\\n     NaN with points {} lc rgb 'black' title 'multi session (mean over "
          "datasets)'",
          multi_marker);
      key_titles.push_back("multi session (mean over datasets)");
    }
  }
  // The y range follows the data (a 0.05 grid with a margin), so that close AUCs stay apart, and
  // stops at 1 (an AUC's ceiling); a log axis needs a positive x range, widened by half a decade
  // each side.
  const double y_low = std::max(0.0, std::floor((low_auc - 0.03) * 20.0) / 20.0);
  const double y_high = std::min(1.0, std::ceil((high_auc + 0.03) * 20.0) / 20.0);
  const double x_low = std::max(low_bytes, 1.0) / 3.0, x_high = high_bytes * 3.0;
  // Each point named beside it, each label where it is clear of every marker and of the labels
  // before it and inside the plot (point_labels.hpp); the same descriptor's point of the other
  // session kind at the same place (within a tenth of a decade and 4 % of the y range) is not
  // named twice.
  const double y_span = std::max(y_high - y_low, 1e-9);
  const double log_low = std::log10(x_low), log_span = std::log10(x_high) - log_low;
  const auto at_of = [&](const AucSizePoint& p) {
    return LabelledPoint{(std::log10(p.payload_bytes) - log_low) / log_span,
                         (*p.mean_auc - y_low) / y_span, p.label.size()};
  };
  std::vector<LabelledPoint> markers, to_label;
  std::vector<const AucSizePoint*> named;
  for (const AucSizePoint* p : labelled) {
    markers.push_back(at_of(*p));
    const bool named_already = std::any_of(named.begin(), named.end(), [&](const auto* other) {
      return other->descriptor_index == p->descriptor_index &&
             std::abs(std::log10(other->payload_bytes) - std::log10(p->payload_bytes)) < 0.1 &&
             std::abs(*other->mean_auc - *p->mean_auc) < 0.04 * y_span;
    });
    if (named_already) continue;
    named.push_back(p);
    to_label.push_back(at_of(*p));
  }
  // The plot area in label characters and lines, as drawn (screen: 711 x 539 px at 8.4 px a
  // character and 16 px a line; paper: 2.34 x 2.2 in at 5.6 pt a character and 9.6 pt a line,
  // the column's plot made taller than the curves' for its labels).
  const LabelGrid grid = paper ? LabelGrid{30.0, 16.0} : LabelGrid{85.0, 33.0};
  const std::vector<LabelPlacement> places = place_point_labels(to_label, markers, grid);
  std::string labels;
  for (std::size_t i = 0; i < named.size(); ++i) {
    // In its point's colour: a label moved off its level still says whose it is.
    labels += fmt::format(
        "set label {} {} at {},{} offset char {},{} {} font ',{}' textcolor rgb '{}' front\n",
        10 + i, gnuplot_string(named[i]->label), named[i]->payload_bytes, *named[i]->mean_auc,
        places[i].dx_chars, places[i].dy_lines, places[i].left_of_point ? "right" : "left",
        paper ? 7 : 10, colour_of(named[i]->descriptor_index));
  }
  // Decades as powers of ten (10², in Unicode superscripts: the terminals draw text as is), with
  // 2 and 5 labelled in between where a decade is wide enough for three labels (the paper
  // style's narrow column over several decades: short unlabelled ticks there).
  const bool label_between = grid.width_chars / log_span >= 12.0;
  std::string xtics = "set xtics (";
  bool first_tic = true;
  for (int decade = static_cast<int>(std::floor(std::log10(x_low)));
       decade <= static_cast<int>(std::ceil(std::log10(x_high))); ++decade) {
    const double base = std::pow(10.0, decade);
    for (const auto& [factor, level] : {std::pair{1.0, 0}, std::pair{2.0, 1}, std::pair{5.0, 1}}) {
      const double at = factor * base;
      if (at < x_low || at > x_high) continue;
      // Labelled ticks are major in gnuplot (a minor one shows no label); the 2 and 5 are
      // short ticks' worth of text.
      if (level == 0 || label_between) {
        xtics += fmt::format(
            "{}\"{}\" {}", first_tic ? "" : ", ",
            level == 0 ? "10" + superscript(decade) : fmt::format("{}", static_cast<int>(factor)),
            at);
      } else {
        xtics += fmt::format("{}\"\" {} 1", first_tic ? "" : ", ", at);
      }
      first_tic = false;
    }
  }
  xtics += ")\n";
  FigureCanvas canvas{kWidth + 300, kHeight, 3.0};
  const std::string key = styled_key(style, "right bottom", key_titles, canvas);
  const std::string settings = fmt::format(
      "set logscale x\nset xrange [{}:{}]\nset yrange [{}:{}]\n{}"
      "set xlabel 'payload bytes (log scale)'\nset ylabel 'mean ROC AUC'\n"
      "set key {}\nset grid xtics mxtics ytics\n{}",
      x_low, x_high, y_low, y_high, first_tic ? "" : xtics, key, labels);
  figure.script = figure_script(name, "ROC AUC against descriptor size", figure.caption, settings,
                                plots, style, canvas);
  return figure;
}

}  // namespace radarpr
