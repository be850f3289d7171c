# Self-test of the layering checks: a scratch project with one tiny library per layer of the real
# table (cmake/RingletLayers.cmake, included as is), linked along every allowed edge, into which
# violations are planted one at a time. Each plant must fail with the message that names it.
#
#   cmake -DRINGLET_SOURCE_DIR=<repo> -DWORK=<scratch dir> -DCXX=<c++ compiler> -P layer_rules_selftest.cmake
#
# Cases:
#   clean          configures, and every layer's source compiles: it includes the headers of every
#                  layer it may use (so the headers of linked layers are reachable);
#   link L->M      ringlet_L links ringlet_M in L's own CMakeLists.txt; configure must fail naming
#                  ringlet_L, ringlet_M and L's rule: EVERY pair the table forbids, planted together
#                  in one configure, and one pair per layer planted alone;
#   include L->M   for EVERY pair the table forbids: a source in L's folder, in a target that links
#                  ringlet_L only, includes <ringlet/M/M.hpp>; its compile must fail (header not found);
#   include dir    ringlet_vision adds behaviour/include to its include path; a global
#                  include_directories(hal/include) leaks hal/ to every target: configure fails;
#   shared link    a target outside the layer folders (ringlet_warnings) links a layer: configure fails;
#   genex link     hal links sim_hal inside $<BUILD_INTERFACE:...>, from another directory: fails;
#   path link      vision links behaviour's library file by its path in the build tree: fails;
#   table          the table made not closed (sim_hal may use vision but not whiteboard), or cyclic
#                  (hal may use whiteboard): configure fails naming the inconsistency;
#   relative       a relative #include leaving its layer: cmake/RingletRelativeIncludes.cmake fails.
cmake_minimum_required(VERSION 3.25)
foreach(var RINGLET_SOURCE_DIR WORK CXX)
  if(NOT ${var})
    message(FATAL_ERROR "layer_rules_selftest: -D${var}=... is required")
  endif()
endforeach()
include(${RINGLET_SOURCE_DIR}/cmake/RingletLayers.cmake)

set(src ${WORK}/src)
set(bin ${WORK}/bin)
file(REMOVE_RECURSE ${WORK})

# ---- the scratch project -----------------------------------------------------------------------
file(WRITE ${src}/CMakeLists.txt "cmake_minimum_required(VERSION 3.25)
project(ringlet_layer_selftest LANGUAGES CXX)
include(\"${RINGLET_SOURCE_DIR}/cmake/RingletLayers.cmake\")
set(PLANT \"\" CACHE STRING \"the violation to plant\")
add_library(ringlet_warnings INTERFACE)
if(PLANT STREQUAL \"global-include\")
  include_directories(\${CMAKE_SOURCE_DIR}/hal/include)
elseif(PLANT STREQUAL \"table-not-closed\")
  list(APPEND RINGLET_LAYER_USES_sim_hal vision)
elseif(PLANT STREQUAL \"table-cycle\")
  list(APPEND RINGLET_LAYER_USES_hal whiteboard)
endif()
foreach(layer IN LISTS RINGLET_LAYERS)
  add_subdirectory(\${RINGLET_LAYER_FOLDER_\${layer}})
endforeach()
if(PLANT STREQUAL \"include-dir\")
  target_include_directories(ringlet_vision PRIVATE \${CMAKE_SOURCE_DIR}/behaviour/include)
elseif(PLANT STREQUAL \"shared-link\")
  target_link_libraries(ringlet_warnings INTERFACE ringlet_hal)
elseif(PLANT STREQUAL \"genex-link\")
  target_link_libraries(ringlet_hal INTERFACE \$<BUILD_INTERFACE:ringlet_sim_hal>)
elseif(PLANT STREQUAL \"path-link\")
  target_link_libraries(ringlet_vision PRIVATE \${CMAKE_BINARY_DIR}/behaviour/libringlet_behaviour.a)
endif()
")

set(forbidden_pairs "")
set(index 0)
foreach(layer IN LISTS RINGLET_LAYERS)
  math(EXPR index "${index} + 1")
  set(dir ${src}/${RINGLET_LAYER_FOLDER_${layer}})
  set(uses ${RINGLET_LAYER_USES_${layer}})
  file(WRITE ${dir}/include/ringlet/${layer}/${layer}.hpp
    "#pragma once\ninline int ringlet_${layer}_value() { return ${index}; }\n")
  # Own header by a relative path that stays in the layer (the relative-include scan allows it).
  set(cpp "#include \"../include/ringlet/${layer}/${layer}.hpp\"\n")
  set(sum "ringlet_${layer}_value()")
  set(links "")
  foreach(used IN LISTS uses)
    string(APPEND cpp "#include <ringlet/${used}/${used}.hpp>\n")
    string(APPEND sum " + ringlet_${used}_value()")
    list(APPEND links ringlet_${used})
  endforeach()
  string(APPEND cpp "int ringlet_${layer}_sum();\nint ringlet_${layer}_sum() { return ${sum}; }\n")
  file(WRITE ${dir}/src/${layer}.cpp "${cpp}")
  list(JOIN links " " links)
  set(cmake "add_library(ringlet_${layer} STATIC src/${layer}.cpp)
target_include_directories(ringlet_${layer} PUBLIC \${CMAKE_CURRENT_SOURCE_DIR}/include)
target_link_libraries(ringlet_${layer} PUBLIC ${links} PRIVATE ringlet_warnings)
string(REPLACE \",\" \";\" plants \"\${PLANT}\")
foreach(plant IN LISTS plants)
  if(plant MATCHES \"^link:${layer}:(.+)$\")
    target_link_libraries(ringlet_${layer} PRIVATE ringlet_\${CMAKE_MATCH_1})
  endif()
endforeach()
")
  foreach(other IN LISTS RINGLET_LAYERS)
    if(other STREQUAL layer OR other IN_LIST uses)
      continue()
    endif()
    list(APPEND forbidden_pairs "${layer}:${other}")
    file(WRITE ${dir}/planted/${layer}_includes_${other}.cpp
      "#include <ringlet/${other}/${other}.hpp>\nint planted_${layer}_${other}();\nint planted_${layer}_${other}() { return ringlet_${other}_value(); }\n")
    string(APPEND cmake "add_library(planted_include_${layer}_${other} OBJECT EXCLUDE_FROM_ALL planted/${layer}_includes_${other}.cpp)
target_link_libraries(planted_include_${layer}_${other} PRIVATE ringlet_${layer})
")
  endforeach()
  file(WRITE ${dir}/CMakeLists.txt "${cmake}")
endforeach()

# ---- running cases -----------------------------------------------------------------------------
set(failures 0)
set(passes 0)

# CMake indents and wraps long message lines; compare with all whitespace runs made one space.
function(_flatten out text)
  string(REGEX REPLACE "[ \t\r\n]+" " " text "${text}")
  set(${out} "${text}" PARENT_SCOPE)
endfunction()

# _ok_if(<var> <condition>...): <var> = TRUE if the condition holds, else FALSE.
macro(_ok_if var)
  if(${ARGN})
    set(${var} TRUE)
  else()
    set(${var} FALSE)
  endif()
endmacro()

# _report(<name> <variable holding TRUE/FALSE> <detail shown on failure>)
macro(_report name ok detail)
  if(${ok})
    math(EXPR passes "${passes} + 1")
  else()
    math(EXPR failures "${failures} + 1")
    message("FAIL ${name}: ${detail}")
  endif()
endmacro()

function(_configure out_rc out_text plant)
  execute_process(
    COMMAND ${CMAKE_COMMAND} -S ${src} -B ${bin} -G "Unix Makefiles" -DCMAKE_CXX_COMPILER=${CXX}
            -DCMAKE_EXPORT_COMPILE_COMMANDS=ON "-DPLANT=${plant}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  _flatten(text "${o}${e}")
  set(${out_rc} ${rc} PARENT_SCOPE)
  set(${out_text} "${text}" PARENT_SCOPE)
endfunction()

# expect_configure_failure NAME PLANT TEXT...: configure fails and its output holds every TEXT.
macro(expect_configure_failure name plant)
  _configure(rc text "${plant}")
  set(ok TRUE)
  set(detail "")
  if(rc EQUAL 0)
    set(ok FALSE)
    set(detail "configure succeeded")
  endif()
  foreach(want IN ITEMS ${ARGN})
    _flatten(want "${want}")
    string(FIND "${text}" "${want}" at)
    if(at EQUAL -1)
      set(ok FALSE)
      string(APPEND detail " [missing: ${want}]")
    endif()
  endforeach()
  if(NOT ok)
    string(APPEND detail "\n  output: ${text}")
  endif()
  _report("${name}" ok "${detail}")
endmacro()

function(_rule_prefix out layer)
  set(${out} "forbidden by rule '${layer} (${RINGLET_LAYER_FOLDER_${layer}}/) may use:" PARENT_SCOPE)
endfunction()

# clean: configures and builds.
_configure(rc text "")
_ok_if(ok rc EQUAL 0 AND text MATCHES "Layering: [0-9]+ targets checked")
_report("clean configure" ok "rc ${rc}: ${text}")
# Compiles: each source with exactly the command CMake generated for its target (from
# compile_commands.json, which lists the planted targets too), syntax only. No make: a build tool
# per case would cost more than the compiles.
file(READ ${bin}/compile_commands.json commands)
string(JSON ncommands LENGTH "${commands}")
math(EXPR last "${ncommands} - 1")
foreach(i RANGE ${last})
  string(JSON file GET "${commands}" ${i} file)
  string(JSON command GET "${commands}" ${i} command)
  string(JSON directory GET "${commands}" ${i} directory)
  cmake_path(GET file FILENAME name)
  separate_arguments(command UNIX_COMMAND "${command}")
  set(command_of_${name} "${command}")
  set(directory_of_${name} "${directory}")
endforeach()

# compile NAME -> rc and text of compiling the source file NAME.
function(_compile out_rc out_text name)
  if(NOT DEFINED command_of_${name})
    set(${out_rc} "no compile command" PARENT_SCOPE)
    set(${out_text} "${name} is not in compile_commands.json" PARENT_SCOPE)
    return()
  endif()
  execute_process(COMMAND ${command_of_${name}} -fsyntax-only
                  WORKING_DIRECTORY ${directory_of_${name}}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
  set(${out_rc} "${rc}" PARENT_SCOPE)
  set(${out_text} "${o}${e}" PARENT_SCOPE)
endfunction()

# clean: every layer's source, which includes the headers of every layer it may use, compiles.
foreach(layer IN LISTS RINGLET_LAYERS)
  _compile(rc text ${layer}.cpp)
  _ok_if(ok rc EQUAL 0)
  _report("compile ${layer}.cpp (includes the layers ${layer} may use)" ok "rc ${rc}: ${text}")
endforeach()

# include L->M: the planted source fails to compile, for want of the header.
foreach(pair IN LISTS forbidden_pairs)
  string(REPLACE ":" ";" pair "${pair}")
  list(GET pair 0 layer)
  list(GET pair 1 other)
  _compile(rc text ${layer}_includes_${other}.cpp)
  # GCC: `fatal error: ringlet/M/M.hpp: No such file or directory`; clang: `'ringlet/M/M.hpp' file not found`.
  set(re "${layer}_includes_${other}\\.cpp:1:[0-9]+: fatal error: '?ringlet/${other}/${other}\\.hpp'?(: No such file or directory| file not found)")
  _ok_if(ok NOT rc EQUAL 0 AND text MATCHES "${re}")
  _report("include ${layer}->${other}" ok "rc ${rc}, wanted a 'header not found' error: ${text}")
endforeach()

# link L->M. One configure with every forbidden pair planted at once: each must be named. Then,
# alone, one pair per layer (one violation of each row of the table): alone it fails the configure.
# (One configure per pair would be thorough too, but ten times slower on a loaded machine.)
set(all_links "")
set(all_messages "")
foreach(pair IN LISTS forbidden_pairs)
  string(REPLACE ":" ";" parts "${pair}")
  list(GET parts 0 layer)
  list(GET parts 1 other)
  _rule_prefix(rule ${layer})
  list(APPEND all_links "link:${pair}")
  set(message_${layer}_${other}
    "ringlet_${layer} (layer ${layer}, ${RINGLET_LAYER_FOLDER_${layer}}/CMakeLists.txt) links ringlet_${other} of layer ${other}: ${rule}")
  list(APPEND all_messages "${message_${layer}_${other}}")
endforeach()
list(JOIN all_links "," all_links)
list(LENGTH forbidden_pairs npairs)
expect_configure_failure("link: all ${npairs} forbidden pairs at once" "${all_links}" ${all_messages})

set(one_per_layer hal:whiteboard whiteboard:vision remote:vision executive:behaviour sim_hal:vision vision:behaviour
                  behaviour:planning planning:vision localization:whiteboard tools:firmware firmware:tests)
foreach(layer IN LISTS RINGLET_LAYERS)
  set(planted FALSE)
  foreach(pair IN LISTS one_per_layer)
    if(pair MATCHES "^${layer}:(.+)$")
      set(planted TRUE)
      set(other ${CMAKE_MATCH_1})
      _ok_if(ok pair IN_LIST forbidden_pairs)
      _report("link ${pair} is a forbidden pair" ok "the table allows it: pick another")
      expect_configure_failure("link ${layer}->${other} alone" "link:${pair}" "${message_${layer}_${other}}")
    endif()
  endforeach()
  # Every layer that may not use some layer gets its own planted violation.
  if(NOT planted)
    set(has_forbidden FALSE)
    foreach(pair IN LISTS forbidden_pairs)
      if(pair MATCHES "^${layer}:")
        set(has_forbidden TRUE)
      endif()
    endforeach()
    _ok_if(ok NOT has_forbidden)
    _report("layer ${layer} has a planted link" ok "add a forbidden pair of ${layer} to one_per_layer")
  endif()
endforeach()

_rule_prefix(vision_rule vision)
expect_configure_failure("include dir of another layer" "include-dir"
  "ringlet_vision (layer vision, vision/CMakeLists.txt) has include directory ${src}/behaviour/include (INCLUDE_DIRECTORIES) of layer behaviour")
expect_configure_failure("global include_directories" "global-include"
  "ringlet_vision (layer vision, vision/CMakeLists.txt) has include directory ${src}/hal/include (INCLUDE_DIRECTORIES) of layer hal")
expect_configure_failure("shared target links a layer" "shared-link"
  "ringlet_warnings (no layer, CMakeLists.txt) links ringlet_hal of layer hal")
_rule_prefix(hal_rule hal)
expect_configure_failure("link inside a generator expression, from another directory" "genex-link"
  "ringlet_hal (layer hal, hal/CMakeLists.txt) links ringlet_sim_hal of layer sim_hal: ${hal_rule} no other layer'")
expect_configure_failure("link to another layer's library file by path" "path-link"
  "ringlet_vision (layer vision, vision/CMakeLists.txt) links ${bin}/behaviour/libringlet_behaviour.a of layer behaviour: ${vision_rule}")
expect_configure_failure("table not closed" "table-not-closed"
  "layer sim_hal uses vision, which uses whiteboard: sim_hal must list whiteboard too")
expect_configure_failure("table with a cycle" "table-cycle"
  "layers hal and whiteboard use each other (a cycle)")

# relative includes: the clean tree passes (its own-layer relative includes are fine), a planted
# one that leaves its layer fails.
set(scan ${RINGLET_SOURCE_DIR}/cmake/RingletRelativeIncludes.cmake)
execute_process(COMMAND ${CMAKE_COMMAND} -DRINGLET_ROOT=${src} -P ${scan}
                RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
_ok_if(ok rc EQUAL 0)
_report("relative includes: clean" ok "rc ${rc}: ${o}${e}")
file(WRITE ${src}/sim_hal/src/planted_relative.cpp
  "#include <vector>\n#include \"../../vision/include/ringlet/vision/vision.hpp\"\n")
execute_process(COMMAND ${CMAKE_COMMAND} -DRINGLET_ROOT=${src} -P ${scan}
                RESULT_VARIABLE rc OUTPUT_VARIABLE o ERROR_VARIABLE e)
set(want "sim_hal/src/planted_relative.cpp:2: sim_hal includes \"../../vision/include/ringlet/vision/vision.hpp\", which is in layer vision")
string(FIND "${o}${e}" "${want}" at)
_ok_if(ok NOT rc EQUAL 0 AND NOT at EQUAL -1)
_report("relative include sim_hal->vision" ok "rc ${rc}: ${o}${e}")

list(LENGTH forbidden_pairs npairs)
math(EXPR total "${passes} + ${failures}")
message("layer rules self-test: ${passes} of ${total} checks passed (${npairs} forbidden layer pairs, each planted as a link and as an include)")
if(failures GREATER 0)
  message(FATAL_ERROR "layer rules self-test: ${failures} case(s) failed")
endif()
