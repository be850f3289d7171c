# Ringlet's layering, checked when CMake configures the tree (see cmake/README.md, "Layering").
#
# A layer is a folder. Every target belongs to the layer whose folder holds the CMakeLists.txt that
# defines it (the deepest one: firmware/executive/ is the executive layer, not firmware/). The
# table below says which layers each layer may use. At the end of the top-level CMakeLists.txt,
# ringlet_check_layers() (deferred by including this file) walks every target and fails the
# configure step when
#   - a target links (LINK_LIBRARIES, INTERFACE_LINK_LIBRARIES, generator expressions included) a
#     target of a layer its own layer may not use;
#   - a target's include directories (INCLUDE_DIRECTORIES, INTERFACE_INCLUDE_DIRECTORIES) reach
#     into another layer's folder, in the source or the build tree: headers of another layer come
#     only through linking that layer's target, so a wrong #include fails to compile;
#   - a target defined outside every layer folder (at the top level: ringlet_warnings and
#     ringlet_opencv from cmake/) links a layer's target: those are shared settings and third-party
#     wrappers, which every layer may link;
#   - the table itself is not closed: a layer that may use M may use everything M may use (M's
#     PUBLIC links hand M's dependencies on), and no layer may use itself through others (a cycle).
# Relative includes ("../../other/include/x.hpp") bypass include directories; the CTest
# LayerRelativeIncludes (cmake/RingletRelativeIncludes.cmake) scans the sources for those.

# ringlet_layer(<name> FOLDER <dir> USES <layer>... WHY <reason>): one row of the table.
macro(ringlet_layer name)
  cmake_parse_arguments(_RL "" "FOLDER;WHY" "USES" ${ARGN})
  list(APPEND RINGLET_LAYERS ${name})
  set(RINGLET_LAYER_FOLDER_${name} ${_RL_FOLDER})
  set(RINGLET_LAYER_USES_${name} ${_RL_USES})
  set(RINGLET_LAYER_WHY_${name} "${_RL_WHY}")
endmacro()

set(RINGLET_LAYERS "")
#             layer       folder                    may use
ringlet_layer(hal         FOLDER hal
  WHY "hal/ is the bottom: interfaces and real backends use no other layer")
ringlet_layer(whiteboard  FOLDER whiteboard         USES hal
  WHY "the whiteboard sits below every algorithm layer and may use only hal/'s plain types")
ringlet_layer(remote      FOLDER remote             USES hal whiteboard
  WHY "the whiteboard over DDS: it reads and writes whiteboard messages and knows no algorithm, backend or firmware/")
ringlet_layer(executive   FOLDER firmware/executive USES hal
  WHY "the cyclic executive schedules tasks on hal/ clocks and knows nothing of what they run")
ringlet_layer(sim_hal     FOLDER sim_hal            USES hal
  WHY "the simulator is a hal/ backend: it implements hal/ and uses no algorithm layer")
ringlet_layer(vision      FOLDER vision             USES hal whiteboard
  WHY "algorithm layers use hal/ and the whiteboard only: never a backend, another algorithm layer or firmware/")
ringlet_layer(behaviour   FOLDER behaviour          USES hal whiteboard
  WHY "algorithm layers use hal/ and the whiteboard only: never a backend, another algorithm layer or firmware/")
ringlet_layer(planning    FOLDER planning           USES hal whiteboard
  WHY "algorithm layers use hal/ and the whiteboard only: never a backend, another algorithm layer or firmware/")
ringlet_layer(localization FOLDER localization     USES hal
  WHY "self-localization is an algorithm: hal/'s plain types only, never the whiteboard, a backend, another algorithm layer or firmware/")
ringlet_layer(tools       FOLDER tools              USES hal whiteboard sim_hal vision
  WHY "desktop tools (the dataset writer) may use the simulator and vision, never firmware/")
ringlet_layer(firmware    FOLDER firmware           USES hal whiteboard remote executive sim_hal vision behaviour planning localization
  WHY "firmware/ composes every layer the robot runs; no desktop tool, no test code")
ringlet_layer(tests       FOLDER tests              USES hal whiteboard remote executive sim_hal vision behaviour planning localization tools firmware
  WHY "tests may use every layer; nothing uses tests")

# Folder -> layer, deepest folder first. Sets <out> to the layer holding <rel> (a path relative to
# the source or build root), or to "" when no layer does.
function(_ringlet_layer_of_path out rel)
  set(best "")
  set(best_len -1)
  foreach(layer IN LISTS RINGLET_LAYERS)
    set(folder ${RINGLET_LAYER_FOLDER_${layer}})
    string(LENGTH "${folder}" len)
    if((rel STREQUAL folder OR rel MATCHES "^${folder}/") AND len GREATER best_len)
      set(best ${layer})
      set(best_len ${len})
    endif()
  endforeach()
  set(${out} "${best}" PARENT_SCOPE)
endfunction()

# The layer of an absolute path in the source tree or in the build tree (which mirrors it).
function(_ringlet_layer_of_abs out path)
  cmake_path(NORMAL_PATH path)
  set(layer "")
  foreach(root IN ITEMS "${CMAKE_BINARY_DIR}" "${CMAKE_SOURCE_DIR}")
    cmake_path(IS_PREFIX root "${path}" NORMALIZE inside)
    if(inside)
      cmake_path(RELATIVE_PATH path BASE_DIRECTORY "${root}" OUTPUT_VARIABLE rel)
      _ringlet_layer_of_path(layer "${rel}")
      break()   # the build tree is checked first: it may lie inside the source tree
    endif()
  endforeach()
  set(${out} "${layer}" PARENT_SCOPE)
endfunction()

# The table must be closed (PUBLIC links pass dependencies on) and acyclic.
function(_ringlet_check_layer_table out)
  set(errors "")
  foreach(layer IN LISTS RINGLET_LAYERS)
    if(NOT DEFINED RINGLET_LAYER_FOLDER_${layer} OR RINGLET_LAYER_FOLDER_${layer} STREQUAL "")
      list(APPEND errors "layer ${layer} has no FOLDER")
    endif()
    foreach(used IN LISTS RINGLET_LAYER_USES_${layer})
      if(NOT used IN_LIST RINGLET_LAYERS)
        list(APPEND errors "layer ${layer} uses ${used}, which is not a layer of the table")
      elseif(used STREQUAL layer)
        list(APPEND errors "layer ${layer} lists itself (a layer always uses its own targets)")
      else()
        foreach(indirect IN LISTS RINGLET_LAYER_USES_${used})
          if(indirect STREQUAL layer)
            list(APPEND errors "layers ${layer} and ${used} use each other (a cycle)")
          elseif(NOT indirect IN_LIST RINGLET_LAYER_USES_${layer})
            list(APPEND errors "layer ${layer} uses ${used}, which uses ${indirect}: ${layer} must list ${indirect} too (${used}'s PUBLIC links give it ${indirect}'s headers)")
          endif()
        endforeach()
      endif()
    endforeach()
  endforeach()
  set(${out} "${errors}" PARENT_SCOPE)
endfunction()

function(_ringlet_rule_text out layer)
  set(uses "${RINGLET_LAYER_USES_${layer}}")
  if(uses STREQUAL "")
    set(uses "no other layer")
  else()
    list(JOIN uses ", " uses)
  endif()
  set(${out} "rule '${layer} (${RINGLET_LAYER_FOLDER_${layer}}/) may use: ${uses}' (${RINGLET_LAYER_WHY_${layer}})"
      PARENT_SCOPE)
endfunction()

# Every buildsystem target under <dir>, as "<target>|<relative dir>" entries.
function(_ringlet_collect_targets out dir)
  get_property(targets DIRECTORY "${dir}" PROPERTY BUILDSYSTEM_TARGETS)
  cmake_path(RELATIVE_PATH dir BASE_DIRECTORY "${CMAKE_SOURCE_DIR}" OUTPUT_VARIABLE rel)
  set(found "")
  foreach(t IN LISTS targets)
    list(APPEND found "${t}|${rel}")
  endforeach()
  get_property(subdirs DIRECTORY "${dir}" PROPERTY SUBDIRECTORIES)
  foreach(sub IN LISTS subdirs)
    _ringlet_collect_targets(sub_found "${sub}")
    list(APPEND found ${sub_found})
  endforeach()
  set(${out} "${found}" PARENT_SCOPE)
endfunction()

# The names and paths in a link entry: names that may be targets inside any generator expression
# ($<LINK_ONLY:x>, $<TARGET_FILE:x>, ::@(dir) markers, plain names), paths whole.
function(_ringlet_words out entry)
  string(REPLACE "::" "_RINGLET_COLONS_" entry "${entry}")
  string(REGEX MATCHALL "[A-Za-z0-9_.+/-]+" words "${entry}")
  list(TRANSFORM words REPLACE "_RINGLET_COLONS_" "::")
  set(${out} "${words}" PARENT_SCOPE)
endfunction()

function(ringlet_check_layers)
  _ringlet_check_layer_table(errors)
  if(errors)
    list(JOIN errors "\n  " text)
    message(FATAL_ERROR "Layering table (cmake/RingletLayers.cmake) is inconsistent:\n  ${text}")
  endif()

  _ringlet_collect_targets(entries "${CMAKE_SOURCE_DIR}")
  # Target -> layer ("" for targets outside every layer folder).
  set(all_targets "")
  foreach(entry IN LISTS entries)
    string(REPLACE "|" ";" entry "${entry}")
    list(GET entry 0 t)
    list(LENGTH entry n)
    set(rel "")
    if(n GREATER 1)
      list(GET entry 1 rel)
    endif()
    _ringlet_layer_of_path(layer "${rel}")
    set(_layer_of_${t} "${layer}")
    set(_dir_of_${t} "${rel}")
    list(APPEND all_targets ${t})
  endforeach()

  set(violations "")
  foreach(t IN LISTS all_targets)
    set(layer "${_layer_of_${t}}")
    set(file "${_dir_of_${t}}/CMakeLists.txt")
    if(_dir_of_${t} STREQUAL ".")
      set(file "CMakeLists.txt")
    endif()
    if(layer STREQUAL "")
      set(where "no layer, ${file}")
      set(rule "rule 'targets outside the layer folders (shared settings, third-party wrappers) use no layer'")
    else()
      set(where "layer ${layer}, ${file}")
      _ringlet_rule_text(rule ${layer})
    endif()

    # Links: every name that is one of our targets, in whatever generator expression.
    set(links "")
    foreach(prop IN ITEMS LINK_LIBRARIES INTERFACE_LINK_LIBRARIES)
      get_target_property(value ${t} ${prop})
      if(value)
        list(APPEND links ${value})
      endif()
    endforeach()
    # A PRIVATE link of a static library is in both properties ($<LINK_ONLY:x> in the second):
    # each linked target once. A library file given by its path counts for the layer whose
    # folder (in the source or build tree) holds it.
    set(linked "")
    foreach(link IN LISTS links)
      _ringlet_words(words "${link}")
      foreach(w IN LISTS words)
        if(w MATCHES "/")
          if(IS_ABSOLUTE "${w}")
            _ringlet_layer_of_abs(path_layer "${w}")
            if(NOT path_layer STREQUAL "")
              set(_layer_of_${w} "${path_layer}")
              list(APPEND linked "${w}")
            endif()
          endif()
          continue()
        endif()
        if(TARGET "${w}")
          get_target_property(aliased "${w}" ALIASED_TARGET)
          if(aliased)
            set(w "${aliased}")
          endif()
        endif()
        if(DEFINED _layer_of_${w} AND NOT w STREQUAL t)
          list(APPEND linked "${w}")
        endif()
      endforeach()
    endforeach()
    list(REMOVE_DUPLICATES linked)
    foreach(w IN LISTS linked)
      set(dep_layer "${_layer_of_${w}}")
      if(dep_layer STREQUAL "")
        continue()   # shared settings and wrappers: anyone may link them
      elseif(NOT layer STREQUAL "" AND
             (dep_layer STREQUAL layer OR dep_layer IN_LIST RINGLET_LAYER_USES_${layer}))
        continue()
      endif()
      list(APPEND violations
        "${t} (${where}) links ${w} of layer ${dep_layer}: forbidden by ${rule}")
    endforeach()

    # Include directories: only the target's own layer's folders (or none of any layer).
    foreach(prop IN ITEMS INCLUDE_DIRECTORIES INTERFACE_INCLUDE_DIRECTORIES)
      get_target_property(dirs ${t} ${prop})
      if(NOT dirs)
        continue()
      endif()
      foreach(d IN LISTS dirs)
        # $<BUILD_INTERFACE:dir> and the like: the path inside.
        string(REGEX REPLACE "^\\$<[A-Z_]+:(.*)>$" "\\1" path "${d}")
        if(NOT IS_ABSOLUTE "${path}")
          continue()
        endif()
        _ringlet_layer_of_abs(dir_layer "${path}")
        if(NOT dir_layer STREQUAL "" AND NOT dir_layer STREQUAL layer)
          list(APPEND violations
            "${t} (${where}) has include directory ${path} (${prop}) of layer ${dir_layer}: a target sees another layer's headers only by linking that layer's target (${rule})")
        endif()
      endforeach()
    endforeach()
  endforeach()

  if(violations)
    list(LENGTH violations count)
    list(JOIN violations "\n  " text)
    message(FATAL_ERROR
      "Layering: ${count} violation(s) of the table in cmake/RingletLayers.cmake:\n  ${text}")
  endif()
  list(LENGTH all_targets count)
  message(STATUS "Layering: ${count} targets checked against cmake/RingletLayers.cmake")
endfunction()

# Check once everything is defined: at the end of the top-level CMakeLists.txt. (Not in script mode:
# cmake -P scripts include this file only for the table.)
if(NOT CMAKE_SCRIPT_MODE_FILE)
  cmake_language(DEFER DIRECTORY "${CMAKE_SOURCE_DIR}" CALL ringlet_check_layers)
endif()
