# cmake -DBUILD_DIR=build -DSOURCE_DIR=. -DWORK_DIR=scratch -DEXPECT_MAN_PAGE=ON|OFF -P install_test.cmake
#
# `cmake --install` into a scratch prefix installs hexray and its man page and nothing else, and
# the installed hexray runs from another directory: --version, and a tiny render of a shipped scene.
foreach(variable BUILD_DIR SOURCE_DIR WORK_DIR EXPECT_MAN_PAGE)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "install_test.cmake: -D${variable}=... is required")
  endif()
endforeach()

set(prefix ${WORK_DIR}/prefix)
set(elsewhere ${WORK_DIR}/elsewhere)
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${elsewhere})

execute_process(COMMAND ${CMAKE_COMMAND} --install ${BUILD_DIR} --prefix ${prefix}
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${result}):\n${output}")
endif()

set(expected_files bin/hexray)
if(EXPECT_MAN_PAGE)
  list(APPEND expected_files share/man/man1/hexray.1)
endif()
file(GLOB_RECURSE installed_files RELATIVE ${prefix} LIST_DIRECTORIES false ${prefix}/*)
list(SORT installed_files)
if(NOT installed_files STREQUAL expected_files)
  message(FATAL_ERROR "installed: [${installed_files}], expected exactly: [${expected_files}]")
endif()

# The installed copy, from a directory with nothing of the source or build tree in it, with a
# kernel cache of its own.
function(run_installed output_variable)
  execute_process(COMMAND ${CMAKE_COMMAND} -E env XDG_CACHE_HOME=${WORK_DIR}/cache ${prefix}/bin/hexray ${ARGN}
                  WORKING_DIRECTORY ${elsewhere} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "installed `hexray ${ARGN}` failed (${result}):\n${output}")
  endif()
  set(${output_variable} "${output}" PARENT_SCOPE)
endfunction()

run_installed(version --version)
if(NOT version MATCHES "^hexray [0-9]+\\.[0-9]+\\.[0-9]+ ")
  message(FATAL_ERROR "installed `hexray --version` printed:\n${version}")
endif()

# The smallest render that goes through the GPU path: a 24x16 PNG, its size read from the IHDR chunk.
run_installed(render_report render ${SOURCE_DIR}/scenes/lecture-demo.json --backend gpu --width 24 --height 16
              -o tiny.png)
if(NOT EXISTS ${elsewhere}/tiny.png)
  message(FATAL_ERROR "installed `hexray render` left no tiny.png:\n${render_report}")
endif()
file(READ ${elsewhere}/tiny.png png_header LIMIT 24 HEX)
if(NOT png_header MATCHES "^89504e470d0a1a0a0000000d49484452(........)(........)$")
  message(FATAL_ERROR "tiny.png is not a PNG: ${png_header}")
endif()
math(EXPR width "0x${CMAKE_MATCH_1}")
math(EXPR height "0x${CMAKE_MATCH_2}")
if(NOT width EQUAL 24 OR NOT height EQUAL 16)
  message(FATAL_ERROR "tiny.png is ${width}x${height}, not 24x16")
endif()

# The man page has a section for every subcommand the installed hexray's help lists.
if(EXPECT_MAN_PAGE)
  run_installed(help --help)
  string(REGEX MATCH "\nSubcommands:\n(  [^\n]*\n)+" subcommand_lines "${help}")
  string(REGEX MATCHALL "\n  [a-z][a-z-]*" subcommands "${subcommand_lines}")
  if(NOT subcommands MATCHES "render")
    message(FATAL_ERROR "installed `hexray --help` lists no render subcommand:\n${help}")
  endif()
  file(READ ${prefix}/share/man/man1/hexray.1 man_page)
  foreach(line IN LISTS subcommands)
    string(STRIP "${line}" subcommand)
    string(FIND "${man_page}" ".SS \"hexray ${subcommand}\"" position)
    if(position EQUAL -1)
      message(FATAL_ERROR "the man page has no section for `hexray ${subcommand}`")
    endif()
  endforeach()
  if(NOT man_page MATCHES "\n\\.TH HEXRAY \"1\"")
    message(FATAL_ERROR "the man page has no .TH HEXRAY \"1\" header")
  endif()
endif()
