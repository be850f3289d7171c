# One place for the compile flags every Ringlet target shares.
add_library(ringlet_warnings INTERFACE)
target_compile_options(ringlet_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wsign-conversion
  -Wnon-virtual-dtor -Wold-style-cast -Wcast-align -Woverloaded-virtual
  # No -Wnull-dereference: GCC 12 reports false positives inside libstdc++ (istreambuf_iterator).
  -Wdouble-promotion -Wimplicit-fallthrough
  # Bit-identical simulation: never let the compiler fuse a*b+c differently per target.
  -ffp-contract=off
  $<$<BOOL:${RINGLET_WERROR}>:-Werror>)

# ringlet_library(name SOURCES... PUBLIC... PRIVATE...) keeps every library's shape the same: it
# exposes only its own folder's include/ (other layers' headers come through PUBLIC links).
function(ringlet_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  add_library(${name} ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${CMAKE_CURRENT_SOURCE_DIR}/include)
  target_link_libraries(${name} PUBLIC ${ARG_PUBLIC} PRIVATE ringlet_warnings ${ARG_PRIVATE})
endfunction()
