// The optional information-density figure: each AUC-against-size point as its mean ROC AUC per
// kilobyte of payload, worked by hand; and the config key that asks for it.
#include "evaluation/report/auc_per_kb_figure.hpp"

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "evaluation/config/config_error.hpp"
#include "evaluation/config/config_reader.hpp"

namespace radarpr {
namespace {

AucSizePoint point(const char* label, std::size_t index, bool multi, double bytes,
                   std::optional<double> auc) {
  AucSizePoint p;
  p.label = label;
  p.descriptor = label;
  p.descriptor_index = index;
  p.multi_session = multi;
  p.payload_bytes = bytes;
  p.mean_auc = auc;
  p.datasets_averaged = auc ? 1 : 0;
  p.datasets_run = 1;
  return p;
}

// a: 200 B, AUC 0.9 single (0.9 / (200 / 1024) = 4.608 per KB) and 0.7 multi (3.584); b: 128 KB,
// AUC 0.8 single (0.00625 per KB); c: no defined AUC, left out.
const std::vector<AucSizePoint> kPoints = {
    point("a", 0, false, 200, 0.9), point("b", 1, false, 131072, 0.8),
    point("c", 2, false, 4800, std::nullopt), point("a", 0, true, 200, 0.7)};

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

TEST(AucPerKbFigure, OneBarPerDefinedPointWithItsDensity) {
  const FigureFiles figure = auc_per_kb_figure("auc_per_kb", kPoints);
  EXPECT_NE(figure.csv.find("0,4.6080000000000005,0.9,200,single,\"a (single)\"\n"),
            std::string::npos)
      << figure.csv;
  EXPECT_NE(figure.csv.find("1,0.00625,0.8,131072,single,\"b (single)\"\n"), std::string::npos)
      << figure.csv;
  EXPECT_NE(figure.csv.find("2,3.5839999999999996,0.7,200,multi,\"a (multi)\"\n"),
            std::string::npos)
      << figure.csv;
  EXPECT_EQ(figure.csv.find("\"c"), std::string::npos) << figure.csv;
  const std::string& gp = figure.script;
  EXPECT_EQ(count(gp, "with boxes"), 3u) << gp;
  EXPECT_NE(gp.find("set logscale y"), std::string::npos) << gp;
  // Whole decades: 10^-3 below 0.00625, 10^1 above 4.608 x 1.6.
  EXPECT_NE(gp.find("set yrange [0.001:10]"), std::string::npos) << gp;
  // Each bar's value above it, three significant digits.
  EXPECT_NE(gp.find("set label 10 '4.61' at 0, 4.6080000000000005"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set label 11 '0.00625' at 1, 0.00625"), std::string::npos) << gp;
  EXPECT_NE(gp.find("set label 12 '3.58' at 2, 3.5839999999999996"), std::string::npos) << gp;
  EXPECT_NE(figure.caption.find("per KB of payload"), std::string::npos);
}

TEST(AucPerKbFigure, OneSessionKindNeedsNoKindInTheNames) {
  const FigureFiles figure =
      auc_per_kb_figure("auc_per_kb", {kPoints[0], kPoints[1]}, FigureStyle::paper);
  EXPECT_NE(figure.csv.find(",\"a\"\n"), std::string::npos) << figure.csv;
  EXPECT_EQ(figure.csv.find("(single)"), std::string::npos) << figure.csv;
}

TEST(AucPerKbFigure, WithoutADefinedAucItSaysSo) {
  const FigureFiles figure = auc_per_kb_figure("auc_per_kb", {kPoints[2]});
  EXPECT_NE(figure.script.find("no defined ROC AUC"), std::string::npos) << figure.script;
}

TEST(AucPerKbFigure, TheReportConfigAsksForIt) {
  EXPECT_FALSE(parse_report_config(ConfigReader(nlohmann::json::object(), "report")).auc_per_kb);
  EXPECT_TRUE(
      parse_report_config(ConfigReader(nlohmann::json{{"auc_per_kb", true}}, "report")).auc_per_kb);
  EXPECT_THROW(parse_report_config(ConfigReader(nlohmann::json{{"auc_per_kb", "yes"}}, "report")),
               ConfigError);
}

}  // namespace
}  // namespace radarpr
