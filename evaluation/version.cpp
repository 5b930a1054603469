#include "evaluation/version.hpp"

namespace radarpr {

std::string_view radarpr_version() {
  return RADARPR_VERSION;
}

}  // namespace radarpr
