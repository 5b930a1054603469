#pragma once

#include <stdexcept>
#include <string_view>

#include <fmt/format.h>

namespace radarpr::synthetic {

// The one check behind every validation of the synthetic world: throws std::invalid_argument
// "<subject>: <field> = <value> is invalid, expected <expected>" unless `condition` holds.
inline void require(bool condition, std::string_view subject, std::string_view field, double value,
                    std::string_view expected) {
  if (!condition) {
    throw std::invalid_argument(
        fmt::format("{}: {} = {} is invalid, expected {}", subject, field, value, expected));
  }
}

}  // namespace radarpr::synthetic
