# RBCSTAB_FUZZ=ON: every target of the build is compiled for libFuzzer (coverage instrumentation, fuzzer-no-link)
# under AddressSanitizer and UndefinedBehaviorSanitizer, and any undefined behaviour aborts so that libFuzzer
# reports the input. libFuzzer ships with Debian's clang (libclang-rt-14-dev: apt-get install clang).
if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
  message(FATAL_ERROR "RBCSTAB_FUZZ=ON needs clang for libFuzzer (apt-get install clang), configure with "
                      "-DCMAKE_CXX_COMPILER=clang++; the corpus replay (RBCSTAB_BUILD_FUZZ_REPLAY) builds with any compiler")
endif()
add_compile_options(-fsanitize=fuzzer-no-link,address,undefined -fno-sanitize-recover=all -fno-omit-frame-pointer -g)
add_link_options(-fsanitize=address,undefined)
