// The two figure styles: the scripts' sizes, fonts and titles, the PDF beside the SVG and PNG
// (its page one IEEE column wide in the paper style), and where the style is chosen (--style,
// the config's "report" object, recorded in summary.json for a later `report`).
#include <gtest/gtest.h>

#include <regex>

#include "evaluation/config/config_error.hpp"
#include "evaluation/report/figure_files.hpp"
#include "evaluation/report/figure_style.hpp"
#include "evaluation/report/gnuplot_runner.hpp"
#include "evaluation/report/report.hpp"
#include "evaluation/results/results_error.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/evaluation/report/figure_images.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

bool contains(const std::string& text, const std::string& what) {
  return text.find(what) != std::string::npos;
}

const std::vector<SweepPoint> kCurve = {
    {0.1, 1.0, 0.2, 0.0, 0.33}, {0.5, 0.8, 0.6, 0.2, 0.69}, {0.9, 0.5, 1.0, 0.7, 0.67}};

TEST(PaperStyle, ScreenScriptsAreTitledAndLargePaperOnesOneColumnWideAndUntitled) {
  const std::vector<CurveSeries> series = {{"a", &kCurve, 0.5, 0.69, 0.8, 0, 1}};
  const std::string screen = pr_figure("pr_x", "x: precision-recall", series).script;
  const std::string paper =
      pr_figure("pr_x", "x: precision-recall", series, KeyPlace::right, FigureStyle::paper).script;
  EXPECT_TRUE(contains(screen, "set title 'x: precision-recall'")) << screen;
  EXPECT_TRUE(contains(screen, "set terminal svg size 1200,640")) << screen;
  EXPECT_FALSE(contains(paper, "set title")) << paper;
  // One IEEE column (3.5 in) at 8 pt in every format: SVG at 100 px/in, PNG at 300 dpi.
  EXPECT_TRUE(contains(paper, "set terminal pdfcairo size 3.5in,2.60in font 'sans,8' fontscale 1"))
      << paper;
  EXPECT_TRUE(contains(paper, "set terminal pngcairo size 1050,780 font 'sans,8'")) << paper;
  // The SVG's font sizes are pixels: all scaled by 100/72, the key's 7 pt too.
  EXPECT_TRUE(contains(paper, "set terminal svg size 350,260 font 'sans,8' fontscale 1.389"))
      << paper;
  // A short key fits inside, in the corner a PR curve leaves empty.
  EXPECT_TRUE(contains(paper, "set key inside left bottom")) << paper;
  for (const std::string& script : {screen, paper}) {
    EXPECT_TRUE(contains(script, "set output 'pr_x.pdf'")) << script;
    // A gnuplot without cairo still draws the SVG and PNG.
    EXPECT_TRUE(contains(script, "if (strstrt(GPVAL_TERMINALS, 'pdfcairo') > 0) {")) << script;
  }
}

TEST(PaperStyle, AKeyTooLongForThePlotGoesBelowItOnATallerCanvas) {
  const std::vector<CurveSeries> series = {
      {"a descriptor with a very long name and parameters", &kCurve, 0.5, 0.69, 0.8, 0, 1}};
  const std::string paper =
      roc_figure("roc_x", "x", series, KeyPlace::right, FigureStyle::paper).script;
  EXPECT_FALSE(contains(paper, "set key inside")) << paper;
  EXPECT_TRUE(contains(paper, "set bmargin at screen")) << paper;
  EXPECT_FALSE(contains(paper, "size 3.5in,2.60in")) << paper;
}

// The paper key below the plot starts at the left edge (centred by gnuplot's own, too wide,
// width estimate its first column was cut off), takes as many columns as the 3.5 in column holds
// for its longest title, makes a title too long for a row smaller, and the bottom margin keeps
// the axis labels (0.51 in as drawn) clear of it.
TEST(PaperStyle, TheKeyBelowThePlotFitsTheColumnWidthAndClearsTheAxisLabel) {
  const auto key_of = [](const std::vector<std::string>& titles, FigureCanvas& canvas) {
    return key_below(titles, FigureStyle::paper, canvas);
  };
  FigureCanvas canvas;
  const std::string long_titles =
      key_of({"referee (F1-max 0.688)", "referee_r:kernel=box,z_q=3 (F1-max 0.798)",
              "referee_r (F1-max 0.770)", "referee_a (F1-max 0.688)", "F1-max"},
             canvas);
  EXPECT_TRUE(contains(long_titles, "at screen 0.04, screen ")) << long_titles;
  EXPECT_TRUE(contains(long_titles, " left top vertical maxcols 1 maxrows 5 ")) << long_titles;
  EXPECT_TRUE(contains(long_titles, "font ',7'")) << long_titles;
  // The canvas grows by the key's rows; the margin above the key leaves 0.58 in for the labels.
  EXPECT_NEAR(canvas.paper_height_in, 2.6 + 5.3 * 11.0 / 72.0, 1e-9);
  std::smatch match;
  ASSERT_TRUE(std::regex_search(
      long_titles, match,
      std::regex(R"(screen ([0-9.]+) left top[^\n]*\nset bmargin at screen ([0-9.]+))")));
  EXPECT_NEAR((std::stod(match[2]) - std::stod(match[1])) * canvas.paper_height_in, 0.58, 0.01);

  FigureCanvas short_canvas;
  const std::string short_titles =
      key_of({"a", "b", "c", "d", "e", "f", "g", "h", "i", "j", "k", "l"}, short_canvas);
  EXPECT_TRUE(contains(short_titles, "maxcols 3 maxrows 4 ")) << short_titles;
  EXPECT_NEAR(short_canvas.paper_height_in, 2.6 + 4.3 * 11.0 / 72.0, 1e-9);
  FigureCanvas medium_canvas;
  EXPECT_TRUE(contains(key_of({"radar_scan_context", "raplace", "open_radvlad"}, medium_canvas),
                       "maxcols 1 maxrows 3 "));

  FigureCanvas very_long_canvas;
  const std::string very_long = key_of({std::string(50, 'x'), "y"}, very_long_canvas);
  EXPECT_TRUE(contains(very_long, "maxcols 1 maxrows 2 ")) << very_long;
  EXPECT_TRUE(contains(very_long, "font ',5.5'")) << very_long;
  EXPECT_TRUE(contains(key_of({std::string(200, 'x')}, very_long_canvas), "font ',5'"));
}

TEST(PaperStyle, EveryFigureScriptSharesOneHeader) {
  const std::string auc = auc_size_figure("auc_vs_size", {}, FigureStyle::paper).script;
  EXPECT_EQ(auc.rfind("# radarpr figure (paper style): ROC AUC against descriptor size.\n", 0), 0u)
      << auc;
  EXPECT_THROW(figure_script("../x", "w", "t", "", "plot x", FigureStyle::screen, {}),
               std::logic_error);
}

TEST(PaperStyle, TheConfigsReportObjectIsCheckedNamingTheKey) {
  nlohmann::json config = testing::small_report_experiment();
  config["report"] = {{"style", "paper"}, {"recall_curve_n", 40}};
  const ExperimentConfig parsed = parse_experiment_config(config);
  EXPECT_EQ(parsed.report.style, FigureStyle::paper);
  EXPECT_EQ(parsed.report.recall_curve_n, 40);
  config["report"] = {{"style", "poster"}};
  try {
    parse_experiment_config(config);
    ADD_FAILURE() << "style poster accepted";
  } catch (const ConfigError& error) {
    EXPECT_EQ(error.key_path(), "report.style");
  }
  config["report"] = {{"recall_curve_n", 0}};
  EXPECT_THROW(parse_experiment_config(config), ConfigError);
}

using testing::has_pdfcairo;
using testing::pdf_page;

// --style paper on `report`: every figure drawn as a PDF one IEEE column (252 pt) wide; without
// --style the run's config decides, and a bad recorded style is an error naming summary.json.
TEST(PaperStyle, ReportDrawsPdfsInTheChosenStyle) {
  if (!has_pdfcairo()) GTEST_SKIP() << "gnuplot with the pdfcairo terminal is not installed";
  const fs::path root = testing::scratch_folder("paper_style");
  testing::write_small_results(root / "run");
  const fs::path paper = testing::copy_of_run(root, "paper");
  const auto result = testing::run_cli("report " + paper.string() + " --style paper");
  ASSERT_EQ(result.exit_code, 0) << result.output;
  std::size_t pdfs = 0;
  for (const auto& entry : fs::directory_iterator(paper / "figures")) {
    if (entry.path().extension() != ".gp") continue;
    const fs::path pdf = fs::path(entry.path()).replace_extension(".pdf");
    const auto page = pdf_page(pdf);
    ASSERT_TRUE(page) << pdf << " is missing or not a PDF";
    EXPECT_NEAR(page->first, 252.0, 0.5) << pdf;
    ++pdfs;
  }
  EXPECT_GT(pdfs, 4u);
  // The same PDF twice: cairo's creation date is blanked.
  const std::string first = testing::read_text(paper / "figures" / "pr_town.pdf");
  ASSERT_EQ(testing::run_cli("report " + paper.string() + " --style paper").exit_code, 0);
  EXPECT_EQ(testing::read_text(paper / "figures" / "pr_town.pdf"), first);
  EXPECT_FALSE(contains(first, "/CreationDate"));

  // The screen style by default: 9 in wide (900 px at 100 px per inch, 648 pt).
  const fs::path screen = testing::copy_of_run(root, "screen");
  ASSERT_EQ(testing::run_cli("report " + screen.string()).exit_code, 0);
  const auto page = pdf_page(screen / "figures" / "pr_town.pdf");
  ASSERT_TRUE(page);
  EXPECT_GT(page->first, 600.0);

  // Each figure's title once on the page: in the screen style's image, else in the caption.
  const std::string caption = "<figcaption>town: precision-recall <br>";
  EXPECT_FALSE(contains(testing::read_text(screen / "index.html"), caption));
  EXPECT_TRUE(contains(testing::read_text(paper / "index.html"), caption));

  // The style a run's config recorded, unless --style says otherwise.
  const fs::path recorded = testing::copy_of_run(root, "recorded");
  nlohmann::json summary = nlohmann::json::parse(testing::read_text(recorded / "summary.json"));
  summary["config"]["report"] = {{"style", "paper"}};
  std::ofstream(recorded / "summary.json") << summary.dump(2);
  write_report(recorded, ReportOptions{});
  EXPECT_FALSE(contains(testing::read_text(recorded / "figures" / "pr_town.gp"), "set title"));
  ReportOptions screen_options;
  screen_options.style = FigureStyle::screen;
  write_report(recorded, screen_options);
  EXPECT_TRUE(contains(testing::read_text(recorded / "figures" / "pr_town.gp"), "set title"));
  summary["config"]["report"] = {{"style", "poster"}};
  std::ofstream(recorded / "summary.json") << summary.dump(2);
  try {
    write_report(recorded, ReportOptions{});
    ADD_FAILURE() << "a recorded style poster was accepted";
  } catch (const ResultsError& error) {
    EXPECT_TRUE(contains(error.what(), (recorded / "summary.json").string())) << error.what();
    EXPECT_TRUE(contains(error.what(), "report.style")) << error.what();
  }
  fs::remove_all(root);
}

}  // namespace
}  // namespace radarpr
