# The controller's code never calls libm's hypot: glibc computes it with FMA on aarch64 and without
# on x86-64, so a lockstep run that reads it differs between the two (hal/portable_math.hpp). Every
# source and header of the folders below is scanned; a call of std::hypot or ::hypot is an error.
# Desktop tools, evaluation and tests may use libm as they like: they decide nothing in a run.
#
#   cmake -DRINGLET_ROOT=<source tree> -P cmake/RingletPortableMath.cmake
#
# Prints `<file>:<line>: <the line>` per call and fails; prints a count of the files scanned otherwise.
cmake_minimum_required(VERSION 3.25)
if(NOT RINGLET_ROOT OR NOT IS_DIRECTORY "${RINGLET_ROOT}")
  message(FATAL_ERROR "RingletPortableMath: RINGLET_ROOT must name the source tree (got '${RINGLET_ROOT}')")
endif()

# What runs in the firmware process: its layers' libraries, not their tools/ folders.
set(controller_folders
  hal/include hal/src hal/can/include hal/can/src whiteboard/include whiteboard/src remote/include remote/src
  firmware/executive firmware/app firmware/camera_opencv sim_hal/include sim_hal/src
  vision/include vision/src behaviour/include behaviour/src planning/include planning/src
  planning/pddl/include planning/pddl/src localization/include localization/src
  behaviour/machines)  # the LLFSM models: their action code is compiled into the firmware
set(patterns "")
foreach(folder IN LISTS controller_folders)
  foreach(ext IN ITEMS hpp cpp h c machine)
    list(APPEND patterns "${RINGLET_ROOT}/${folder}/*.${ext}")
  endforeach()
endforeach()
file(GLOB_RECURSE files LIST_DIRECTORIES false ${patterns})

set(call_re "(std::|[^A-Za-z0-9_:])hypot\\(")
set(violations "")
set(count 0)
foreach(f IN LISTS files)
  file(READ "${f}" text)
  if(NOT text MATCHES "${call_re}")
    continue()
  endif()
  cmake_path(RELATIVE_PATH f BASE_DIRECTORY "${RINGLET_ROOT}" OUTPUT_VARIABLE rel)
  # One list element per line: ';' and the brackets that would change how a CMake list splits are
  # swapped for placeholders first, and swapped back for the message.
  string(REPLACE ";" "@SEMI@" text "${text}")
  string(REPLACE "[" "@OPEN@" text "${text}")
  string(REPLACE "]" "@CLOSE@" text "${text}")
  string(REPLACE "\n" ";" lines "${text}")
  set(n 0)
  foreach(line IN LISTS lines)
    math(EXPR n "${n} + 1")
    if(line MATCHES "${call_re}")
      string(REPLACE "@SEMI@" ";" line "${line}")
      string(REPLACE "@OPEN@" "[" line "${line}")
      string(REPLACE "@CLOSE@" "]" line "${line}")
      string(STRIP "${line}" code)
      string(APPEND violations "${rel}:${n}: ${code}\n")
      math(EXPR count "${count} + 1")
    endif()
  endforeach()
endforeach()

list(LENGTH files nfiles)
if(count GREATER 0)
  message("${violations}")
  message(FATAL_ERROR "RingletPortableMath: ${count} call(s) of libm's hypot in the controller (${nfiles} files scanned): "
                      "use hal::portable_hypot (ringlet/hal/portable_math.hpp), the same bits on every host")
endif()
message(STATUS "RingletPortableMath: OK (${nfiles} files scanned, no libm hypot in the controller)")
