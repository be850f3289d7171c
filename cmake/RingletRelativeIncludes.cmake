# Relative #includes that leave their layer, which per-target include directories cannot stop:
# `#include "../../vision/include/ringlet/vision/colour.hpp"` compiles from any folder. Every
# source and header under the layer folders of cmake/RingletLayers.cmake is scanned; an include
# whose path holds ".." and resolves (from the including file's folder) outside that file's layer
# is an error. Includes without ".." go through the include directories, which the configure-time
# check already limits to what a target links.
#
#   cmake -DRINGLET_ROOT=<source tree> -P cmake/RingletRelativeIncludes.cmake
#
# Prints `<file>:<line>: <layer> includes <path>, which is in <other layer or "no layer">` per
# violation and fails; prints a count of the files scanned otherwise.
cmake_minimum_required(VERSION 3.25)
if(NOT RINGLET_ROOT OR NOT IS_DIRECTORY "${RINGLET_ROOT}")
  message(FATAL_ERROR "RingletRelativeIncludes: RINGLET_ROOT must name the source tree (got '${RINGLET_ROOT}')")
endif()
include(${CMAKE_CURRENT_LIST_DIR}/RingletLayers.cmake)
cmake_path(NORMAL_PATH RINGLET_ROOT)
string(REGEX REPLACE "/$" "" RINGLET_ROOT "${RINGLET_ROOT}")

set(patterns "")
foreach(layer IN LISTS RINGLET_LAYERS)
  set(dir "${RINGLET_ROOT}/${RINGLET_LAYER_FOLDER_${layer}}")
  foreach(ext IN ITEMS h hh hpp hxx ipp inl tpp def c cc cpp cxx)
    list(APPEND patterns "${dir}/*.${ext}")
  endforeach()
endforeach()
file(GLOB_RECURSE files LIST_DIRECTORIES false ${patterns})
list(REMOVE_DUPLICATES files)   # nested layer folders (firmware/executive in firmware/)

set(include_re "^[ \t]*#[ \t]*include[ \t]*[<\"]([^>\"]*\\.\\.[^>\"]*)[>\"]")
set(violations "")
foreach(f IN LISTS files)
  file(STRINGS "${f}" hits REGEX "${include_re}")
  if(NOT hits)
    continue()
  endif()
  cmake_path(RELATIVE_PATH f BASE_DIRECTORY "${RINGLET_ROOT}" OUTPUT_VARIABLE rel)
  _ringlet_layer_of_path(layer "${rel}")
  cmake_path(GET f PARENT_PATH here)
  # Line numbers: only the few files with a hit are read whole (as text, never as a CMake list:
  # brackets in C++ would change how a list splits).
  file(READ "${f}" text)
  foreach(line IN LISTS hits)
    string(FIND "${text}" "${line}" at)
    string(SUBSTRING "${text}" 0 ${at} before)
    string(REGEX MATCHALL "\n" newlines "${before}")
    list(LENGTH newlines n)
    math(EXPR n "${n} + 1")
    string(REGEX MATCH "${include_re}" unused "${line}")
    set(inc "${CMAKE_MATCH_1}")
    set(target "${here}/${inc}")
    cmake_path(NORMAL_PATH target)
    cmake_path(IS_PREFIX RINGLET_ROOT "${target}" NORMALIZE inside)
    set(other "")
    if(inside)
      cmake_path(RELATIVE_PATH target BASE_DIRECTORY "${RINGLET_ROOT}" OUTPUT_VARIABLE target_rel)
      _ringlet_layer_of_path(other "${target_rel}")
    endif()
    if(NOT other STREQUAL layer)
      if(other STREQUAL "")
        set(other "no layer")
      else()
        set(other "layer ${other}")
      endif()
      list(APPEND violations "${rel}:${n}: ${layer} includes \"${inc}\", which is in ${other}: include other layers' headers as <ringlet/...> through the target you link")
    endif()
  endforeach()
endforeach()

list(LENGTH files nfiles)
if(violations)
  list(LENGTH violations count)
  list(JOIN violations "\n" text)
  message("${text}")
  message(FATAL_ERROR "RingletRelativeIncludes: ${count} relative include(s) leaving their layer (${nfiles} files scanned)")
endif()
message(STATUS "RingletRelativeIncludes: OK (${nfiles} files scanned, no relative include leaves its layer)")
