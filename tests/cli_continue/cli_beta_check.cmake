# rbcstab continue with beta (the rest shape's orientation) free, and --curve NS: the orbit branch in
# beta against an independent path (`rbcstab simulate` of the reduced model at that beta, relaxed and
# sampled at t = 2 pi k), the modal orbit in beta, the NS curve's clear refusal when the branch has no
# NS point, and bad input refused with exit code 2 naming the flag.
# Usage: cmake -DCLI=<rbcstab> -DCASE=<case> -DWORK=<dir> -P cli_beta_check.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake)

# Fig. 2's in-plane scene at Delta = 1 (tumbling at beta = pi/2), the reduced level.
set(FIG2 --lambda 5 --Delta 1 --Delta0 0.01 --B 2 --C 0.04 --L 2)

file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
if(CASE STREQUAL "beta_orbit_json")
  # From the in-plane tumbling orbit (beta = pi/2) down to beta = 0.3 (swinging), through the
  # swinging <-> tumbling UZ (beta = 0.6477, tests/continuation/beta_test.cpp, where it is checked
  # against a continuation in Delta).
  execute_process(COMMAND ${CLI} continue --kind orbit --parameter beta --min 0.3 --direction backward ${FIG2}
                  --csv ${WORK}/beta.csv --json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("exit ${rc}: ${err}")
  endif()
  string(JSON free GET "${out}" free_parameter)
  if(NOT free STREQUAL "beta")
    fail("free_parameter = ${free}")
  endif()
  foreach(key beta r Psi winding kind multipliers)
    require_path("${out}" branch 0 ${key})
  endforeach()
  string(JSON nsp LENGTH "${out}" special_points)
  string(JSON name GET "${out}" special_points 0 name)
  string(JSON b GET "${out}" special_points 0 beta)
  if(NOT nsp EQUAL 1 OR NOT name STREQUAL "swing_tumble" OR b LESS 0.6 OR b GREATER 0.7)
    fail("expected one swing_tumble UZ near beta = 0.65, got ${nsp} points, ${name} at ${b}")
  endif()
  file(STRINGS ${WORK}/beta.csv lines)
  list(GET lines 0 header)
  if(NOT header MATCHES "^beta,r,Psi,")
    fail("CSV header: ${header}")
  endif()
  # The branch ends on the bound beta = 0.3 exactly; its orbit at t = 0 (r, Psi) ...
  list(GET lines -1 row)
  string(REPLACE "," ";" row "${row}")
  list(GET row 0 beta_end)
  list(GET row 1 r_branch)
  list(GET row 2 Psi_branch)
  list(GET row 8 kind)
  if(NOT beta_end EQUAL 0.3 OR NOT kind STREQUAL "swinging")
    fail("last row at beta = ${beta_end} (${kind}), expected 0.3 (swinging)")
  endif()
  # ... is where the reduced model relaxes to at t = 2 pi k (here k = 50; the multipliers ~0.15 damp
  # the transient by 0.15^50). 1e-8: the simulation's rtol 1e-11 over 50 periods and the orbit's
  # rtol 1e-12 shooting (measured agreement ~1e-14).
  execute_process(COMMAND ${CLI} simulate ${FIG2} --beta 0.3 --delta 0 --model reduced --T 314.15926535897932
                  --dt 6.2831853071795865 --rtol 1e-11 --atol 1e-13 --trajectory ${WORK}/sim.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE sout ERROR_VARIABLE serr)
  if(NOT rc EQUAL 0)
    fail("simulate: exit ${rc}: ${serr}")
  endif()
  file(STRINGS ${WORK}/sim.csv slines)
  list(GET slines 0 sheader)
  if(NOT sheader STREQUAL "t,Delta_2,sigma,r,Psi,integrated")
    fail("simulate trajectory header: ${sheader}")
  endif()
  list(GET slines -1 srow)
  string(REPLACE "," ";" srow "${srow}")
  list(GET srow 0 t_end)
  list(GET srow 3 r_sim)
  list(GET srow 4 Psi_sim)
  if(t_end LESS 314.159 OR t_end GREATER 314.16)
    fail("simulation ends at t = ${t_end}, expected 100 pi")
  endif()
  expect_close("r at beta = 0.3" "${r_branch}" "${r_sim}" 10000)
  expect_close("Psi at beta = 0.3" "${Psi_branch}" "${Psi_sim}" 10000)
elseif(CASE STREQUAL "beta_modal_orbit_json")
  # The in-plane post-instability modal orbit (as modal_orbit_json) tilted a little: beta from pi/2 down.
  execute_process(COMMAND ${CLI} continue --kind modal-orbit --parameter beta --min 1.4 --direction backward
                  --lambda 5 --Delta 1 --Delta0 0.01 --B 2 --C 0.04 --L 5 --delta 1e-3 --relax-T 600 --max-points 3
                  --json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("exit ${rc}: ${err}")
  endif()
  string(JSON free GET "${out}" free_parameter)
  foreach(key beta r Psi sigma Delta_2 Delta_3 stable multipliers)
    require_path("${out}" branch 2 ${key})
  endforeach()
  string(JSON b0 GET "${out}" branch 0 beta)
  string(JSON b2 GET "${out}" branch 2 beta)
  string(JSON D3 GET "${out}" branch 2 Delta_3)
  if(NOT free STREQUAL "beta" OR NOT b0 EQUAL 1.5707963267948966 OR NOT b2 LESS b0 OR D3 LESS 0.5)
    fail("free ${free}, beta ${b0} -> ${b2}, Delta_3 = ${D3}: expected beta decreasing from pi/2, Delta_3 > 0.5")
  endif()
elseif(CASE STREQUAL "curve_ns_none")
  # No NS point on the in-plane orbit branch (its multipliers stay inside the unit circle,
  # docs/continuation.md): the NS curve is refused with exit 1 and the reason, no file written.
  execute_process(COMMAND ${CLI} continue --kind orbit --parameter Delta --min 0.3 --max 0.45 --Delta 0.3 --lambda 5
                  --Delta0 0.01 --B 2 --C 0.04 --L 2 --curve NS --parameter2 C --csv ${WORK}/ns.csv
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${err}" "no located NS point" pos)
  if(NOT rc EQUAL 1 OR pos EQUAL -1)
    fail("expected exit 1 with 'no located NS point', got ${rc}: ${err}")
  endif()
  if(EXISTS ${WORK}/ns.csv)
    fail("a curve file was written without a curve")
  endif()
elseif(CASE STREQUAL "curve_modal_orbit_none")
  # --kind modal-orbit --curve runs the one-parameter modal orbit branch and then refuses the curve:
  # the post-instability orbit has no located NS point in lambda in [4.9, 5.1] (exit 1, the reason).
  execute_process(COMMAND ${CLI} continue --kind modal-orbit --parameter lambda --min 4.9 --max 5.1 --lambda 5
                  --Delta 1 --Delta0 0.01 --B 2 --C 0.04 --L 5 --delta 1e-3 --relax-T 600 --max-points 3
                  --curve NS --parameter2 beta RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  string(FIND "${err}" "no located NS point" pos)
  if(NOT rc EQUAL 1 OR pos EQUAL -1)
    fail("expected exit 1 with 'no located NS point', got ${rc}: ${err}")
  endif()
elseif(CASE STREQUAL "curve_modal_orbit_bp")
  # The modal post-instability orbit (L = 4: a_3 carries area) continued in C has a BP where the
  # l = 4 multiplier crosses 1. Closed form (docs/continuation.md, modal orbits): a periodic a_3 != 0
  # needs int Upsilon_3 dt = 0, i.e. the period mean of sigma is sigma_3^c, and the zero-amplitude
  # l = 4 direction has the multiplier exp(2 pi Upsilon_4(sigma_3^c)); Upsilon_l ~ Pi_l + sigma + 4 alpha/Pi_l
  # vanishes at sigma_3^c = -(12 + alpha/3) iff alpha = B/C = 3 Pi_4 = 60: the BP curve is C = B/60,
  # whatever lambda, Delta. Its BP curve in (C, B) from B = 2 (C = 1/30) over B in [1.5, 2.5].
  execute_process(COMMAND ${CLI} continue --kind modal-orbit --parameter C --min 0.025 --max 0.04 --lambda 5
                  --Delta 1 --Delta0 0.01 --B 2 --C 0.04 --L 4 --delta 1e-3 --relax-T 600 --segments 2 --curve BP
                  --parameter2 B --min2 1.5 --max2 2.5 --csv ${WORK}/bp.csv --json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("exit ${rc}: ${err}")
  endif()
  string(JSON type GET "${out}" curve type)
  string(JSON level GET "${out}" level)
  string(JSON stable GET "${out}" branch 0 stable)
  if(NOT type STREQUAL "BP" OR NOT level STREQUAL "modal" OR NOT stable)
    fail("curve ${type}, level ${level}, stable ${stable}: expected a BP curve of stable modal orbits")
  endif()
  file(STRINGS ${WORK}/bp.csv lines)
  list(GET lines 0 header)
  if(NOT header STREQUAL "C,B,r,Psi,stable,n_unstable,label,type")
    fail("CSV header: ${header}")
  endif()
  list(LENGTH lines n)
  if(n LESS 8)
    fail("only ${n} CSV lines")
  endif()
  list(REMOVE_AT lines 0)
  set(first "")
  foreach(line IN LISTS lines)
    string(REPLACE "," ";" row "${line}")
    list(GET row 0 C)
    list(GET row 1 B)
    if(first STREQUAL "")
      set(first "${B}")
    endif()
    set(last "${B}")
    # 60 C = B to 1e-9 (the curve's Newton tolerance 1e-12 and the shooting's rtol 1e-12 give ~1e-10).
    e12("${C}" iC)
    e12("${B}" iB)
    math(EXPR d "60 * ${iC} - ${iB}")
    if(d LESS -1000 OR d GREATER 1000)
      fail("point (C = ${C}, B = ${B}): 60 C - B = ${d}e-12, expected 0")
    endif()
  endforeach()
  if(NOT first EQUAL 1.5 OR NOT last EQUAL 2.5)
    fail("curve spans B = ${first} .. ${last}, expected 1.5 .. 2.5")
  endif()
elseif(CASE STREQUAL "curve_modal_orbit_zbp")
  # The in-plane ELLIPSOIDAL modal orbit (lambda = 1, L = 4, a_3 = a_4 = 0) continued in C loses
  # stability to l = 3 at a BP; --curve BP then uses the Z2-reduced system (reduced shooting + sigma_bar =
  # sigma_3^c) and reports sigma_bar and mode. Independent path: a one-parameter modal-orbit run at
  # B = 1.5 (modal shooting, the engine's BP test on the modal multipliers) locates its BP at the C of the
  # curve's B = 1.5 row, to 1e-9 (both solve to 1e-12; measured ~1e-15).
  set(ELL --kind modal-orbit --parameter C --min 0.05 --max 0.08 --lambda 1 --Delta 1 --Delta0 0.01 --C 0.07 --L 4
      --delta 0 --relax-T 600 --segments 2 --direction backward)
  execute_process(COMMAND ${CLI} continue ${ELL} --B 2 --curve BP --parameter2 B --min2 1.5 --max2 2.5
                  --csv ${WORK}/zbp.csv --json RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("exit ${rc}: ${err}")
  endif()
  foreach(key C B r Psi sigma_bar mode multipliers stable)
    require_path("${out}" branch 0 ${key})
  endforeach()
  string(JSON mode GET "${out}" branch 0 mode)
  if(NOT mode EQUAL 3)
    fail("critical mode ${mode}, expected 3")
  endif()
  file(STRINGS ${WORK}/zbp.csv lines)
  list(GET lines 0 header)
  if(NOT header STREQUAL "C,B,r,Psi,sigma_bar,mode,stable,n_unstable,label,type")
    fail("CSV header: ${header}")
  endif()
  list(GET lines 1 row)
  string(REPLACE "," ";" row "${row}")
  list(GET row 0 C_curve)
  list(GET row 1 B_first)
  if(NOT B_first EQUAL 1.5)
    fail("first row at B = ${B_first}, expected 1.5")
  endif()
  execute_process(COMMAND ${CLI} continue ${ELL} --B 1.5 --json RESULT_VARIABLE rc OUTPUT_VARIABLE one ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    fail("one-parameter run at B = 1.5: exit ${rc}: ${err}")
  endif()
  string(JSON type GET "${one}" special_points 0 type)
  string(JSON C_one GET "${one}" special_points 0 C)
  if(NOT type STREQUAL "BP")
    fail("one-parameter run at B = 1.5: first special point ${type}, expected BP")
  endif()
  expect_close("C of the BP at B = 1.5 (curve vs one-parameter modal run)" "${C_curve}" "${C_one}" 1000)
elseif(CASE STREQUAL "beta_bad_input")
  expect_bad_input("beta" continue --kind orbit --parameter beta --beta 4 ${FIG2})
  expect_bad_input("curve = NS" continue --kind equilibrium --parameter lambda --curve NS --parameter2 B)
  expect_bad_input("curve = LP" continue --kind modal-orbit --parameter lambda --curve LP --parameter2 B)
  expect_bad_input("parameter2" continue --kind orbit --parameter Delta --curve NS)
  expect_bad_input("parameter2 = beta" continue --kind orbit --parameter beta --curve NS --parameter2 beta)
  # A range that excludes the scene's own value (beta = pi/2) names --min/--max and the start value.
  expect_bad_input("outside [--min, --max] = [0, 1]" continue --kind orbit --parameter beta --min 0 --max 1 ${FIG2})
else()
  fail("unknown case")
endif()
