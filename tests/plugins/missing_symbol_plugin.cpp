// A plugin built against a radarpr that has a function this one lacks: it calls it, so dlopen with
// RTLD_NOW fails on an undefined symbol before the ABI record can be read. Compiled twice: with
// this radarpr's version (the loader must name the symbol) and declaring another minor version
// (RADARPR_PLUGIN_DECLARED_VERSION_MINOR; the loader must report the version mismatch).
#include "descriptors/plugins/plugin.hpp"

namespace radarpr {

// Declared as a newer radarpr would; defined nowhere in this one.
void register_descriptors_of_a_newer_radarpr(DescriptorRegistry& registry);

}  // namespace radarpr

namespace {

void register_with_the_newer_function(radarpr::DescriptorRegistry& registry) {
  radarpr::register_descriptors_of_a_newer_radarpr(registry);
}

}  // namespace

RADARPR_PLUGIN(register_with_the_newer_function);
