// Opens a report page in headless Chromium from disk (no network): it must render, show its
// inline SVG figures, and not be a blank screenshot. CI installs Debian's chromium.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstdlib>

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "evaluation/report/figure_files.hpp"
#include "evaluation/report/gnuplot_runner.hpp"
#include "evaluation/report/report.hpp"
#include "tests/cli/cli_runner.hpp"
#include "tests/evaluation/report/small_results.hpp"

namespace radarpr {
namespace {

namespace fs = std::filesystem;

std::optional<fs::path> find_chromium() {
  for (const char* name : {"chromium", "chromium-browser", "google-chrome"}) {
    for (const char* folder : {"/usr/bin", "/usr/local/bin", "/snap/bin"}) {
      const fs::path candidate = fs::path(folder) / name;
      if (::access(candidate.c_str(), X_OK) == 0) return candidate;
    }
  }
  return std::nullopt;
}

// A path for the shell: single-quoted, a quote inside closed, escaped and reopened.
std::string shell_quote(const std::string& text) {
  std::string quoted = "'";
  for (char c : text) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// Headless flags: no sandbox (CI runs as root), no GPU, no first-run work, a fresh profile. A
// hung browser is killed (-k) after the 120 s timeout asked it to stop.
std::string chromium_command(const fs::path& chromium, const fs::path& profile,
                             const std::string& action, const fs::path& page) {
  return fmt::format(
      "timeout -k 10 120 {} --headless=new --no-sandbox --disable-gpu --no-first-run "
      "--disable-extensions --hide-scrollbars --user-data-dir={} --window-size=1200,3000 {} {}",
      shell_quote(chromium.string()), shell_quote(profile.string()), action,
      shell_quote("file://" + page.string()));
}

// Pixels within `tolerance` per channel of the colour '#rrggbb' (the screenshot is BGR).
std::size_t pixels_near(const cv::Mat& image, const std::string& colour, int tolerance) {
  const int r = std::stoi(colour.substr(1, 2), nullptr, 16);
  const int g = std::stoi(colour.substr(3, 2), nullptr, 16);
  const int b = std::stoi(colour.substr(5, 2), nullptr, 16);
  std::size_t count = 0;
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const auto& p = image.at<cv::Vec3b>(y, x);
      if (std::abs(p[2] - r) <= tolerance && std::abs(p[1] - g) <= tolerance &&
          std::abs(p[0] - b) <= tolerance) {
        ++count;
      }
    }
  }
  return count;
}

// The figures are drawn when the two descriptors' own plot colours (palette 0 and 1: the
// AUC-size points and the PR curves at the top of the page) show. Nothing else on the page has
// them: links are #0000ee, the "not drawn" boxes #cc0000 / #990000, text and rules grey.
bool figures_drawn(const cv::Mat& image) {
  return pixels_near(image, figure_palette()[0], 40) > 150 &&
         pixels_near(image, figure_palette()[1], 40) > 150;
}

// Loads `page` in headless chromium and returns its screenshot (empty on failure, with why).
cv::Mat screenshot(const fs::path& chromium, const fs::path& root, const fs::path& page,
                   std::string& output) {
  const fs::path shot = root / (page.parent_path().filename().string() + "_shot.png");
  const testing::CommandResult result = testing::run_command_line(
      chromium_command(chromium, root / "profile", "--screenshot=" + shell_quote(shot.string()),
                       page) +
      " 2>&1");
  output = result.output;
  if (result.exit_code != 0) return {};
  return cv::imread(shot.string());
}

TEST(ReportPage, RendersInHeadlessChromiumWithItsFigures) {
  const auto chromium = find_chromium();
  if (!chromium) GTEST_SKIP() << "chromium absent: /usr/bin/chromium (apt install chromium)";
  if (!find_gnuplot()) GTEST_SKIP() << "gnuplot absent: the page would have no figure to show";
  const fs::path root = testing::scratch_folder("chromium");
  testing::write_small_results(root / "run");
  const ReportOutcome outcome = write_report(root / "run", {});
  ASSERT_GT(outcome.drawn, 0u);
  const fs::path page = fs::absolute(root / "run" / "index.html");

  // The DOM after loading: complete, with every figure as an image of its SVG file.
  const testing::CommandResult dom = testing::run_command_line(
      chromium_command(*chromium, root / "profile", "--dump-dom", page) + " 2>/dev/null");
  ASSERT_EQ(dom.exit_code, 0) << "chromium --dump-dom failed";
  const std::string& text = dom.output;
  EXPECT_NE(text.find("</html>"), std::string::npos);
  // Table I as rendered: a dataset over its AUC, F1-max and R@1 columns, Recall@1 among them.
  const auto table1 = text.find("Table I: ROC AUC, F1-max and Recall@1 per dataset");
  ASSERT_NE(table1, std::string::npos);
  const std::string table1_html = text.substr(table1, text.find("</table>", table1) - table1);
  EXPECT_NE(table1_html.find("<th colspan=\"3\">town</th>"), std::string::npos) << table1_html;
  EXPECT_NE(table1_html.find("<th class=\"num\">R@1</th>"), std::string::npos) << table1_html;
  std::size_t images = 0;
  const std::string link = "<img src=\"figures/";
  for (auto at = text.find(link); at != std::string::npos; at = text.find(link, at + 1)) {
    ++images;
  }
  EXPECT_EQ(images, outcome.drawn);

  // A screenshot of the top of the page: not blank, and the figures' own colours drawn.
  std::string output;
  const cv::Mat image = screenshot(*chromium, root, page, output);
  ASSERT_FALSE(image.empty()) << "no screenshot: " << output;
  EXPECT_EQ(image.cols, 1200);
  cv::Scalar mean, deviation;
  cv::meanStdDev(image, mean, deviation);
  EXPECT_GT(deviation[0], 10.0) << "a blank page";
  EXPECT_TRUE(figures_drawn(image))
      << "figure colours: " << pixels_near(image, figure_palette()[0], 40) << " and "
      << pixels_near(image, figure_palette()[1], 40) << " pixels";

  // The same page without gnuplot (red "not drawn" boxes, links, tables) must fail the check.
  fs::copy(root / "run", root / "undrawn", fs::copy_options::recursive);
  {
    const testing::ScopedEnvironment no_gnuplot("RADARPR_GNUPLOT", "/nonexistent");
    ASSERT_EQ(write_report(root / "undrawn", {}).drawn, 0u);
  }
  const cv::Mat undrawn =
      screenshot(*chromium, root, fs::absolute(root / "undrawn" / "index.html"), output);
  ASSERT_FALSE(undrawn.empty()) << "no screenshot: " << output;
  EXPECT_FALSE(figures_drawn(undrawn))
      << "figure colours without figures: " << pixels_near(undrawn, figure_palette()[0], 40)
      << " and " << pixels_near(undrawn, figure_palette()[1], 40) << " pixels";
  fs::remove_all(root);
}

// Every text the page shows from a results folder (experiment, description, labels, machine,
// protocol, value sources) holding a script or an attribute breaker: chromium runs none of them
// and shows each as text.
TEST(ReportPage, InjectedTextsAreShownNotRun) {
  const auto chromium = find_chromium();
  if (!chromium) GTEST_SKIP() << "chromium absent: /usr/bin/chromium (apt install chromium)";
  const fs::path root = testing::scratch_folder("chromium_injection");
  testing::write_small_results(root / "run");
  const std::string script =
      "<script>document.documentElement.setAttribute('data-pwned','script')</script>";
  const std::string attribute =
      "x\"'><img src=\"nonexistent.png\" "
      "onerror=\"document.documentElement.setAttribute('data-pwned','img')\">";
  auto summary = nlohmann::json::parse(testing::read_text(root / "run" / "summary.json"));
  summary["experiment"] = script;
  summary["description"] = attribute + script;
  summary["machine"][attribute] = script;
  summary["protocol"]["labels"] = attribute;
  for (auto& row : summary["rows"]) {
    row["label"] = script + attribute;
    row["values_from"]["query"] = attribute;
  }
  std::ofstream(root / "run" / "summary.json") << summary.dump(2);
  write_report(root / "run", {});
  const testing::CommandResult dom =
      testing::run_command_line(chromium_command(*chromium, root / "profile", "--dump-dom",
                                                 fs::absolute(root / "run" / "index.html")) +
                                " 2>/dev/null");
  ASSERT_EQ(dom.exit_code, 0) << "chromium --dump-dom failed";
  const std::string& text = dom.output;
  EXPECT_NE(text.find("</html>"), std::string::npos);
  // A script that ran would have set the attribute on <html>: data-pwned="..." (the texts
  // themselves hold the name only as 'data-pwned').
  EXPECT_EQ(text.find("data-pwned=\""), std::string::npos) << "a script ran";
  // The page's own images are its figures; an injected one would carry its own source.
  const std::string image = "<img src=\"";
  for (auto at = text.find(image); at != std::string::npos; at = text.find(image, at + 1)) {
    EXPECT_EQ(text.substr(at + image.size(), 8), "figures/") << "an element was injected";
  }
  EXPECT_EQ(text.find("<script"), std::string::npos) << "an element was injected";
  // Shown as text: the DOM serialises a text node's < > & as entities.
  const std::string shown =
      "&lt;script&gt;document.documentElement.setAttribute('data-pwned','script')&lt;/script&gt;";
  std::size_t count = 0;
  for (auto at = text.find(shown); at != std::string::npos; at = text.find(shown, at + 1)) ++count;
  EXPECT_GE(count, 4u) << "the title, heading, overview and tables show the text";
  EXPECT_NE(text.find("onerror=\"document"), std::string::npos);
  fs::remove_all(root);
}

}  // namespace
}  // namespace radarpr
