# Optional sanitizer build: RADARPR_SANITIZE lists the sanitizers, as -fsanitize takes them
# (e.g. "address,undefined"). Applied to every target of the tree, test plugins included, so that
# a plugin loaded into an instrumented program is instrumented too. UBSan findings abort (no
# recovery): a finding fails the test that triggered it instead of scrolling past in its log.
set(RADARPR_SANITIZE "" CACHE STRING
    "Sanitizers to build with, as -fsanitize= takes them (e.g. address,undefined); empty: none")

if(RADARPR_SANITIZE)
  if(NOT RADARPR_SANITIZE MATCHES "^[a-z,]+$")
    message(FATAL_ERROR "RADARPR_SANITIZE='${RADARPR_SANITIZE}': expected a comma-separated list "
                        "of sanitizer names such as address,undefined")
  endif()
  # Frame pointers and line tables: readable stacks in the reports at little build cost.
  add_compile_options(-fsanitize=${RADARPR_SANITIZE} -fno-sanitize-recover=all
                      -fno-omit-frame-pointer)
  if(CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    add_compile_options(-gline-tables-only)
  else()
    add_compile_options(-g1)
  endif()
  add_link_options(-fsanitize=${RADARPR_SANITIZE})
endif()
