# Finds OpenCV modules (core, imgproc, imgcodecs) where OpenCV's own package file is absent.
#
# Debian ships OpenCVConfig.cmake only in libopencv-dev, which depends on every OpenCV module:
# about 220 more packages than libopencv-core-dev and libopencv-imgproc-dev, the two the radarpr
# program needs (the tests add libopencv-imgcodecs-dev). With only those installed, this module
# defines the imported targets OpenCVConfig.cmake would define (opencv_core, opencv_imgproc,
# opencv_imgcodecs) for the components asked for, with OpenCV's include folder.
# Sets OpenCVModules_FOUND and OpenCVModules_<component>_FOUND.

find_path(OpenCVModules_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4)
find_library(OpenCVModules_core_LIBRARY opencv_core)
set(OpenCVModules_core_FOUND FALSE)
if(OpenCVModules_INCLUDE_DIR AND OpenCVModules_core_LIBRARY)
  set(OpenCVModules_core_FOUND TRUE)
  if(NOT TARGET opencv_core)
    add_library(opencv_core SHARED IMPORTED)
    set_target_properties(opencv_core PROPERTIES
      IMPORTED_LOCATION "${OpenCVModules_core_LIBRARY}"
      INTERFACE_INCLUDE_DIRECTORIES "${OpenCVModules_INCLUDE_DIR}")
  endif()
endif()

foreach(module IN ITEMS imgproc imgcodecs)
  set(OpenCVModules_${module}_FOUND FALSE)
  if(${module} IN_LIST OpenCVModules_FIND_COMPONENTS AND OpenCVModules_core_FOUND)
    find_library(OpenCVModules_${module}_LIBRARY opencv_${module})
    mark_as_advanced(OpenCVModules_${module}_LIBRARY)
    if(OpenCVModules_${module}_LIBRARY)
      set(OpenCVModules_${module}_FOUND TRUE)
      if(NOT TARGET opencv_${module})
        add_library(opencv_${module} SHARED IMPORTED)
        set_target_properties(opencv_${module} PROPERTIES
          IMPORTED_LOCATION "${OpenCVModules_${module}_LIBRARY}"
          INTERFACE_LINK_LIBRARIES opencv_core)
      endif()
    endif()
  endif()
endforeach()

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenCVModules
                                  REQUIRED_VARS OpenCVModules_INCLUDE_DIR OpenCVModules_core_LIBRARY
                                  HANDLE_COMPONENTS)
mark_as_advanced(OpenCVModules_INCLUDE_DIR OpenCVModules_core_LIBRARY)
