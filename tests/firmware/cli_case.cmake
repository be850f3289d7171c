# Runs the firmware binary once and checks its exit code and output (ctest -P script):
#   cmake -DBIN=<path> [-DEMULATOR=<qemu>] -DARGS="a;b" -DRC=<code> -DREGEX=<regex> -P cli_case.cmake
# Used by the CLI tests: exact exit codes matter to scripts driving the robot.
execute_process(COMMAND ${EMULATOR} ${BIN} ${ARGS}
  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(all "${out}${err}")
if(NOT rc STREQUAL RC)
  message(FATAL_ERROR "expected exit code ${RC}, got ${rc}\n--- output:\n${all}")
endif()
if(NOT all MATCHES "${REGEX}")
  message(FATAL_ERROR "output does not match '${REGEX}'\n--- output:\n${all}")
endif()
message(STATUS "exit ${rc}, output matches '${REGEX}'")
