#pragma once

#include <string_view>

namespace radarpr {

// The project version from CMakeLists.txt; recorded in every result file.
std::string_view radarpr_version();

}  // namespace radarpr
