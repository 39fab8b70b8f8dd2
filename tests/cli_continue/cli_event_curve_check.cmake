# rbcstab continue --curve UZ end to end: the swinging <-> tumbling transition of in-plane orbits as a
# curve in two parameters, checked against independent one-parameter runs of the CLI (the UZ located on
# a branch at the curve's end value of the second parameter), the modal-orbit path against the reduced
# one, and no UZ on the branch refused (exit 1, a message, nothing written).
# Usage: cmake -DCLI=<rbcstab> -DCASE=<case> -DWORK=<dir> -P cli_event_curve_check.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake)

# Fig. 2's in-plane scene (lambda = 5, Delta0 = 0.01, B = 2, C = 0.04) in Delta: the UZ near 0.3848.
set(SCENE --Delta0 0.01 --B 2 --segments 4)
set(ORBIT_ARGS continue --kind orbit --parameter Delta --min 0.3 --max 0.45 --direction forward --lambda 5
    --Delta 0.3 --C 0.04 --L 2 ${SCENE})

# The UZ Delta of a one-parameter orbit branch (`kind`, extra args): sets UZ_DELTA in the caller.
macro(uz_delta)
  execute_process(COMMAND ${CLI} continue --parameter Delta --direction forward ${SCENE} ${ARGN} --json
                  RESULT_VARIABLE urc OUTPUT_VARIABLE uout ERROR_VARIABLE uerr)
  if(NOT urc EQUAL 0)
    fail("one-parameter run ${ARGN}: exit ${urc}: ${uerr}")
  endif()
  string(JSON utype GET "${uout}" special_points 0 type)
  string(JSON UZ_DELTA GET "${uout}" special_points 0 Delta)
  if(NOT utype STREQUAL "UZ")
    fail("one-parameter run ${ARGN}: first special point ${utype}, expected UZ")
  endif()
endmacro()

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
if(CASE STREQUAL "curve_uz_orbit")
  execute_process(COMMAND ${CLI} ${ORBIT_ARGS} --curve UZ --parameter2 lambda --min2 4 --max2 6 --csv ${WORK}/uz.csv
                  --save ${WORK}/uz_file.json --json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("exit ${rc}: ${err}")
  endif()
  # The event curve's branch file loads back, and a restart from its first label says how it started.
  execute_process(COMMAND ${CLI} continue --restart ${WORK}/uz_file.json --label 1 --parameter Delta --min 0.3 --max 0.45
                  --json RESULT_VARIABLE rrc OUTPUT_VARIABLE rout ERROR_VARIABLE rerr)
  if(NOT rrc EQUAL 0)
    fail("restart from the UZ curve's file: exit ${rrc}: ${rerr}")
  endif()
  string(JSON method GET "${rout}" start method)
  if(NOT method STREQUAL "restart")
    fail("restart from the UZ curve's file: start.method = '${method}', expected 'restart'")
  endif()
  foreach(key Delta lambda r Psi t_passage stable multipliers)
    require_path("${out}" branch 0 ${key})
  endforeach()
  string(JSON type GET "${out}" curve type)
  string(JSON system GET "${out}" curve system)
  string(JSON st GET "${out}" curve start type)
  string(JSON name GET "${out}" curve start name)
  string(JSON D0 GET "${out}" curve start Delta)
  string(JSON free GET "${out}" free_parameter)
  if(NOT type STREQUAL "UZ" OR NOT system STREQUAL "event" OR NOT st STREQUAL "UZ" OR NOT name STREQUAL "swing_tumble"
     OR NOT free STREQUAL "lambda" OR D0 LESS 0.3847 OR D0 GREATER 0.3849)
    fail("curve ${type} (${system}, free ${free}) from ${st} ${name} at Delta = ${D0}; expected UZ (event, free "
         "lambda) from UZ swing_tumble at Delta = 0.38478")
  endif()
  file(STRINGS ${WORK}/uz.csv lines)
  list(GET lines 0 header)
  if(NOT header MATCHES "^Delta,lambda," OR NOT header MATCHES ",t_passage,")
    fail("header: ${header}")
  endif()
  string(JSON n LENGTH "${out}" branch)
  math(EXPR last "${n} - 1")
  string(JSON lfirst GET "${out}" branch 0 lambda)
  string(JSON llast GET "${out}" branch ${last} lambda)
  string(JSON Dlast GET "${out}" branch ${last} Delta)
  if(n LESS 5 OR NOT lfirst EQUAL 4 OR NOT llast EQUAL 6)
    fail("${n} points, lambda ${lfirst} .. ${llast}; expected >= 5 points from 4 to 6 (the bounds)")
  endif()
  # The independent computation: the transition of the branch in Delta at lambda = 6 (its own start,
  # the UZ function +-r_min located by the secant). Both converged to 1e-12 and located to 1e-11: 1e-10.
  uz_delta(--kind orbit --min 0.25 --max 0.32 --Delta 0.25 --lambda 6 --C 0.04 --L 2)
  expect_close("curve at lambda = 6 vs the one-parameter UZ" "${Dlast}" "${UZ_DELTA}" 100)
elseif(CASE STREQUAL "curve_uz_modal_orbit")
  # C = 0.1: the l = 3 mode decays, so the modal orbit is the ellipsoidal one, on which the reduced system
  # is exact: the modal-orbit transition curve (L = 3) is the reduced one.
  set(ARGS --parameter Delta --min 0.7 --max 1 --direction forward --lambda 5 --Delta 0.7 --C 0.1 ${SCENE}
      --curve UZ --parameter2 lambda --min2 5 --max2 6 --json)
  execute_process(COMMAND ${CLI} continue --kind modal-orbit --L 3 ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE mout
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("modal-orbit: exit ${rc}: ${err}")
  endif()
  execute_process(COMMAND ${CLI} continue --kind orbit --L 2 ${ARGS} RESULT_VARIABLE rc OUTPUT_VARIABLE rout
                  ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("orbit: exit ${rc}: ${err}")
  endif()
  foreach(key Delta lambda r Psi t_passage)
    require_path("${mout}" branch 0 ${key})
  endforeach()
  string(JSON system GET "${mout}" curve system)
  string(JSON n LENGTH "${mout}" branch)
  math(EXPR last "${n} - 1")
  string(JSON lm GET "${mout}" branch ${last} lambda)
  string(JSON Dm GET "${mout}" branch ${last} Delta)
  string(JSON n LENGTH "${rout}" branch)
  math(EXPR last "${n} - 1")
  string(JSON lr GET "${rout}" branch ${last} lambda)
  string(JSON Dr GET "${rout}" branch ${last} Delta)
  if(NOT system STREQUAL "event" OR NOT lm EQUAL 6 OR NOT lr EQUAL 6)
    fail("modal-orbit curve (${system}) ends at lambda = ${lm}, reduced at ${lr}; expected event curves to lambda = 6")
  endif()
  # Two curves of two systems (4 and 24 shooting unknowns), each converged to 1e-12: 1e-10 (measured 1e-15).
  expect_close("modal-orbit vs reduced transition at lambda = 6" "${Dm}" "${Dr}" 100)
elseif(CASE STREQUAL "curve_uz_point")
  # --point K: the branch in beta at Delta = 1 has two UZs, at beta* and pi - beta* (the reduced system is
  # the same at beta and pi - beta); their curves in (beta, Delta) are mirror images: beta_1 + beta_2 = pi
  # at the start and at Delta = 0.5, the curves' first points (each converged to 1e-12: 1e-9).
  foreach(K 1 2)
    execute_process(COMMAND ${CLI} continue --kind orbit --parameter beta --lambda 5 --Delta 1 --C 0.04 --L 2 ${SCENE}
                    --curve UZ --parameter2 Delta --min2 0.5 --max2 1.5 --point ${K} --json
                    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
    if(NOT rc EQUAL 0)
      fail("--point ${K}: exit ${rc}: ${err}")
    endif()
    string(JSON start${K} GET "${out}" curve start beta)
    string(JSON D${K} GET "${out}" branch 0 Delta)
    string(JSON first${K} GET "${out}" branch 0 beta)
  endforeach()
  if(NOT D1 EQUAL 0.5 OR NOT D2 EQUAL 0.5)
    fail("first points at Delta = ${D1}, ${D2}; expected 0.5")
  endif()
  foreach(pair "start1;start2" "first1;first2")
    list(GET pair 0 a)
    list(GET pair 1 b)
    e12("${${a}}" ia)
    e12("${${b}}" ib)
    math(EXPR d "${ia} + ${ib} - 3141592653590")  # pi in units of 1e-12
    if(d LESS -1000 OR d GREATER 1000)
      fail("${a} + ${b} = ${${a}} + ${${b}} differs from pi by ${d}e-12")
    endif()
  endforeach()
elseif(CASE STREQUAL "curve_uz_none")
  # Swinging throughout: no UZ to start from. A failed run (exit 1) with the reason, and no file.
  execute_process(COMMAND ${CLI} continue --kind orbit --parameter Delta --min 0.3 --max 0.35 --direction forward
                  --lambda 5 --Delta 0.3 --C 0.04 --L 2 ${SCENE} --curve UZ --parameter2 lambda --min2 4 --max2 6
                  --csv ${WORK}/never.csv RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${err}" "--curve UZ: no located UZ point number 1: the one-parameter branch has 0 UZ point(s)" pos)
  if(NOT rc EQUAL 1 OR pos EQUAL -1)
    fail("expected exit 1 naming the missing UZ, got ${rc}: ${err}")
  endif()
  if(EXISTS ${WORK}/never.csv OR NOT out STREQUAL "")
    fail("output written without a curve: ${out}")
  endif()
  # Equilibrium branches carry no event: bad input, exit 2, naming the flag.
  expect_bad_input("curve = UZ is not available for --kind equilibrium" continue --curve UZ --parameter2 B)
else()
  fail("unknown case")
endif()
