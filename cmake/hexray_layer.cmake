# hexray_layer(NAME [COLD] [FOLDER folder] [SOURCES ...] [DEPENDS layer ...] [LIBRARIES ...] [PRIVATE_LIBRARIES ...])
#
# One library per layer of host/ (docs/architecture.md draws them). A layer's headers are reached
# only through an include root of its own, `build/layers/NAME/`, which holds a single link,
# FOLDER -> host/FOLDER: a target sees `#include "FOLDER/x.h"` only for the layers it depends on
# (DEPENDS, passed on to whatever depends on it), so a lower layer including a higher one is a
# compile error, not a review comment. COLD: code that runs a few times per command (the command
# line, files, setting Vulkan up), compiled in Release at HEXRAY_COLD_OPTIMIZATION.
function(hexray_layer name)
  cmake_parse_arguments(LAYER "COLD" "FOLDER" "SOURCES;DEPENDS;LIBRARIES;PRIVATE_LIBRARIES" ${ARGN})
  if(NOT LAYER_FOLDER)
    set(LAYER_FOLDER ${name})
  endif()
  set(root ${PROJECT_BINARY_DIR}/layers/${name})
  file(MAKE_DIRECTORY ${root})
  file(CREATE_LINK ${PROJECT_SOURCE_DIR}/host/${LAYER_FOLDER} ${root}/${LAYER_FOLDER} SYMBOLIC)
  list(TRANSFORM LAYER_SOURCES PREPEND ${PROJECT_SOURCE_DIR}/host/${LAYER_FOLDER}/)
  list(TRANSFORM LAYER_DEPENDS PREPEND hexray_)
  if(LAYER_SOURCES)
    add_library(hexray_${name} STATIC ${LAYER_SOURCES})
    set_target_properties(hexray_${name} PROPERTIES UNITY_BUILD ${HEXRAY_UNITY_BUILD} UNITY_BUILD_BATCH_SIZE 0)
    set(scope PUBLIC)
    target_link_libraries(hexray_${name} PRIVATE hexray_warnings ${LAYER_PRIVATE_LIBRARIES})
    if(LAYER_COLD)
      target_compile_options(hexray_${name} PRIVATE $<$<CONFIG:Release>:${HEXRAY_COLD_OPTIMIZATION}>)
    endif()
  else()
    add_library(hexray_${name} INTERFACE)
    set(scope INTERFACE)
  endif()
  target_include_directories(hexray_${name} ${scope} ${root})
  target_link_libraries(hexray_${name} ${scope} ${LAYER_DEPENDS} ${LAYER_LIBRARIES})
endfunction()
