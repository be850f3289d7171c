# One CTest Fuzz.<name> run: a fresh scratch directory receives what the fuzzer finds; the
# committed corpus is only read (libFuzzer writes new inputs to its FIRST corpus directory only).
# Deterministic: -seed=1 and a fixed number of executions (the time cap only guards a slow
# machine). Fails if the fuzzer exits non-zero (crash, sanitizer report, leak, timeout, OOM).
#   cmake -DBIN=... -DCORPUS=... -DWORK=... -DRUNS=... -DSECONDS=... [-DDICT=...] -P run_fuzz_case.cmake
foreach(var BIN CORPUS WORK RUNS SECONDS)
  if(NOT DEFINED ${var} OR "${${var}}" STREQUAL "")
    message(FATAL_ERROR "run_fuzz_case.cmake: -D${var}=... is required")
  endif()
endforeach()

file(GLOB seeds ${CORPUS}/*)
list(LENGTH seeds seed_count)
if(seed_count EQUAL 0)
  message(FATAL_ERROR "${CORPUS}: the seed corpus is empty")
endif()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK}/new ${WORK}/artifacts)
set(args -seed=1 -runs=${RUNS} -max_total_time=${SECONDS} -timeout=10 -rss_limit_mb=2048
         -print_final_stats=1 -artifact_prefix=${WORK}/artifacts/)
if(DICT)
  list(APPEND args -dict=${DICT})
endif()
list(JOIN args " " shown)
message(STATUS "${BIN} ${shown} ${WORK}/new ${CORPUS}")
execute_process(COMMAND ${BIN} ${args} ${WORK}/new ${CORPUS}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE out)
message("${out}")
if(NOT rc EQUAL 0)
  file(GLOB artifacts ${WORK}/artifacts/*)
  message(FATAL_ERROR "fuzzer failed (exit ${rc}); reproducer(s): ${artifacts}")
endif()
string(REGEX MATCH "stat::number_of_executed_units: *[0-9]+" executed "${out}")
if(NOT executed)
  message(FATAL_ERROR "${BIN} exited 0 but printed no libFuzzer final stats: is it a fuzz target?")
endif()
message(STATUS "ok: ${seed_count} seeds, ${executed}")
