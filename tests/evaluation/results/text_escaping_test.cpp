#include <gtest/gtest.h>

#include "evaluation/safe_name.hpp"
#include "evaluation/text_escaping.hpp"

namespace radarpr {
namespace {

TEST(TextEscaping, GnuplotStringCannotEndItsCommand) {
  EXPECT_EQ(gnuplot_string("plain"), "'plain'");
  EXPECT_EQ(gnuplot_string("it's"), "'it''s'");
  // A newline would end the command and start the next one: a space instead.
  EXPECT_EQ(gnuplot_string("a\nsystem('x')"), "'a system(''x'')'");
  EXPECT_EQ(gnuplot_string("a\r\n\t\x1b[0m\x7f"), "'a    [0m '");
  // Backquotes, macros and backslashes are plain inside single quotes.
  EXPECT_EQ(gnuplot_string("`id` @m \\"), "'`id` @m \\'");
  EXPECT_EQ(gnuplot_string(std::string("a\0b", 3)), "'a b'");
}

TEST(TextEscaping, HtmlEscapesMarkupAndQuotes) {
  EXPECT_EQ(html_escape("<a href=\"x\">&'</a>"),
            "&lt;a href=&quot;x&quot;&gt;&amp;&#39;&lt;/a&gt;");
  EXPECT_EQ(html_escape(std::string("a\0b\nc", 5)), "a b\nc");
}

TEST(TextEscaping, LatexEscapesSpecialsAndLineBreaks) {
  EXPECT_EQ(latex_escape("\\input{x} 5% $_#&~^<>\"\n\nend"),
            "\\textbackslash{}input\\{x\\} 5\\% \\$\\_\\#\\&\\textasciitilde{}"
            "\\textasciicircum{}\\textless{}\\textgreater{}\\textquotedbl{}  end");
}

TEST(TextEscaping, MarkdownCellsStayOneCell) {
  EXPECT_EQ(markdown_cell("a|b\n| c |\\"), "a\\|b \\| c \\|\\\\");
  EXPECT_EQ(markdown_cell("<b>*x*[y](z)`"), "\\<b>\\*x\\*\\[y\\](z)\\`");
  EXPECT_EQ(markdown_cell("referee_r:kernel=box,z_q=3"), "referee_r:kernel=box,z_q=3");
  EXPECT_EQ(markdown_code_cell("a|b"), "`a\\|b`");
  EXPECT_EQ(markdown_code_cell("p`q"), "`` p`q ``");
}

TEST(TextEscaping, CsvQuotesAndKeepsFormulasAsText) {
  EXPECT_EQ(csv_field("plain"), "plain");
  EXPECT_EQ(csv_field("a,b"), "\"a,b\"");
  EXPECT_EQ(csv_field("say \"x\""), "\"say \"\"x\"\"\"");
  EXPECT_EQ(csv_field("a\rb"), "\"a\rb\"");
  EXPECT_EQ(csv_field("=1+2"), "'=1+2");
  EXPECT_EQ(csv_field("@SUM(A1)"), "'@SUM(A1)");
  EXPECT_EQ(csv_field("-0.5"), "-0.5");  // a number stays a number
  EXPECT_EQ(csv_field("x", CsvQuoting::always), "\"x\"");
}

TEST(TextEscaping, PrintableShowsControlsAndBadBytes) {
  EXPECT_EQ(printable("caf\xc3\xa9"), "caf\xc3\xa9");
  EXPECT_EQ(printable("a\nb\x1b[1m"), "a\\nb\\x1b[1m");
  EXPECT_EQ(printable("bad\xff\xc3"), "bad\\xff\\xc3");
  EXPECT_TRUE(is_utf8("caf\xc3\xa9"));
  EXPECT_FALSE(is_utf8("caf\xe9"));
  EXPECT_FALSE(is_utf8("\xed\xa0\x80"));  // a surrogate
  EXPECT_FALSE(is_utf8("\xc0\xaf"));      // an overlong '/'
}

TEST(SafeName, OnlyOneEntryInsideTheFolder) {
  for (const char* good : {"town", "city_sessions", "referee_r__kernel=box_z_q=3", "a..b", "_x"}) {
    EXPECT_FALSE(unsafe_name_reason(good)) << good;
  }
  for (const char* bad : {"", ".", "..", "../x", "/abs", "a/b", "a\\b", ".hidden", "-rf", "a b",
                          "a\nb", "caf\xc3\xa9", "x'y", "<x", "a|b"}) {
    EXPECT_TRUE(unsafe_name_reason(bad)) << bad;
  }
  EXPECT_TRUE(unsafe_name_reason(std::string("a\0b", 3)));
  EXPECT_FALSE(unsafe_name_reason(std::string(kMaxNameLength, 'a')));
  EXPECT_EQ(*unsafe_name_reason(std::string(kMaxNameLength + 1, 'a')),
            "is 101 bytes long (at most 100)");
  EXPECT_EQ(*unsafe_name_reason("../x"), "starts with '.'");
  EXPECT_EQ(*unsafe_name_reason("a/b"), "holds '/'");
}

}  // namespace
}  // namespace radarpr
