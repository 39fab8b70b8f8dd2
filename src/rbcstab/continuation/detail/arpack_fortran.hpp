#pragma once
// Prototypes of ARPACK's Fortran reverse-communication routines for real nonsymmetric problems
// (libarpack2, gfortran ABI: every argument by reference, LOGICAL = int, and one hidden size_t
// length per CHARACTER argument appended in order).
#include <cstddef>

extern "C" {
void dnaupd_(int* ido, const char* bmat, const int* n, const char* which, const int* nev, const double* tol,
             double* resid, const int* ncv, double* v, const int* ldv, int* iparam, int* ipntr, double* workd,
             double* workl, const int* lworkl, int* info, std::size_t bmat_len, std::size_t which_len);

void dneupd_(const int* rvec, const char* howmny, int* select, double* dr, double* di, double* z, const int* ldz,
             const double* sigmar, const double* sigmai, double* workev, const char* bmat, const int* n,
             const char* which, const int* nev, const double* tol, double* resid, const int* ncv, double* v,
             const int* ldv, int* iparam, int* ipntr, double* workd, double* workl, const int* lworkl, int* info,
             std::size_t howmny_len, std::size_t bmat_len, std::size_t which_len);
}
