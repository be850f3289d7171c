# ringlet_llfsm_machines(<target> MODELS a.machine ... [NAMESPACE ns] [INCLUDE_DIR dir])
#
# Compiles each LLFSM model at build time with behaviour/llfsmc/llfsmc.py into
#   <build>/llfsm/<target>/include/<INCLUDE_DIR>/<stem>.hpp   (included as "<INCLUDE_DIR>/<stem>.hpp")
#   <build>/llfsm/<target>/src/<stem>.cpp                      (added to <target>)
#   <build>/llfsm/<target>/dot/<stem>.dot                      (the diagram)
# A model error (printed as `model:line:col: error: message`) fails the build. The generator is a
# host program (stdlib-only Python 3), so this works unchanged in cross builds. It checks externals
# and their fields against the whiteboard schema, so the outputs depend on schema.def too. The
# target must link ringlet_llfsm and ringlet_whiteboard (the generated code uses both).
# RINGLET_PYTHON3: the host's Python 3 (top-level CMakeLists.txt).
set(RINGLET_LLFSMC ${CMAKE_CURRENT_LIST_DIR}/../llfsmc/llfsmc.py CACHE INTERNAL "LLFSM model compiler")
# The compiler's modules (llfsmc.py is only the entry point): a change to any regenerates.
file(GLOB _llfsmc_sources CONFIGURE_DEPENDS ${CMAKE_CURRENT_LIST_DIR}/../llfsmc/llfsmc/*.py
     ${CMAKE_CURRENT_LIST_DIR}/../../whiteboard/schema/*.py)
set(RINGLET_LLFSMC_SOURCES ${RINGLET_LLFSMC} ${_llfsmc_sources} CACHE INTERNAL "LLFSM model compiler sources")
get_filename_component(_wb_schema ${CMAKE_CURRENT_LIST_DIR}/../../whiteboard/include/ringlet/whiteboard/schema.def ABSOLUTE)
set(RINGLET_WB_SCHEMA ${_wb_schema} CACHE INTERNAL "whiteboard schema the LLFSM models are checked against")

function(ringlet_llfsm_machines target)
  cmake_parse_arguments(ARG "" "NAMESPACE;INCLUDE_DIR" "MODELS" ${ARGN})
  if(NOT ARG_NAMESPACE)
    set(ARG_NAMESPACE ringlet::behaviour::machines)
  endif()
  if(NOT ARG_INCLUDE_DIR)
    set(ARG_INCLUDE_DIR ringlet/behaviour/machines)
  endif()
  set(out ${CMAKE_CURRENT_BINARY_DIR}/llfsm/${target})
  set(dots "")
  foreach(model IN LISTS ARG_MODELS)
    get_filename_component(model_abs ${model} ABSOLUTE)
    get_filename_component(stem ${model} NAME_WE)
    set(hpp ${out}/include/${ARG_INCLUDE_DIR}/${stem}.hpp)
    set(cpp ${out}/src/${stem}.cpp)
    set(dot ${out}/dot/${stem}.dot)
    add_custom_command(
      OUTPUT ${hpp} ${cpp} ${dot}
      COMMAND ${RINGLET_PYTHON3} ${RINGLET_LLFSMC} ${model_abs}
              --hpp ${hpp} --cpp ${cpp} --dot ${dot} --schema ${RINGLET_WB_SCHEMA}
              --namespace ${ARG_NAMESPACE} --include-dir ${ARG_INCLUDE_DIR}
      DEPENDS ${model_abs} ${RINGLET_LLFSMC_SOURCES} ${RINGLET_WB_SCHEMA}
      COMMENT "llfsmc ${stem}.machine"
      VERBATIM)
    target_sources(${target} PRIVATE ${cpp} ${hpp})
    list(APPEND dots ${dot})
  endforeach()
  target_include_directories(${target} PUBLIC ${out}/include)
  set_property(TARGET ${target} APPEND PROPERTY RINGLET_LLFSM_DOTS ${dots})
endfunction()
