# One place for the compile options every radarpr target shares.
function(radarpr_set_warnings target)
  # -Wno-missing-field-initializers: GCC 12 flags C++20 designated initializers that leave
  # members at their defaults, which is what they are for.
  target_compile_options(${target} PRIVATE -Wall -Wextra -Wpedantic -Wshadow -Wconversion
                                           -Wno-sign-conversion -Wno-missing-field-initializers
                                           -Wnon-virtual-dtor)
  if(RADARPR_WARNINGS_AS_ERRORS)
    target_compile_options(${target} PRIVATE -Werror)
  endif()
endfunction()

# ccache caches a compile that uses a precompiled header only with this sloppiness (its manual,
# "Precompiled headers"); without it every such file would be compiled again on each rebuild.
# Call for each target with target_precompile_headers, when compiling through ccache.
function(radarpr_ccache_precompiled_headers target)
  get_target_property(launcher ${target} CXX_COMPILER_LAUNCHER)
  get_filename_component(launcher_name "${launcher}" NAME)
  if(launcher_name STREQUAL "ccache")
    set_target_properties(${target} PROPERTIES CXX_COMPILER_LAUNCHER
      "${CMAKE_COMMAND};-E;env;CCACHE_SLOPPINESS=pch_defines,time_macros;${launcher}")
  endif()
endfunction()
