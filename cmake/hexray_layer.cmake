# hexray_layer(NAME [FOLDER folder] [SOURCES ...] [DEPENDS layer ...] [LIBRARIES ...] [PRIVATE_LIBRARIES ...])
#
# One library per layer of host/ (docs/architecture.md draws them). A layer's headers are reached
# only through an include root of its own, `build/layers/NAME/`, which holds a single link,
# FOLDER -> host/FOLDER: a target sees `#include "FOLDER/x.h"` only for the layers it depends on
# (DEPENDS, passed on to whatever depends on it), so a lower layer including a higher one is a
# compile error, not a review comment.
function(hexray_layer name)
  cmake_parse_arguments(LAYER "" "FOLDER" "SOURCES;DEPENDS;LIBRARIES;PRIVATE_LIBRARIES" ${ARGN})
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
    set_target_properties(hexray_${name} PROPERTIES UNITY_BUILD ${HEXRAY_UNITY_BUILD})
    set(scope PUBLIC)
    target_link_libraries(hexray_${name} PRIVATE hexray_warnings ${LAYER_PRIVATE_LIBRARIES})
  else()
    add_library(hexray_${name} INTERFACE)
    set(scope INTERFACE)
  endif()
  target_include_directories(hexray_${name} ${scope} ${root})
  target_link_libraries(hexray_${name} ${scope} ${LAYER_DEPENDS} ${LAYER_LIBRARIES})
endfunction()
