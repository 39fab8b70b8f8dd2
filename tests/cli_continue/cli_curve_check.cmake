# rbcstab continue --curve end to end: two-parameter curves checked against an independent oracle run
# through `rbcstab thresholds` (analysis/, not continuation/) at points of the curve, the JSON/CSV
# keys, and bad input refused with exit code 2 naming the flag.
# Usage: cmake -DCLI=<rbcstab> -DCASE=<case> -DWORK=<dir> -P cli_curve_check.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake)

# thresholds --json at (lambda, Delta, Delta0, B, C) of the modal scene: sets OUT_JSON in the caller.
macro(thresholds)
  execute_process(COMMAND ${CLI} thresholds --L 6 ${ARGN} --json RESULT_VARIABLE trc OUTPUT_VARIABLE OUT_JSON
                  ERROR_VARIABLE terr)
  if(NOT trc EQUAL 0)
    fail("thresholds ${ARGN}: exit ${trc}: ${terr}")
  endif()
endmacro()

# The modal scene of cli_continue_check.cmake (lambda = 1, B = 1, Delta = 1, Delta0 = 0.01, L = 6): the
# ellipsoidal branch loses stability to l = 3 at C = 0.036169 (a BP, Upsilon_3(sigma) = 0).
set(MODAL_ARGS continue --kind modal --parameter C --min 0.015 --max 0.08 --direction backward --lambda 1 --B 1
    --C 0.08 --Delta 1 --Delta0 0.01 --L 6)
# The vesicle limit (S = inf: Delta0 = 0, C = inf) on the tank-treading branch r = 1 (Lambda = 0.85 at
# lambda = 5, Delta = 0.2), which folds at Lambda = 1.
set(VESICLE_ARGS continue --parameter lambda --min 0 --max 20 --lambda 5 --Delta 0.2 --Delta0 0 --C inf)

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
if(CASE STREQUAL "curve_modal_bp")
  # The BP curve in (C, B): every point is on the ellipsoidal branch with sigma = sigma_3^c(B/C), i.e.
  # the l = 3 growth rate Upsilon_3(sigma) of `thresholds` (exact steady state) vanishes there.
  execute_process(COMMAND ${CLI} ${MODAL_ARGS} --curve BP --parameter2 B --min2 0.5 --max2 2 --json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("exit ${rc}: ${err}")
  endif()
  foreach(key C B r Psi sigma Delta_2 Delta_3 stable eigenvalues)
    require_path("${out}" branch 0 ${key})
  endforeach()
  require_path("${out}" special_points)
  string(JSON type GET "${out}" curve type)
  string(JSON st GET "${out}" curve start type)
  string(JSON C0 GET "${out}" curve start C)
  string(JSON B0 GET "${out}" curve start B)
  if(NOT type STREQUAL "BP" OR NOT st STREQUAL "BP" OR C0 LESS 0.036168 OR C0 GREATER 0.036170 OR NOT B0 EQUAL 1)
    fail("curve ${type} from ${st} at C = ${C0}, B = ${B0}; expected BP from BP at C = 0.036169, B = 1")
  endif()
  string(JSON n LENGTH "${out}" branch)
  if(n LESS 10)
    fail("only ${n} curve points")
  endif()
  string(JSON Bfirst GET "${out}" branch 0 B)
  math(EXPR last "${n} - 1")
  string(JSON Blast GET "${out}" branch ${last} B)
  if(NOT Bfirst EQUAL 0.5 OR NOT Blast EQUAL 2)
    fail("curve spans B = ${Bfirst} .. ${Blast}, expected 0.5 .. 2 (the bounds)")
  endif()
  math(EXPR mid "${n} / 2")
  foreach(i 0 ${mid} ${last})
    string(JSON C GET "${out}" branch ${i} C)
    string(JSON B GET "${out}" branch ${i} B)
    string(JSON D3 GET "${out}" branch ${i} Delta_3)
    thresholds(--lambda 1 --Delta 1 --Delta0 0.01 --B ${B} --C ${C})
    string(JSON rate GET "${OUT_JSON}" asymptotic rate 3)
    # 1e-7: C and B are printed with 17 digits, sigma is then recomputed from the exact steady state;
    # the rate's slope in C is ~ B / (3 C^2) ~ 1e3, so rounding alone gives ~1e-13 and the curve's
    # Newton tolerance 1e-12 gives ~1e-9.
    if(rate LESS -1e-7 OR rate GREATER 1e-7 OR NOT D3 EQUAL 0)
      fail("point ${i} (C = ${C}, B = ${B}): Upsilon_3 = ${rate}, Delta_3 = ${D3}; expected 0 and 0")
    endif()
  endforeach()
elseif(CASE STREQUAL "curve_vesicle_lp")
  # The LP curve in (lambda, Delta): Lambda(lambda, Delta) = 1 (closed form), r = 1, Psi = 0.
  execute_process(COMMAND ${CLI} ${VESICLE_ARGS} --curve LP --parameter2 Delta --min2 0.1 --max2 2
                  --csv ${WORK}/lp.csv --json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("exit ${rc}: ${err}")
  endif()
  file(STRINGS ${WORK}/lp.csv lines)
  list(GET lines 0 header)
  if(NOT header STREQUAL "lambda,Delta,r,Psi,stable,n_unstable,label,type")
    fail("header: ${header}")
  endif()
  string(JSON type GET "${out}" curve type)
  string(JSON st GET "${out}" curve start type)
  if(NOT type STREQUAL "LP" OR NOT st STREQUAL "LP")
    fail("curve ${type} from ${st}")
  endif()
  string(JSON n LENGTH "${out}" branch)
  math(EXPR last "${n} - 1")
  math(EXPR mid "${n} / 2")
  foreach(i 0 ${mid} ${last})
    string(JSON lam GET "${out}" branch ${i} lambda)
    string(JSON D GET "${out}" branch ${i} Delta)
    string(JSON r GET "${out}" branch ${i} r)
    thresholds(--lambda ${lam} --Delta ${D} --Delta0 0 --C inf)
    string(JSON L GET "${OUT_JSON}" Lambda)
    # 1e-9: the curve is converged to 1e-12 and Lambda is recomputed from 17-digit lambda, Delta.
    if(L LESS 0.999999999 OR L GREATER 1.000000001 OR r LESS 0.9999999999)
      fail("point ${i} (lambda = ${lam}, Delta = ${D}): Lambda = ${L}, r = ${r}; expected 1 and 1")
    endif()
  endforeach()
elseif(CASE STREQUAL "curve_bad_parameter2")
  expect_bad_input("parameter2 = Delta" continue --parameter Lambda --curve LP --parameter2 Delta)
  execute_process(COMMAND ${CLI} continue --curve LPC --parameter2 B RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${err}" "curve = LPC" pos)
  if(NOT rc EQUAL 2 OR pos EQUAL -1)
    fail("--kind equilibrium --curve LPC: exit ${rc}, ${err}")
  endif()
else()
  fail("unknown case")
endif()
