#pragma once

// Numbers given on the command line. A value is read as one whole token ("0.2abc", "1e", " 3"
// and "0x10" are refused, not read as 0.2, 1, 3 or 16), must be finite ("inf", "nan" and
// "1e999" are refused) and lie in the option's range; otherwise the command line is refused
// (exit code 2) with a message naming the option and the value. Every numeric option of every
// verb is added through these functions, so all of them follow the same rules.
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace radarpr::cli {

// The number spelled by the whole of `text` (decimal, optional sign, fraction and exponent), when
// it is one and finite.
std::optional<double> parse_number(std::string_view text);
// The whole number spelled by the whole of `text` (decimal digits, optional '-').
std::optional<long long> parse_whole_number(std::string_view text);

// The values an option accepts, for its check and its help ("M > 0", "N in 1..1024").
struct NumberRange {
  double minimum = -std::numeric_limits<double>::max();
  double maximum = std::numeric_limits<double>::max();
  bool minimum_excluded = false;  // minimum itself refused: (minimum, maximum]
};

struct WholeNumberRange {
  long long minimum = std::numeric_limits<long long>::min();
  long long maximum = std::numeric_limits<long long>::max();
};

// Why `text` is no acceptable value ("" when it is one): "'inf' is not a finite number",
// "'0' is not > 0", "'2000' is not in 1..1024".
std::string number_problem(std::string_view text, const NumberRange& range);
std::string whole_number_problem(std::string_view text, const WholeNumberRange& range);

// `--name VALUE` read into `target`; `value_name` is what the help shows (M, N, SECONDS).
CLI::Option* add_number_option(CLI::App& verb, const std::string& name,
                               std::optional<double>& target, const NumberRange& range,
                               const std::string& value_name, const std::string& help);
CLI::Option* add_whole_number_option(CLI::App& verb, const std::string& name,
                                     std::optional<long long>& target,
                                     const WholeNumberRange& range, const std::string& value_name,
                                     const std::string& help);
// `--name N,N,...` (also `--name N --name N`): every element checked, all kept in order.
CLI::Option* add_whole_numbers_option(CLI::App& verb, const std::string& name,
                                      std::vector<long long>& target, const WholeNumberRange& range,
                                      const std::string& value_name, const std::string& help);

}  // namespace radarpr::cli
