// load_opencv_module() of every program except `radarpr`: the module's descriptors are linked in
// (radarpr_opencv_descriptors), so registering them is all there is to do.
#include "descriptors/descriptor_registry.hpp"
#include "descriptors/opencv_module/opencv_module.hpp"

namespace radarpr {

void load_opencv_module(DescriptorRegistry& registry, std::string_view /*wanted*/) {
  register_opencv_module_descriptors(registry);
}

}  // namespace radarpr
