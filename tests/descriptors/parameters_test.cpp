#include "descriptors/parameters.hpp"

#include <gtest/gtest.h>

namespace radarpr {
namespace {

ParameterSpec number_spec() {
  return {.name = "z_q", .kind = ParameterKind::number, .default_value = 6.0, .minimum = 0.0};
}

TEST(ParameterFormat, NumbersUseTheShortestRoundTripForm) {
  EXPECT_EQ(format_parameter_value(3.0), "3");
  EXPECT_EQ(format_parameter_value(0.5), "0.5");
  EXPECT_EQ(format_parameter_value(std::int64_t{80}), "80");
  EXPECT_EQ(format_parameter_value(true), "true");
  EXPECT_EQ(format_parameter_value(std::string("box")), "box");
}

TEST(ParameterParse, NumberAcceptsDecimalsAndRejectsGarbageAndBounds) {
  EXPECT_EQ(std::get<double>(parse_parameter_value(number_spec(), "2.5")), 2.5);
  EXPECT_THROW(parse_parameter_value(number_spec(), "2.5x"), ParameterError);
  EXPECT_THROW(parse_parameter_value(number_spec(), ""), ParameterError);
  EXPECT_THROW(parse_parameter_value(number_spec(), "-1"), ParameterError);  // below minimum 0
}

TEST(ParameterCheck, IntegerAcceptsIntegralDoublesOnly) {
  const ParameterSpec spec{.name = "alpha",
                           .kind = ParameterKind::integer,
                           .default_value = std::int64_t{50},
                           .minimum = 1.0};
  EXPECT_EQ(std::get<std::int64_t>(check_parameter_value(spec, 40.0)), 40);
  EXPECT_THROW(check_parameter_value(spec, 40.5), ParameterError);
  EXPECT_THROW(check_parameter_value(spec, std::int64_t{0}), ParameterError);
  EXPECT_THROW(check_parameter_value(spec, std::string("40")), ParameterError);
}

TEST(ParameterCheck, ChoiceMustBeListedAndErrorNamesTheParameter) {
  const ParameterSpec spec{.name = "kernel",
                           .kind = ParameterKind::choice,
                           .default_value = std::string("gaussian"),
                           .choices = {"gaussian", "box"}};
  EXPECT_NO_THROW(check_parameter_value(spec, std::string("box")));
  try {
    check_parameter_value(spec, std::string("boxx"));
    FAIL() << "expected a ParameterError";
  } catch (const ParameterError& error) {
    EXPECT_EQ(error.parameter(), "kernel");
    EXPECT_NE(std::string(error.what()).find("gaussian, box"), std::string::npos) << error.what();
  }
}

TEST(ParameterParse, BooleanNeedsTrueOrFalse) {
  const ParameterSpec spec{
      .name = "normalize", .kind = ParameterKind::boolean, .default_value = false};
  EXPECT_TRUE(std::get<bool>(parse_parameter_value(spec, "true")));
  EXPECT_THROW(parse_parameter_value(spec, "yes"), ParameterError);
}

}  // namespace
}  // namespace radarpr
