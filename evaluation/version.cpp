#include "evaluation/version.hpp"

#include "descriptors/plugins/plugin_version.hpp"

namespace radarpr {

std::string_view radarpr_version() {
  return RADARPR_VERSION_STRING;
}

}  // namespace radarpr
