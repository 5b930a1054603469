// The fast paths use x86 instructions (SSE, AVX2, AVX-512) chosen at run time, but radarpr must
// still build on other processors (an arm64 robot computer runs Debian too), where those paths
// fall back to their portable code. This test reads every source file and names each x86-only
// construct (the intrinsics headers, __builtin_cpu_supports, target("...") attributes, _mm*
// intrinsics and __m128/__m256/__m512 types) that is not inside a preprocessor block compiled on
// x86 only: `#if defined(__x86_64__) ...`, or `#if` of a macro the same file defines inside such a
// block (e.g. RADARPR_VLAD_X86).
#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "source_tree.hpp"

namespace radarpr::test {
namespace {

// One open #if/#ifdef/#ifndef: whether the branch being read is compiled on x86 only.
struct OpenConditional {
  bool x86_condition = false;  // the #if tested an x86 macro
  bool in_else = false;        // past its #else or #elif
};

bool names_x86_macro(const std::string& condition, const std::set<std::string>& x86_macros) {
  static const std::regex builtin(R"(__x86_64__|__i386__|__amd64__|_M_X64|__SSE\w*__|__AVX\w*__)");
  if (std::regex_search(condition, builtin)) return true;
  static const std::regex identifier(R"([A-Za-z_]\w*)");
  for (auto it = std::sregex_iterator(condition.begin(), condition.end(), identifier);
       it != std::sregex_iterator(); ++it) {
    if (x86_macros.count(it->str()) != 0) return true;
  }
  return false;
}

// "file:line: <text>" for each x86-only construct of `text` outside an x86-only block; `name` is
// how the file is named in the report.
std::vector<std::string> unguarded_x86(const std::string& text, const std::string& name) {
  static const std::regex directive(R"(^\s*#\s*(if|ifdef|ifndef|elif|else|endif|define)\b\s*(.*))");
  static const std::regex x86_only(
      R"(<(imm|x86|[ex]?mm|[pstn]mm|wmm|avx\w*)intrin\.h>|__builtin_cpu_supports|__builtin_cpu_init|)"
      R"(__attribute__\s*\(\(\s*target\s*\(|\b_mm\d*_\w+\s*\(|\b__m(128|256|512)\w*\b)");
  std::vector<std::string> found;
  std::vector<OpenConditional> open;
  std::set<std::string> x86_macros;
  const auto guarded = [&open] {
    for (const auto& conditional : open) {
      if (conditional.x86_condition && !conditional.in_else) return true;
    }
    return false;
  };
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    std::smatch match;
    if (std::regex_search(line, match, directive)) {
      const std::string keyword = match[1];
      const std::string rest = match[2];
      if (keyword == "if" || keyword == "ifdef") {
        open.push_back({names_x86_macro(rest, x86_macros), false});
      } else if (keyword == "ifndef") {
        open.push_back({false, false});
      } else if ((keyword == "elif" || keyword == "else") && !open.empty()) {
        open.back().in_else = true;
      } else if (keyword == "endif" && !open.empty()) {
        open.pop_back();
      } else if (keyword == "define" && guarded()) {
        std::smatch macro;
        static const std::regex macro_name(R"(^([A-Za-z_]\w*))");
        if (std::regex_search(rest, macro, macro_name)) x86_macros.insert(macro[1]);
      }
      if (keyword != "define") continue;
    }
    const auto comment = line.find("//");
    const std::string code = comment == std::string::npos ? line : line.substr(0, comment);
    if (std::regex_search(code, x86_only) && !guarded()) {
      found.push_back(name + ":" + std::to_string(number) + ": " + line);
    }
  }
  return found;
}

TEST(X86Guards, EveryX86OnlyConstructIsCompiledOnX86Only) {
  std::size_t files = 0;
  std::vector<std::string> violations;
  for (const std::string folder :
       {"datasets", "descriptors", "evaluation", "benchmarks", "cli", "python", "examples"}) {
    for (const auto& file : files_under(source_root(), folder, {".cpp", ".hpp", ".h", ".in"})) {
      ++files;
      const std::string name = file.lexically_relative(source_root()).string();
      for (auto& violation : unguarded_x86(read_text(file), name)) {
        violations.push_back(violation);
      }
    }
  }
  EXPECT_GT(files, 100u) << "the source tree was not found at " << source_root();
  std::string report;
  for (const auto& violation : violations) report += "\n  " + violation;
  EXPECT_TRUE(violations.empty())
      << "x86-only code outside an #if defined(__x86_64__) block (other processors could not "
         "build it):"
      << report;
}

// The check itself: constructs outside a guard, in an #else branch or behind a macro defined
// elsewhere are reported; those inside a guard, or behind a macro defined inside one, are not.
TEST(X86Guards, ReportsUnguardedConstructsOnly) {
  const std::string text =
      "#include <immintrin.h>\n"                                      // 1: reported
      "#if defined(__x86_64__) && defined(__GNUC__)\n"                // 2
      "#include <immintrin.h>\n"                                      // 3
      "#define FAST_X86 1\n"                                          // 4
      "#else\n"                                                       // 5
      "static const bool avx2 = __builtin_cpu_supports(\"avx2\");\n"  // 6: reported
      "#endif\n"                                                      // 7
      "#if FAST_X86\n"                                                // 8
      "__attribute__((target(\"avx2\"))) void f() { __m256 x; }\n"    // 9
      "#endif\n"                                                      // 10
      "#if OTHER_MACRO\n"                                             // 11
      "void g() { _mm256_setzero_ps(); }\n"                           // 12: reported
      "#endif\n"                                                      // 13
      "// __builtin_cpu_supports in a comment is fine\n";             // 14
  const auto found = unguarded_x86(text, "probe.cpp");
  ASSERT_EQ(found.size(), 3u);
  EXPECT_EQ(found[0].rfind("probe.cpp:1: ", 0), 0u) << found[0];
  EXPECT_EQ(found[1].rfind("probe.cpp:6: ", 0), 0u) << found[1];
  EXPECT_EQ(found[2].rfind("probe.cpp:12: ", 0), 0u) << found[2];
}

}  // namespace
}  // namespace radarpr::test
