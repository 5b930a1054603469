# `cmake --install build --prefix P`: the radarpr program and what a descriptor plugin builds
# against (find_package(radarpr) then target_link_libraries(my_plugin PRIVATE
# radarpr::plugin_api)). Only the headers of the plugin interface are installed, under
# P/include/radarpr so that their "descriptors/..." and "datasets/..." includes stay unique.
include(CMakePackageConfigHelpers)

set(radarpr_plugin_headers
  datasets/byte_image.hpp
  datasets/polar_image.hpp
  descriptors/descriptor.hpp
  descriptors/descriptor_registry.hpp
  descriptors/extraction_stages.hpp
  descriptors/parameters.hpp
  descriptors/plugins/plugin.hpp
  # The building blocks of radarpr's own descriptors a plugin may reuse: the Cen 2018 feature
  # extractor with its shared parameters, and the ReFeree helpers (block profile, scan check,
  # L2 distance, timed stages). Their code is in the radarpr program that loads the plugin.
  descriptors/features/cen2018.hpp
  descriptors/features/cen2018_parameters.hpp
  descriptors/features/polar_features.hpp
  descriptors/referee/referee_common.hpp
)
foreach(header IN LISTS radarpr_plugin_headers)
  get_filename_component(folder ${header} DIRECTORY)
  install(FILES ${PROJECT_SOURCE_DIR}/${header}
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/radarpr/${folder})
endforeach()
install(FILES ${PROJECT_BINARY_DIR}/generated/descriptors/plugins/plugin_version.hpp
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/radarpr/descriptors/plugins)

install(TARGETS radarpr radarpr_plugin_api EXPORT radarprTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# The descriptors that need OpenCV, which the program loads from ../lib/radarpr/ relative to its
# own folder (descriptors/opencv_module/module_loader.cpp).
install(TARGETS radarpr_opencv_module LIBRARY DESTINATION ${RADARPR_OPENCV_MODULE_INSTALL_DIR})
# `radarpr bench`'s benchmark module, from the same folder (benchmarks/bench_module.hpp).
if(RADARPR_BUILD_BENCHMARKS)
  install(TARGETS radarpr_bench_module LIBRARY DESTINATION ${RADARPR_OPENCV_MODULE_INSTALL_DIR})
endif()
set_target_properties(radarpr_plugin_api PROPERTIES EXPORT_NAME plugin_api)
set(radarpr_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/radarpr)
install(EXPORT radarprTargets NAMESPACE radarpr:: DESTINATION ${radarpr_cmake_dir})

configure_package_config_file(${CMAKE_CURRENT_LIST_DIR}/radarprConfig.cmake.in
                              ${PROJECT_BINARY_DIR}/radarprConfig.cmake
                              INSTALL_DESTINATION ${radarpr_cmake_dir})
# A plugin must be rebuilt for another major.minor (the loader's rule, plugin_compatibility.hpp),
# so find_package(radarpr 0.1) accepts 0.1.x only.
write_basic_package_version_file(${PROJECT_BINARY_DIR}/radarprConfigVersion.cmake
                                 COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/radarprConfig.cmake
              ${PROJECT_BINARY_DIR}/radarprConfigVersion.cmake
        DESTINATION ${radarpr_cmake_dir})
