#include <gtest/gtest.h>

#include "evaluation/report/compare.hpp"
#include "evaluation/report/figure_files.hpp"
#include "evaluation/results/csv_file.hpp"
#include "evaluation/results/paper_tables.hpp"
#include "evaluation/results/table.hpp"

namespace radarpr {
namespace {

// A 2-row table: descriptor "a_1" (bold AUC) and "b|2" (an id cell), worked by hand below.
Table hand_table() {
  Table table;
  table.header = {"descriptor", "AUC"};
  table.numeric = {false, true};
  table.rows = {{{"a_1"}, {"0.900", true}}, {{"b|2", false, true}, {"0.5,1"}}};
  return table;
}

TEST(ReportTable, MarkdownBoldsAndEscapesPipes) {
  EXPECT_EQ(to_markdown(hand_table()),
            "| descriptor | AUC |\n|---|---:|\n| a_1 | **0.900** |\n| `b\\|2` | 0.5,1 |\n");
}

TEST(ReportTable, CsvIsPlainAndQuotesCommas) {
  EXPECT_EQ(to_csv(hand_table()), "descriptor,AUC\na_1,0.900\nb|2,\"0.5,1\"\n");
}

TEST(ReportTable, LatexEscapesAndUsesTextbf) {
  const std::string tex = to_latex(hand_table());
  EXPECT_NE(tex.find("\\begin{tabular}{lr}"), std::string::npos) << tex;
  EXPECT_NE(tex.find("a\\_1 & \\textbf{0.900} \\\\"), std::string::npos) << tex;
  EXPECT_NE(tex.find("\\texttt{b|2} & 0.5,1 \\\\"), std::string::npos) << tex;
}

TEST(ReportTable, MarkdownEscapesBackticks) {
  Table table;
  table.header = {"a"};
  table.numeric = {false};
  // Plain text: `\``; a code span holding a backtick: a two-backtick fence, padded by spaces.
  table.rows = {{{"x`y"}}, {{"p`q", false, true}}, {{"plain", false, true}}};
  EXPECT_EQ(to_markdown(table), "| a |\n|---|\n| x\\`y |\n| `` p`q `` |\n| `plain` |\n");
}

TEST(ReportTable, LatexEscapesEverySpecial) {
  Table table;
  table.header = {"h"};
  table.numeric = {false};
  table.rows = {{{"<a> \"b\" & 5% $1 #2 _ {c} ~ ^ \\"}}};
  const std::string tex = to_latex(table);
  EXPECT_NE(tex.find("\\textless{}a\\textgreater{} \\textquotedbl{}b\\textquotedbl{} \\& 5\\% "
                     "\\$1 \\#2 \\_ \\{c\\} \\textasciitilde{} \\textasciicircum{} "
                     "\\textbackslash{} \\\\"),
            std::string::npos)
      << tex;
}

TEST(ReportTable, HtmlEscapesText) {
  EXPECT_EQ(html_escape("<a href=\"x\">&'</a>"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&#39;&lt;/a&gt;");
  const std::string html = to_html(hand_table());
  EXPECT_NE(html.find("<td class=\"num\"><strong>0.900</strong></td>"), std::string::npos);
  EXPECT_NE(html.find("<td><code>b|2</code></td>"), std::string::npos);
}

TEST(ReportTable, BestPerColumnBoldsTiesAsShown) {
  // 0.8124 and 0.8121 both print 0.812: equally best; 0.700 not; n/a never.
  Table table;
  table.header = {"d", "AUC"};
  table.numeric = {false, true};
  for (const char* v : {"0.812", "0.700", "n/a", "0.812"}) table.rows.push_back({{"x"}, {v}});
  bold_best(table, {1});
  EXPECT_TRUE(table.rows[0][1].bold);
  EXPECT_FALSE(table.rows[1][1].bold);
  EXPECT_FALSE(table.rows[2][1].bold);
  EXPECT_TRUE(table.rows[3][1].bold);
  EXPECT_EQ(metric_text(0.81249), "0.812");
  EXPECT_EQ(metric_text(std::nullopt), "n/a");
}

TEST(ReportCsv, SplitsQuotedFields) {
  EXPECT_EQ(split_csv_line("1,\"referee_r:kernel=box,z_q=3\",,\"a\"\"b\""),
            (std::vector<std::string>{"1", "referee_r:kernel=box,z_q=3", "", "a\"b"}));
}

TEST(ReportFigures, StemsAreFileSafe) {
  EXPECT_EQ(figure_stem("town 2/a:b,c=1"), "town_2_a_b_c=1");
}

TEST(ReportCompare, LabelsAreDisambiguatedByFolderThenNumber) {
  std::vector<RunResults> runs(4);
  runs[0].experiment = "qs";
  runs[0].folder = "/r/a/";
  runs[1].experiment = "qs";
  runs[1].folder = "/r/b";
  runs[2].experiment = "other";
  runs[2].folder = "/r/a";
  runs[3].experiment = "qs";
  runs[3].folder = "/s/b";
  EXPECT_EQ(comparison_labels(runs),
            (std::vector<std::string>{"qs (a)", "qs (b) #2", "other", "qs (b) #4"}));
}

// Column groups: in LaTeX a heading per dataset over its metrics (\multicolumn, \cmidrule),
// the metric names under it; the other formats keep the one-line header.
TEST(ReportTable, LatexGroupsColumnsUnderTwoLevelHeaders) {
  Table table;
  table.header = {"descriptor", "a_b AUC", "a_b F1-max", "c AUC", "c F1-max"};
  table.numeric = {false, true, true, true, true};
  table.rows = {{{"x"}, {"0.9", true}, {"0.8"}, {"0.7"}, {"0.6", true}}};
  table.groups = {
      {"", 1, {"descriptor"}}, {"a_b", 2, {"AUC", "F1-max"}}, {"c", 2, {"AUC", "F1-max"}}};
  EXPECT_EQ(to_latex(table),
            "% needs \\usepackage{booktabs} (and \\usepackage[T1]{fontenc} for "
            "\\textquotedbl)\n\\begin{tabular}{lrrrr}\n\\toprule\n"
            " & \\multicolumn{2}{c}{a\\_b} & \\multicolumn{2}{c}{c} \\\\\n"
            "\\cmidrule(lr){2-3}\\cmidrule(lr){4-5}\n"
            "descriptor & AUC & F1-max & AUC & F1-max \\\\\n\\midrule\n"
            "x & \\textbf{0.9} & 0.8 & 0.7 & \\textbf{0.6} \\\\\n\\bottomrule\n\\end{tabular}\n");
  EXPECT_NE(to_markdown(table).find("| descriptor | a_b AUC |"), std::string::npos)
      << to_markdown(table);
  // HTML the same way (a page of six datasets stays narrow): the ungrouped column spans both
  // header rows.
  EXPECT_NE(to_html(table).find(
                "<thead><tr><th rowspan=\"2\">descriptor</th><th colspan=\"2\">a_b</th><th "
                "colspan=\"2\">c</th></tr>\n<tr><th class=\"num\">AUC</th><th "
                "class=\"num\">F1-max</th><th class=\"num\">AUC</th><th "
                "class=\"num\">F1-max</th></tr></thead>"),
            std::string::npos)
      << to_html(table);
  // Groups that do not cover every column are ignored: the one-line header.
  table.groups.pop_back();
  EXPECT_NE(to_latex(table).find("descriptor & a\\_b AUC & a\\_b F1-max"), std::string::npos);
  EXPECT_NE(to_html(table).find("<th class=\"num\">a_b AUC</th>"), std::string::npos);
}

}  // namespace
}  // namespace radarpr
