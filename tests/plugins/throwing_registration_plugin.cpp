// A plugin whose registration throws an exception of its own type, not derived from
// std::exception: its typeinfo lives in this library, which the loader closes after refusing it.
// The loader must report it as a load error, not let it escape and end the program.
#include "descriptors/plugins/plugin.hpp"

namespace {

struct PluginOwnFailure {
  int code;
};

void register_throwing(radarpr::DescriptorRegistry& /*registry*/) {
  throw PluginOwnFailure{7};
}

}  // namespace

RADARPR_PLUGIN(register_throwing);
