# Runs the firmware binary once and checks its exit code and output (ctest -P script):
#   cmake -DBIN=<path> [-DEMULATOR=<qemu>] -DARGS="a;b" -DRC=<code> -DREGEX=<regex>
#         [-DNOT_REGEX=<regex>] [-DMAX_OUTPUT=<bytes>] -P cli_case.cmake
# Used by the CLI tests: exact exit codes matter to scripts driving the robot. NOT_REGEX must not
# appear (e.g. "MISSION": the error came before the run); MAX_OUTPUT bounds stdout + stderr.
execute_process(COMMAND ${EMULATOR} ${BIN} ${ARGS}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
string(LENGTH "${all}" length)
string(SUBSTRING "${all}" 0 20000 shown)
if(NOT rc STREQUAL RC)
  message(FATAL_ERROR "expected exit code ${RC}, got ${rc}\n--- output (${length} bytes):\n${shown}")
endif()
if(NOT all MATCHES "${REGEX}")
  message(FATAL_ERROR "output does not match '${REGEX}'\n--- output (${length} bytes):\n${shown}")
endif()
if(DEFINED NOT_REGEX AND NOT NOT_REGEX STREQUAL "" AND all MATCHES "${NOT_REGEX}")
  message(FATAL_ERROR "output matches '${NOT_REGEX}', which it must not\n--- output:\n${shown}")
endif()
if(DEFINED MAX_OUTPUT AND NOT MAX_OUTPUT STREQUAL "" AND length GREATER MAX_OUTPUT)
  message(FATAL_ERROR "output is ${length} bytes, more than ${MAX_OUTPUT}\n--- output:\n${shown}")
endif()
message(STATUS "exit ${rc}, output matches '${REGEX}' (${length} bytes)")
