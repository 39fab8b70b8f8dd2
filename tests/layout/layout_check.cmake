# Usage: cmake -DROOT=<source dir> -DCASE=detail_includes|citations -P layout_check.cmake
cmake_minimum_required(VERSION 3.20)

set(violations "")

if(CASE STREQUAL "detail_includes")
  # Owner of a file: the module folder it lives in (src/rbcstab/<m>/ or tests/<m>/); apps/ and
  # benchmarks/ own no module, so they may include no detail header at all.
  file(GLOB_RECURSE files RELATIVE ${ROOT}
    ${ROOT}/src/*.hpp ${ROOT}/src/*.cpp ${ROOT}/apps/*.hpp ${ROOT}/apps/*.cpp
    ${ROOT}/tests/*.hpp ${ROOT}/tests/*.cpp ${ROOT}/benchmarks/*.hpp ${ROOT}/benchmarks/*.cpp)
  foreach(f IN LISTS files)
    set(owner "")
    if(f MATCHES "^src/rbcstab/([a-z_]+)/")
      set(owner ${CMAKE_MATCH_1})
    elseif(f MATCHES "^tests/([a-z_]+)/")
      set(owner ${CMAKE_MATCH_1})
    endif()
    file(STRINGS ${ROOT}/${f} includes REGEX "^[ \t]*#[ \t]*include[ \t]*[\"<]rbcstab/[a-z_]+/detail/")
    foreach(line IN LISTS includes)
      string(REGEX MATCH "rbcstab/([a-z_]+)/detail/[^\">]+" header "${line}")
      if(NOT CMAKE_MATCH_1 STREQUAL owner)
        list(APPEND violations "${f} includes ${header} (private to module ${CMAKE_MATCH_1})")
      endif()
    endforeach()
  endforeach()
elseif(CASE STREQUAL "citations")
  # Design notes (design/*.md) are not in the repository and issue numbers mean nothing to its reader:
  # say the fact, or cite docs/ or the paper's equation labels.
  file(GLOB_RECURSE files RELATIVE ${ROOT}
    ${ROOT}/src/* ${ROOT}/apps/* ${ROOT}/docs/*.md ${ROOT}/scenes/* ${ROOT}/tests/* ${ROOT}/benchmarks/* ${ROOT}/scripts/*)
  list(APPEND files README.md)
  list(FILTER files EXCLUDE REGEX "^tests/layout/|\\.(png|jpg|svg|pdf)$")
  foreach(f IN LISTS files)
    file(STRINGS ${ROOT}/${f} hits REGEX "design/[A-Za-z_]+\\.md|(^|[^a-z_/])model\\.md|[Ii]ssues? #?[0-9]")
    foreach(line IN LISTS hits)
      string(STRIP "${line}" line)
      list(APPEND violations "${f}: ${line}")
    endforeach()
  endforeach()
else()
  message(FATAL_ERROR "unknown case ${CASE}")
endif()

if(violations)
  list(LENGTH violations n)
  string(REPLACE ";" "\n  " text "${violations}")
  message(FATAL_ERROR "layout.${CASE}: ${n} violation(s):\n  ${text}")
endif()
message(STATUS "layout.${CASE}: ok")
