// Numbers on the command line: the whole token, finite, within the option's range.
#include "cli/number_options.hpp"

#include <gtest/gtest.h>

namespace radarpr::cli {
namespace {

TEST(NumberOptions, ANumberIsTheWholeToken) {
  EXPECT_EQ(parse_number("0.2"), 0.2);
  EXPECT_EQ(parse_number("-3"), -3.0);
  EXPECT_EQ(parse_number("1e-3"), 1e-3);
  EXPECT_EQ(parse_number("0.0595238"), 0.0595238);  // exactly the double strtod gives
  for (const char* bad : {"", " 1", "1 ", "0.2abc", "1e", "+1", "0x10", "1,5", "--1", "."}) {
    EXPECT_FALSE(parse_number(bad)) << "'" << bad << "'";
  }
}

TEST(NumberOptions, ANumberIsFinite) {
  for (const char* bad : {"inf", "-inf", "infinity", "nan", "NaN", "1e999", "-1e999"}) {
    EXPECT_FALSE(parse_number(bad)) << bad;
    EXPECT_NE(number_problem(bad, {}).find("is not a finite number"), std::string::npos) << bad;
  }
}

TEST(NumberOptions, AWholeNumberHasOnlyDigits) {
  EXPECT_EQ(parse_whole_number("16"), 16);
  EXPECT_EQ(parse_whole_number("-2"), -2);
  EXPECT_EQ(parse_whole_number("010"), 10);  // decimal, not octal
  for (const char* bad : {"", "1.5", "1e3", "0x10", "2x", " 2", "+2", "99999999999999999999"}) {
    EXPECT_FALSE(parse_whole_number(bad)) << "'" << bad << "'";
  }
}

TEST(NumberOptions, RangesNameTheirBounds) {
  const NumberRange positive{.minimum = 0.0, .minimum_excluded = true};
  EXPECT_EQ(number_problem("0.5", positive), "");
  EXPECT_EQ(number_problem("0", positive), "'0' is out of range, expected a value > 0");
  EXPECT_EQ(number_problem("-1", positive), "'-1' is out of range, expected a value > 0");
  const NumberRange unit{0.0, 1.0};
  EXPECT_EQ(number_problem("1", unit), "");
  EXPECT_EQ(number_problem("1.5", unit), "'1.5' is out of range, expected a value in [0, 1]");
  const WholeNumberRange threads{0, 1024};
  EXPECT_EQ(whole_number_problem("0", threads), "");
  EXPECT_EQ(whole_number_problem("1025", threads),
            "'1025' is out of range, expected a value in 0..1024");
  EXPECT_EQ(whole_number_problem("two", threads), "'two' is not a whole number");
}

}  // namespace
}  // namespace radarpr::cli
