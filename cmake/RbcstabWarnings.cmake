add_library(rbcstab_warnings INTERFACE)
target_compile_options(rbcstab_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -Wnon-virtual-dtor -Wold-style-cast
  -Woverloaded-virtual -Wnull-dereference -Wdouble-promotion -Wformat=2 -Wimplicit-fallthrough)
if(RBCSTAB_WERROR)
  target_compile_options(rbcstab_warnings INTERFACE -Werror)
endif()
