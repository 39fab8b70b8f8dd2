# `rbcstab continue --diagram` stopped mid-run by a signal (CASE diagram_sigint: SIGINT, Ctrl-C; diagram_sigkill:
# SIGKILL, nothing runs after it) once 3 of its 9 branches are journaled, then run again with the same command:
# it resumes from d.json.journal, and the tree and all branch files equal an uninterrupted run's byte for byte
# (cmp); the journal holds each branch once (nothing journaled was continued again).
# Usage: cmake -DCLI=<rbcstab> -DCASE=<case> -DWORK=<dir> -P cli_diagram_resume_check.cmake
include(${CMAKE_CURRENT_LIST_DIR}/cli_common.cmake)

# The walk-through's diagram (cli_restart_check.cmake's "diagram") with steps of 0.001: ~0.1 s a branch, so that
# polling the journal every 5 ms stops it midway.
set(ARGS continue --kind modal --parameter C --min 0.01 --max 0.1 --lambda 1 --B 1 --L 6 --diagram 1 --step 0.001
    --max-step 0.001)
if(CASE STREQUAL "diagram_sigint")
  set(SIG INT)
elseif(CASE STREQUAL "diagram_sigkill")
  set(SIG KILL)
else()
  fail("unknown case")
endif()
file(REMOVE_RECURSE ${WORK})
file(MAKE_DIRECTORY ${WORK})
string(JOIN " " command ${CLI} ${ARGS})

execute_process(COMMAND ${CLI} ${ARGS} --no-journal --save ${WORK}/clean.json RESULT_VARIABLE rc OUTPUT_QUIET
                ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  fail("the uninterrupted run: exit ${rc}: ${err}")
endif()

# Records of branches ("B <hash> <branch> ...") in the journal.
set(records "cat ${WORK}/d.json.journal 2>/dev/null | grep -c '^B '")
execute_process(COMMAND sh -c "${command} --save ${WORK}/d.json >/dev/null 2>${WORK}/err1.txt & pid=$!
n=0
while [ \"$(${records})\" -lt 3 ] && [ $n -lt 4000 ]; do sleep 0.005; n=$((n + 1)); done
kill -${SIG} $pid
wait $pid
echo $?" OUTPUT_VARIABLE rc)
execute_process(COMMAND sh -c "${records}" OUTPUT_VARIABLE before)
string(STRIP "${rc}" rc)
string(STRIP "${before}" before)
if(rc EQUAL 0 OR before GREATER_EQUAL 9)
  fail("the run finished (exit ${rc}, ${before} branches journaled) before it could be stopped")
endif()
if(before LESS 3)
  fail("${before} branches journaled before the stop")
endif()

execute_process(COMMAND ${CLI} ${ARGS} --save ${WORK}/d.json RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT rc EQUAL 0)
  fail("the resumed run: exit ${rc}: ${err}")
endif()
execute_process(COMMAND sh -c "${records}" OUTPUT_VARIABLE after)
string(STRIP "${after}" after)
if(NOT after EQUAL 9)
  fail("${after} records after resuming (expected 9: one per branch, none continued twice)")
endif()

function(same a b)
  execute_process(COMMAND cmp -s ${a} ${b} RESULT_VARIABLE differ)
  set(same ${differ} PARENT_SCOPE)
endfunction()
same(${WORK}/d.json ${WORK}/clean.json)
if(same)
  fail("the resumed tree d.json differs from the uninterrupted run's")
endif()
foreach(k RANGE 1 9)
  same(${WORK}/d.b${k}.json ${WORK}/clean.b${k}.json)
  if(same)
    fail("the resumed branch file d.b${k}.json differs from the uninterrupted run's")
  endif()
endforeach()
# The comparison sees a changed branch: two different branches' files differ.
same(${WORK}/d.b2.json ${WORK}/clean.b3.json)
if(NOT same)
  fail("cmp does not tell branch 2 from branch 3")
endif()
