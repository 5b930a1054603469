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
