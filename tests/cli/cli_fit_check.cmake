# cmake -DCLI=<rbcstab> -DCASE=<report|refused|interrupted> -DWORK=<scratch folder> -P cli_fit_check.cmake
# `rbcstab fit --report DIR`: the page's folder written whole (report), an existing folder refused before the fit
# runs, exit 2 naming the output and --overwrite, the folder left as it was (refused), and Ctrl-C (interrupted). The data: four angles the
# model makes at lambda = 5, Delta = 0.1, Delta0 = 0.05 (data/fit_synthetic.csv's first rows), lambda fitted alone.
cmake_minimum_required(VERSION 3.22)
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
include(${CMAKE_CURRENT_LIST_DIR}/cli_run.cmake)

file(WRITE "${WORK}/obs.csv" "# four rows of data/fit_synthetic.csv\n"
  "observable,shear_rate[1/s],viscosity[mPa s],value,uncertainty,unit\n"
  "inclination_angle,150,1,25.11,0.5,deg\n"
  "swinging_amplitude,150,1,20.31,0.5,deg\n"
  "inclination_angle,600,1,25.87,0.5,deg\n"
  "swinging_amplitude,600,1,4.53,0.5,deg\n")
set(FIT fit --data obs.csv --free lambda --fixed Delta=0.1,Delta0=0.05 --starts 1 --profiles --profile-points 2)

if(CASE STREQUAL "report")
  run_cli(${FIT} --report page --json)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "exit code ${rc}\nstderr: ${err}\nstdout: ${out}")
  endif()
  string(JSON folder GET "${out}" report)
  string(JSON status GET "${out}" status)
  if(NOT status STREQUAL "converged" OR NOT folder STREQUAL "${WORK}/page")
    message(FATAL_ERROR "status ${status}, report ${folder}")
  endif()
  foreach(f index.html README.md fit.json parameters.csv correlation.csv residuals.csv observations.csv fig_fit.png
          fig_profile_lambda.png drawn.json)
    if(NOT EXISTS "${WORK}/page/${f}")
      message(FATAL_ERROR "missing page/${f}")
    endif()
  endforeach()
  file(READ "${WORK}/page/README.md" readme)
  expect_contains("${readme}" "Status: converged" "README.md")
  expect_contains("${readme}" "| lambda | 5." "README.md")
elseif(CASE STREQUAL "refused")
  file(MAKE_DIRECTORY "${WORK}/mine")
  file(WRITE "${WORK}/mine/notes.txt" "not a report\n")
  run_cli(${FIT} --report mine)
  expect_refusal("fit --report mine" "output:" "exists" "--overwrite")
  if(NOT out STREQUAL "")
    message(FATAL_ERROR "the fit ran before the refusal:\n${out}")
  endif()
  file(GLOB left RELATIVE "${WORK}/mine" "${WORK}/mine/*")
  if(NOT left STREQUAL "notes.txt")
    message(FATAL_ERROR "the refused folder changed: ${left}")
  endif()
elseif(CASE STREQUAL "interrupted")
  # Ctrl-C (SIGINT after 3 s, by coreutils' timeout) during 64 starts: the result printed and marked, a message on
  # stderr, exit 1, no page.
  find_program(TIMEOUT timeout REQUIRED)
  execute_process(COMMAND ${TIMEOUT} --preserve-status -s INT 3 "${CLI}" fit --data obs.csv --free mu,lambda
                          --fixed Delta=0.1,Delta0=0.05 --starts 64 --report page
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err WORKING_DIRECTORY "${WORK}" TIMEOUT 100)
  if(NOT rc EQUAL 1)
    message(FATAL_ERROR "exit code ${rc} (expected 1)\nstderr: ${err}\nstdout: ${out}")
  endif()
  expect_contains("${out}" "fit: interrupted" "stdout")
  expect_contains("${err}" "stopped by a signal: interrupted after" "stderr")
  expect_contains("${err}" "no report written" "stderr")
  if(EXISTS "${WORK}/page")
    message(FATAL_ERROR "an interrupted fit wrote a page")
  endif()
else()
  message(FATAL_ERROR "unknown CASE ${CASE}")
endif()
