# cmake -DBUILD_DIR=... -DCONSUMER_SOURCE=... -DWORK=... -DGENERATOR=... -DCXX=... [-DBUILD_TYPE=...]
#       [-DCXX_FLAGS=... -DEXE_LINKER_FLAGS=...] -P package_check.cmake
cmake_minimum_required(VERSION 3.22)
file(REMOVE_RECURSE "${WORK}")
set(prefix "${WORK}/prefix")

function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "${what} failed (${rc}):\n${out}\n${err}")
  endif()
  set(out "${out}" PARENT_SCOPE)
endfunction()

step("install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")
foreach(f lib/cmake/rbcstab/rbcstabConfig.cmake lib/cmake/rbcstab/rbcstabConfigVersion.cmake
          lib/cmake/rbcstab/rbcstabTargets.cmake include/rbcstab/model/parameters.hpp)
  if(NOT EXISTS "${prefix}/${f}")
    file(GLOB_RECURSE all RELATIVE "${prefix}" "${prefix}/*")
    message(FATAL_ERROR "install tree lacks ${f}; it has:\n${all}")
  endif()
endforeach()
if(EXISTS "${prefix}/include/rbcstab/integrate/detail")
  message(FATAL_ERROR "private detail/ headers were installed")
endif()
if(NOT BUILD_TYPE)
  set(BUILD_TYPE Release)
endif()
step("consumer configure" "${CMAKE_COMMAND}" -S "${CONSUMER_SOURCE}" -B "${WORK}/consumer" -G "${GENERATOR}"
     "-DCMAKE_CXX_COMPILER=${CXX}" "-DCMAKE_PREFIX_PATH=${prefix}" "-DCMAKE_BUILD_TYPE=${BUILD_TYPE}"
     "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_EXE_LINKER_FLAGS=${EXE_LINKER_FLAGS}")
step("consumer build" "${CMAKE_COMMAND}" --build "${WORK}/consumer")
step("consumer run" "${WORK}/consumer/rbcstab_consumer")
string(FIND "${out}" "rbcstab consumer ok" pos)
if(pos EQUAL -1)
  message(FATAL_ERROR "consumer output unexpected:\n${out}")
endif()
message(STATUS "${out}")
file(REMOVE_RECURSE "${WORK}")
