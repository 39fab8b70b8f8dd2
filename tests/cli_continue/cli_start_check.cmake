# Usage: cmake -DCLI=<rbcstab> -DCASE=<case> -DWORK=<dir> -P cli_start_check.cmake
# A start you can trust and certified stability labels, end to end through `rbcstab continue`.
include(${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake)

# The in-plane scene whose start was the repelling orbit (|mu| = 1.024) after 32 periods of relaxation
# (tests/continuation/wrong_start_fixture.hpp); relaxed to the periodicity tolerance it is the attracting
# one (|mu| = 0.97659 at Lambda = 1.19991, margin 0.0234).
set(WRONG_START_ARGS continue --kind orbit --parameter Lambda --min 1.1 --max 1.3 --beta 1.5707963267948966
    --lambda 15.5 --Delta 0.05754 --Delta0 1e-6 --C 0.04120 --B 2 --delta 0)
# The in-plane ellipsoidal modal orbit (delta = 0 keeps l >= 3 at 0, so the relaxation stays on it),
# unstable to l = 3 at lambda = 5 (multiplier ~695).
set(UNSTABLE_ORBIT_ARGS continue --kind modal-orbit --parameter lambda --min 4.9 --max 5.1 --lambda 5 --Delta 1
    --Delta0 0.01 --B 2 --C 0.04 --L 5 --delta 0 --relax-T 600 --max-points 3)

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
if(CASE STREQUAL "start_wrong_case")
  execute_process(COMMAND ${CLI} ${WRONG_START_ARGS} --json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("exit ${rc}: ${err}")
  endif()
  foreach(key stability margin margin_error relaxation_periods periodicity_defect periodicity_tol relaxed refused)
    require_path("${out}" start ${key})
  endforeach()
  string(JSON stability GET "${out}" start stability)
  string(JSON periods GET "${out}" start relaxation_periods)
  string(JSON margin GET "${out}" start margin)
  if(NOT stability STREQUAL "stable" OR periods LESS 100 OR margin LESS 0.0233 OR margin GREATER 0.0235)
    fail("start ${stability} after ${periods} periods with margin ${margin}: expected the attracting orbit "
         "(margin 0.0234) after > 100 periods")
  endif()
  string(JSON n LENGTH "${out}" branch)
  math(EXPR last "${n} - 1")
  foreach(k RANGE ${last})
    string(JSON s GET "${out}" branch ${k} stability)
    string(JSON m GET "${out}" branch ${k} margin)
    string(JSON e GET "${out}" branch ${k} margin_error)
    if(NOT s STREQUAL "stable" OR NOT m GREATER e)
      fail("point ${k}: ${s}, margin ${m} +- ${e}: expected stable")
    endif()
  endforeach()
elseif(CASE STREQUAL "start_unstable_refused")
  execute_process(COMMAND ${CLI} ${UNSTABLE_ORBIT_ARGS} --json --csv ${WORK}/never.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 1)
    fail("expected exit 1, got ${rc}: ${err}")
  endif()
  foreach(fragment "unstable periodic orbit" "--allow-unstable-start")
    string(FIND "${err}" "${fragment}" pos)
    if(pos EQUAL -1)
      fail("message does not say '${fragment}': ${err}")
    endif()
  endforeach()
  if(NOT out STREQUAL "" OR EXISTS ${WORK}/never.csv)
    fail("output written for a refused start")
  endif()
elseif(CASE STREQUAL "start_unstable_allowed")
  execute_process(COMMAND ${CLI} ${UNSTABLE_ORBIT_ARGS} --allow-unstable-start --json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("exit ${rc}: ${err}")
  endif()
  string(JSON stability GET "${out}" start stability)
  string(JSON refused GET "${out}" start refused)
  string(JSON s0 GET "${out}" branch 0 stability)
  string(FIND "${err}" "note:" pos)
  if(NOT stability STREQUAL "unstable" OR refused OR NOT s0 STREQUAL "unstable" OR pos EQUAL -1)
    fail("start ${stability} (refused ${refused}), first point ${s0}, stderr '${err}': expected an unstable start "
         "continued with a note")
  endif()
elseif(CASE STREQUAL "stability_at_bp")
  # Modal equilibria in C from 0.08 down (lambda = 1, B = 1, L = 6): stable before the first BP
  # (C = 0.036169, Upsilon_3 = 0), unstable after, and the located BP itself uncertain.
  execute_process(COMMAND ${CLI} continue --kind modal --parameter C --min 0.02 --max 0.08 --direction backward
                  --lambda 1 --B 1 --C 0.08 --Delta 1 --Delta0 0.01 --L 6 --json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("exit ${rc}: ${err}")
  endif()
  foreach(key stability margin margin_error)
    require_path("${out}" special_points 0 ${key})
    require_path("${out}" branch 0 ${key})
  endforeach()
  string(JSON type GET "${out}" special_points 0 type)
  string(JSON s GET "${out}" special_points 0 stability)
  string(JSON first GET "${out}" branch 0 stability)
  string(JSON n LENGTH "${out}" branch)
  math(EXPR last "${n} - 1")
  string(JSON final GET "${out}" branch ${last} stability)
  if(NOT type STREQUAL "BP" OR NOT s STREQUAL "uncertain" OR NOT first STREQUAL "stable" OR NOT final STREQUAL "unstable")
    fail("${type} ${s}, first point ${first}, last ${final}: expected BP uncertain, stable -> unstable")
  endif()
else()
  fail("unknown case")
endif()
