# cmake -DHEXRAY=path/to/hexray -DHELP2MAN=path/to/help2man -DVERSION=x.y.z -DOUTPUT=hexray.1 -P man_page.cmake
#
# hexray(1) from the program's own help, so the page cannot drift from it: help2man turns
# `hexray --help` into the page, and every subcommand's `hexray NAME --help` follows in a
# COMMANDS section, verbatim. The version is given, not asked for: `hexray --version` opens a
# Vulkan device, which a build machine or a container build may not have.
foreach(variable HEXRAY HELP2MAN VERSION OUTPUT)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "man_page.cmake: -D${variable}=... is required")
  endif()
endforeach()

function(help_of output_variable)
  execute_process(COMMAND ${HEXRAY} ${ARGN} --help OUTPUT_VARIABLE help ERROR_VARIABLE error RESULT_VARIABLE result)
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "man_page.cmake: `hexray ${ARGN} --help` failed (${result}): ${error}")
  endif()
  set(${output_variable} "${help}" PARENT_SCOPE)
endfunction()

# roff: a backslash is \e, and a line starting with a dot or an apostrophe would be a request.
function(as_roff_text output_variable text)
  string(REPLACE "\\" "\\e" text "${text}")
  string(REGEX REPLACE "(^|\n)([.'])" "\\1\\\\&\\2" text "${text}")
  set(${output_variable} "${text}" PARENT_SCOPE)
endfunction()

help_of(main_help)
string(REGEX MATCH "\nSubcommands:\n(  [^\n]*\n)+" subcommand_lines "${main_help}")
string(REGEX MATCHALL "\n  [a-z][a-z-]*" subcommands "${subcommand_lines}")
if(NOT subcommands)
  message(FATAL_ERROR "man_page.cmake: `hexray --help` lists no subcommands under \"Subcommands:\"")
endif()

set(commands_section "[COMMANDS]\nEach subcommand's own help, as `hexray NAME --help` prints it.\n")
foreach(line IN LISTS subcommands)
  string(STRIP "${line}" subcommand)
  help_of(subcommand_help ${subcommand})
  as_roff_text(subcommand_help "${subcommand_help}")
  string(APPEND commands_section ".SS \"hexray ${subcommand}\"\n.nf\n${subcommand_help}.fi\n")
endforeach()
set(include_file ${OUTPUT}.include)
file(WRITE ${include_file} "${commands_section}")

execute_process(COMMAND ${HELP2MAN} --no-info --no-discard-stderr "--version-string=hexray ${VERSION}"
                        "--name=render scenes with a Vulkan compute shader, checked against a CPU reference"
                        --include=${include_file} --output=${OUTPUT} ${HEXRAY}
                RESULT_VARIABLE result ERROR_VARIABLE error)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "man_page.cmake: help2man failed (${result}): ${error}")
endif()
