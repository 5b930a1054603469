// Opens a report page in headless Chromium from disk (no network): it must render, show its
// inline SVG figures, and not be a blank screenshot. CI installs Debian's chromium.
#include <sys/wait.h>
#include <unistd.h>

#include <array>
#include <cstdio>

#include <gtest/gtest.h>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "evaluation/report/gnuplot_runner.hpp"
#include "evaluation/report/report.hpp"
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

struct ShellResult {
  int exit_code = -1;
  std::string output;
};

ShellResult run_shell(const std::string& command) {
  ShellResult result;
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) return result;
  std::array<char, 4096> buffer{};
  while (std::fgets(buffer.data(), buffer.size(), pipe) != nullptr) result.output += buffer.data();
  const int status = ::pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// Headless flags: no sandbox (CI runs as root), no GPU, no first-run work, a fresh profile.
std::string chromium_command(const fs::path& chromium, const fs::path& profile,
                             const std::string& action, const fs::path& page) {
  return fmt::format(
      "timeout 120 {} --headless=new --no-sandbox --disable-gpu --no-first-run "
      "--disable-extensions --hide-scrollbars --user-data-dir={} --window-size=1200,1600 {} "
      "file://{}",
      chromium.string(), profile.string(), action, page.string());
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

  // The DOM after loading: complete, with every figure as an SVG element.
  const ShellResult dom =
      run_shell(chromium_command(*chromium, root / "profile", "--dump-dom", page) + " 2>/dev/null");
  ASSERT_EQ(dom.exit_code, 0) << "chromium --dump-dom failed";
  const std::string& text = dom.output;
  EXPECT_NE(text.find("</html>"), std::string::npos);
  EXPECT_NE(text.find("Table I: ROC AUC and F1-max per dataset"), std::string::npos);
  std::size_t svgs = 0;
  for (auto at = text.find("<svg"); at != std::string::npos; at = text.find("<svg", at + 1)) {
    ++svgs;
  }
  EXPECT_EQ(svgs, outcome.drawn);

  // A screenshot of the top of the page: not blank, and the first figure (coloured points) drawn.
  const fs::path shot = root / "shot.png";
  const ShellResult screenshot = run_shell(
      chromium_command(*chromium, root / "profile", "--screenshot=" + shot.string(), page) +
      " 2>&1");
  ASSERT_EQ(screenshot.exit_code, 0) << screenshot.output;
  const cv::Mat image = cv::imread(shot.string());
  ASSERT_FALSE(image.empty()) << "no screenshot at " << shot;
  EXPECT_EQ(image.cols, 1200);
  cv::Scalar mean, deviation;
  cv::meanStdDev(image, mean, deviation);
  EXPECT_GT(deviation[0], 10.0) << "a blank page";
  std::size_t coloured = 0;  // saturated pixels: the plotted figure, not text or table rules
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const auto& p = image.at<cv::Vec3b>(y, x);
      const int high = std::max({p[0], p[1], p[2]}), low = std::min({p[0], p[1], p[2]});
      if (high - low > 80) ++coloured;
    }
  }
  EXPECT_GT(coloured, 200u) << "no figure drawn in the screenshot";
  fs::remove_all(root);
}

}  // namespace
}  // namespace radarpr
