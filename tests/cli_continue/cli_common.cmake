# Helpers shared by the `rbcstab continue` CLI checks (cli_*_check.cmake).
function(fail msg)
  message(FATAL_ERROR "cli.continue.${CASE}: ${msg}")
endfunction()

# Every listed top-level key must exist.
function(require_keys json)
  foreach(key IN LISTS ARGN)
    string(JSON type ERROR_VARIABLE err TYPE "${json}" ${key})
    if(err)
      fail("missing key '${key}'")
    endif()
  endforeach()
endfunction()

# One JSON path (its elements as separate arguments) must exist.
function(require_path json)
  string(JSON type ERROR_VARIABLE err TYPE "${json}" ${ARGN})
  if(err)
    fail("missing '${ARGN}'")
  endif()
endfunction()

# `rbcstab <args> --csv WORK/never.csv --save WORK/never.json` must exit 2, name `fragment` on stderr and
# write neither file.
function(expect_bad_input fragment)
  execute_process(COMMAND ${CLI} ${ARGN} --csv ${WORK}/never.csv --save ${WORK}/never.json
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 2)
    fail("expected exit 2, got ${rc}: ${err}")
  endif()
  string(FIND "${err}" "${fragment}" pos)
  if(pos EQUAL -1)
    fail("message does not name '${fragment}': ${err}")
  endif()
  if(EXISTS ${WORK}/never.csv OR EXISTS ${WORK}/never.json)
    fail("a file was written on bad input")
  endif()
endfunction()

# A plain decimal in [0, 1e6) as an integer in units of 1e-12 (truncated; CMake has no floating-point
# arithmetic, and its integers are 64-bit).
function(e12 value out)
  if(NOT value MATCHES "^([0-9]+)(\\.([0-9]+))?$")
    fail("not a plain decimal: ${value}")
  endif()
  set(int "${CMAKE_MATCH_1}")
  string(SUBSTRING "${CMAKE_MATCH_3}000000000000" 0 12 digits)
  string(REGEX REPLACE "^0+" "" digits "${digits}")
  if(digits STREQUAL "")
    set(digits 0)
  endif()
  math(EXPR v "${int} * 1000000000000 + ${digits}")
  set(${out} ${v} PARENT_SCOPE)
endfunction()

# A JSON number in [0, 1) written as 0.ddd... (no exponent) -> integer units of 1e-12 (truncated), so
# that two runs' values can be subtracted with math(EXPR) (CMake has no floating-point arithmetic).
function(to_pico value out)
  if(NOT value MATCHES "^0\\.[0-9]+$")
    fail("to_pico: ${value} is not of the form 0.ddd")
  endif()
  e12("${value}" v)
  set(${out} ${v} PARENT_SCOPE)
endfunction()

# |a - b| <= tol_e12 * 1e-12 for plain decimals.
function(expect_close what a b tol_e12)
  e12("${a}" ia)
  e12("${b}" ib)
  math(EXPR d "${ia} - ${ib}")
  if(d LESS 0)
    math(EXPR d "-${d}")
  endif()
  if(d GREATER ${tol_e12})
    fail("${what}: ${a} vs ${b} differ by ${d}e-12 > ${tol_e12}e-12")
  endif()
endfunction()

# A plain decimal in (-1e6, 1e6) as an integer in units of 1e-12 (truncated; CMake has no floating-point
# arithmetic, and its integers are 64-bit).
function(e12 value out)
  if(NOT value MATCHES "^(-?)([0-9]+)(\\.([0-9]+))?$")
    fail("not a plain decimal: ${value}")
  endif()
  set(sign "${CMAKE_MATCH_1}")
  set(int "${CMAKE_MATCH_2}")
  string(SUBSTRING "${CMAKE_MATCH_4}000000000000" 0 12 digits)
  string(REGEX REPLACE "^0+" "" digits "${digits}")
  if(digits STREQUAL "")
    set(digits 0)
  endif()
  math(EXPR v "${sign}(${int} * 1000000000000 + ${digits})")
  set(${out} ${v} PARENT_SCOPE)
endfunction()
