# What keeps the build within its budget (docs/building.md "Where the compile time goes").
#
# Unity builds: most of a file's compile time is spent instantiating the same templates of the heavy third-party
# headers (nlohmann/json, CLI11's validators, Eigen's products) that its neighbours instantiate too; compiling a
# module's files in batches of RBCSTAB_UNITY_BATCH does that once per batch. A batch of 8 keeps the rebuild after
# touching one library file under a minute. Names private to a file must therefore be unique within its module
# (anonymous namespaces are shared by the batch); a file that cannot be merged sets SKIP_UNITY_BUILD_INCLUSION.
# RBCSTAB_UNITY_BATCH=0 compiles each module as one batch (and drops the modules' own batch sizes): the 'asan'
# preset does, since CI builds it once and cold, where the fewest instantiations matter and no rebuild does.
option(RBCSTAB_UNITY "Compile each target's sources in unity batches" ON)
set(RBCSTAB_UNITY_BATCH 8 CACHE STRING "Sources per unity batch")
if(RBCSTAB_UNITY)
  set(CMAKE_UNITY_BUILD ON)
  set(CMAKE_UNITY_BUILD_BATCH_SIZE ${RBCSTAB_UNITY_BATCH})
endif()

# Precompiled headers: the third-party headers that most files
# include (Eigen, nlohmann/json, the standard library; GoogleTest, CLI11 or Google Benchmark by family) are parsed
# once per family into a .gch that every target of the family reuses. The Python module is one unity batch: a PCH
# of its own would cost more than it saves.
#
# GCC refuses a PCH made with other -fpic/-fpie settings, or without __OPTIMIZE__ when the user has it: every
# object is compiled -fPIC (static libraries need it for the Python module anyway), and a family's donor is
# compiled with the build's own flags. A PCH that does not fit is a -Winvalid-pch warning, an error under -Werror,
# never a silent fallback. RBCSTAB_PCH=OFF builds without them (and so checks that each file includes what it
# uses; the tidy preset does).
option(RBCSTAB_PCH "Precompile the heavy third-party headers, one PCH per target family" ON)
if(RBCSTAB_FUZZ)
  set(RBCSTAB_PCH OFF)  # clang's libFuzzer build (scripts/fuzz.sh) builds rarely and from scratch
endif()
if(RBCSTAB_PCH)
  add_compile_options(-fPIC)
endif()

set(RBCSTAB_PCH_COMMON
  <algorithm> <array> <cmath> <complex> <cstddef> <filesystem> <fstream> <functional> <iomanip> <iostream>
  <limits> <map> <memory> <numbers> <optional> <set> <span> <sstream> <stdexcept> <string> <string_view>
  <utility> <vector> <Eigen/Dense> <nlohmann/json.hpp>)

# rbcstab_precompile(TARGET FAMILY): TARGET reuses the PCH of FAMILY (lib, test, cli, bench).
function(rbcstab_precompile target family)
  if(NOT RBCSTAB_PCH)
    return()
  endif()
  set(donor rbcstab_pch_${family})
  if(NOT TARGET ${donor})
    set(headers ${RBCSTAB_PCH_COMMON})
    set(deps Eigen3::Eigen nlohmann_json::nlohmann_json)
    if(family STREQUAL "test")
      list(APPEND headers <gtest/gtest.h>)
      list(APPEND deps GTest::gtest)
    elseif(family STREQUAL "cli")
      list(APPEND headers <CLI/CLI.hpp>)
      list(APPEND deps CLI11::CLI11)
    elseif(family STREQUAL "bench")
      list(APPEND headers <benchmark/benchmark.h>)
      list(APPEND deps benchmark::benchmark)
    elseif(NOT family STREQUAL "lib")
      message(FATAL_ERROR "rbcstab_precompile: unknown family '${family}'")
    endif()
    set(source ${PROJECT_BINARY_DIR}/pch/${family}.cpp)
    file(CONFIGURE OUTPUT ${source} CONTENT "// The donor of the '${family}' precompiled header (cmake/RbcstabCompileCost.cmake).\n")
    add_library(${donor} OBJECT ${source})
    target_link_libraries(${donor} PRIVATE ${deps} rbcstab_warnings)
    target_compile_features(${donor} PRIVATE cxx_std_20)
    target_precompile_headers(${donor} PRIVATE ${headers})
  endif()
  target_precompile_headers(${target} REUSE_FROM ${donor})
endfunction()

# ccache when installed (CCACHE_DISABLE=1 for cold figures, as scripts/build_budget.sh measures); the sloppiness
# lets it cache the objects that use a precompiled header.
option(RBCSTAB_CCACHE "Compile through ccache when it is installed" ON)
find_program(RBCSTAB_CCACHE_PROGRAM ccache)
if(RBCSTAB_CCACHE AND RBCSTAB_CCACHE_PROGRAM AND NOT CMAKE_CXX_COMPILER_LAUNCHER)
  set(CMAKE_CXX_COMPILER_LAUNCHER ${CMAKE_COMMAND} -E env
      CCACHE_SLOPPINESS=pch_defines,time_macros,include_file_mtime,include_file_ctime ${RBCSTAB_CCACHE_PROGRAM})
endif()
