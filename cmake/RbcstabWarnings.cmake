add_library(rbcstab_warnings INTERFACE)
target_compile_options(rbcstab_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Wnon-virtual-dtor -Wold-style-cast
  -Woverloaded-virtual -Wnull-dereference -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
if(RBCSTAB_WERROR)
  target_compile_options(rbcstab_warnings INTERFACE -Werror)
endif()
# GCC 12 misfires -Wstringop-overflow, -Warray-bounds and -Wrestrict on std::string concatenation ("[" + std::string(...))
# once -O3 inlines it deep enough, as in a unity batch: a memcpy bound above PTRDIFF_MAX inside libstdc++'s
# char_traits (GCC bugs 105329, 105545, 105651; fixed in 13). Those three are off on GCC 12 and older only; the
# sanitized suite checks bounds at run time.
if(CMAKE_CXX_COMPILER_ID STREQUAL "GNU" AND CMAKE_CXX_COMPILER_VERSION VERSION_LESS 13)
  target_compile_options(rbcstab_warnings INTERFACE -Wno-stringop-overflow -Wno-array-bounds -Wno-restrict)
endif()
