# run_cli(<args>): runs the CLI in WORK; sets rc, out (stdout) and err (stderr) in the caller.
# expect_contains(text fragment what): fails unless text contains fragment.
# expect_refusal(what fragments...): after run_cli, exit code 2 and every fragment in stderr.
# Shared by the CMake -P drivers of this folder.
function(run_cli)
  execute_process(COMMAND "${CLI}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err
                  WORKING_DIRECTORY "${WORK}" TIMEOUT 100)
  set(rc "${rc}" PARENT_SCOPE)
  set(out "${out}" PARENT_SCOPE)
  set(err "${err}" PARENT_SCOPE)
endfunction()

function(expect_contains text fragment what)
  string(FIND "${text}" "${fragment}" pos)
  if(pos EQUAL -1)
    message(FATAL_ERROR "${what}: expected '${fragment}' in:\n${text}")
  endif()
endfunction()

function(expect_refusal what)
  if(NOT rc EQUAL 2)
    message(FATAL_ERROR "exit code ${rc} (expected 2) for ${what}\nstderr: ${err}")
  endif()
  foreach(n IN LISTS ARGN)
    expect_contains("${err}" "${n}" "stderr for ${what}")
  endforeach()
endfunction()
