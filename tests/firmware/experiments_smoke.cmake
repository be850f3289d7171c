# The smallest run of ringlet-experiments (the whole pipeline: data, Tables I and II, Fig. 2,
# Fig. 3, incremental learning), twice: with 1 thread and with 2. Checks that every output exists
# and is sane, and that the two runs wrote byte-identical files (the threads change nothing).
# Missions end after 10 s of simulated time: the smoke judges the pipeline, not whether goals are
# reached, and under qemu-aarch64 the missions are most of its time (149 s with 20 s missions).
#   cmake -DBIN=... -DEMULATOR=... -DOUT=... -DCONFIG_DIR=... -P experiments_smoke.cmake
file(REMOVE_RECURSE "${OUT}")
set(common --quick --experiences 40 --sizes 20,40 --fig2-distance 15 --repeats 1 --woods-trials 1 --folds 3
           --mission-timeout 10 --quiet --config-dir "${CONFIG_DIR}")
foreach(t 1 2)
  execute_process(COMMAND ${EMULATOR} "${BIN}" ${common} --threads ${t} --out "${OUT}/t${t}/experiments"
                          --markdown "${OUT}/t${t}/experiments.md"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "ringlet-experiments --threads ${t} exited with ${rc}:\n${out}\n${err}")
  endif()
endforeach()

set(files table1.csv table2.csv fig2.csv fig2_goals.csv fig3.csv incremental.csv training_missions.csv
          fig2.svg fig3.svg fig3_laser.svg incremental.svg training.exp)
foreach(f IN LISTS files)
  set(a "${OUT}/t1/experiments/${f}")
  set(b "${OUT}/t2/experiments/${f}")
  if(NOT EXISTS "${a}" OR NOT EXISTS "${b}")
    message(FATAL_ERROR "ringlet-experiments did not write ${f}")
  endif()
  file(SHA256 "${a}" ha)
  file(SHA256 "${b}" hb)
  if(NOT ha STREQUAL hb)
    message(FATAL_ERROR "${f} differs between 1 and 2 threads: ${a} ${b}")
  endif()
endforeach()

# Sane: the training data hold exactly the experiences asked for; Table I has its six learners
# with errors and correlations in range; every report section is there, naming the command.
file(STRINGS "${OUT}/t1/experiments/training.exp" lines)
list(LENGTH lines n)
if(NOT n EQUAL 42)
  message(FATAL_ERROR "training.exp: ${n} lines, expected 2 header lines and 40 experiences")
endif()
file(STRINGS "${OUT}/t1/experiments/table1.csv" rows)
list(LENGTH rows n)
if(NOT n EQUAL 7)
  message(FATAL_ERROR "table1.csv: ${n} lines, expected a header and 6 learners")
endif()
list(REMOVE_AT rows 0)
foreach(row IN LISTS rows)
  if(NOT row MATCHES "^[^,]+,40,[0-9]+\\.[0-9][0-9],-?[01]\\.[0-9]+,")
    message(FATAL_ERROR "table1.csv: not a sane row: ${row}")
  endif()
endforeach()
file(READ "${OUT}/t1/experiments.md" md)
foreach(section "## The issue's goals" "## Data" "## Table I" "## Table II" "## Fig. 2" "## Fig. 3"
                "The same trials with the laser alone" "## Incremental learning" "tools/ringlet experiments --quick"
                "experiments/fig3.svg" "experiments/fig3_laser.svg")
  string(FIND "${md}" "${section}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "experiments.md has no \"${section}\"")
  endif()
endforeach()
# fig3.csv: one baseline and one learned row per trial, with the prior map and with the laser alone.
file(STRINGS "${OUT}/t1/experiments/fig3.csv" rows)
list(FILTER rows INCLUDE REGEX "^(prior|laser),1,[0-9]+,(baseline|learned n=40),[01],")
list(LENGTH rows n)
if(NOT n EQUAL 4)
  message(FATAL_ERROR "fig3.csv: ${n} trial rows, expected baseline and learned with the prior map and the laser")
endif()
file(READ "${OUT}/t1/experiments/fig3.svg" svg)
string(REGEX MATCHALL "<svg " nested "${svg}")
list(LENGTH nested panels)
if(NOT panels EQUAL 5)
  message(FATAL_ERROR "fig3.svg: ${panels} <svg> elements, expected the figure and its four panels")
endif()
# Each panel is placed and scaled by the figure: its own <svg> tag carries the slot (x, y, width,
# height) and its viewBox, with no width of its own (a panel nested at its own 960 px inside a
# 480 px slot is clipped).
string(REGEX MATCHALL "<svg x=\"[^>]*viewBox" placed "${svg}")
list(LENGTH placed n)
if(NOT n EQUAL 4)
  message(FATAL_ERROR "fig3.svg: ${n} panels placed with their viewBox, expected 4")
endif()
