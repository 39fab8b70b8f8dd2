# Ipopt through pkg-config, linked as -lipopt only. Debian's ipopt.pc lists Ipopt's own dependencies in
# Libs (lapack, dmumps_seq, ...); libdmumps_seq and libmumps_common_seq export sequential stubs of the C
# MPI API (MPI_Init, MPI_Comm_rank, ...). On our link line those stubs would come before OpenMPI and
# capture rbcstab's MPI calls (every rank then reports rank 0). libipopt.so already records its own
# dependencies, so linking it alone is enough and keeps MPI's symbols resolved by libmpi.
pkg_check_modules(IPOPT REQUIRED IMPORTED_TARGET ipopt)
find_library(RBCSTAB_IPOPT_LIBRARY NAMES ipopt HINTS ${IPOPT_LIBRARY_DIRS} REQUIRED)
set_property(TARGET PkgConfig::IPOPT PROPERTY INTERFACE_LINK_LIBRARIES "${RBCSTAB_IPOPT_LIBRARY}")
