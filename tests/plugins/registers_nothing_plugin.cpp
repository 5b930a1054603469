// A well-formed plugin whose registration adds no descriptor: the loader must refuse it rather
// than load a plugin that does nothing.
#include "descriptors/plugins/plugin.hpp"

namespace {

void register_nothing(radarpr::DescriptorRegistry& /*registry*/) {}

}  // namespace

RADARPR_PLUGIN(register_nothing);
