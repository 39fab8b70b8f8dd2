#include "rbcstab/continuation/eigen_arpack.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <mutex>
#include <numeric>
#include <vector>

#include "rbcstab/continuation/detail/arpack_fortran.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

void ArpackOptions::validate(std::size_t n) const {
  const double nn = static_cast<double>(n);
  require(n >= 3, "n", nn, ">= 3 (ARPACK needs k + 2 <= ncv <= n)");
  require(k >= 1 && static_cast<double>(k) <= nn - 2, "k", k, "[1, n - 2]");
  require(ncv == 0 || (ncv >= k + 2 && static_cast<double>(ncv) <= nn), "ncv", ncv, "0 (automatic) or [k + 2, n]");
  require(std::isfinite(tol) && tol >= 0 && tol < 1, "tol", tol, "[0, 1)");
  require(max_iterations >= 1, "max_iterations", max_iterations, ">= 1");
  require(std::isfinite(shift), "shift", shift, "a finite real number");
}

namespace {

// Deterministic start vector (ARPACK's own random start depends on how often it was called in the
// process): a splitmix64 sequence mapped to [-1, 1), so no eigenvector is orthogonal to it by symmetry.
void start_vector(std::vector<double>& resid) {
  std::uint64_t s = 0x9E3779B97F4A7C15ULL;
  for (double& r : resid) {
    s += 0x9E3779B97F4A7C15ULL;
    std::uint64_t z = s;
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    z ^= z >> 31;
    r = static_cast<double>(z >> 11) * 0x1.0p-52 - 1.0;
  }
}

std::string arpack_error(const char* routine, int info) {
  std::string what;
  switch (info) {
    case -8:
      what = "error in the LAPACK Schur form (dlahqr)";
      break;
    case -9:
      what = "starting vector is zero";
      break;
    case -9999:
      what = "could not build an Arnoldi factorization (the operator may be rank deficient)";
      break;
    case -14:
      what = "no Ritz value converged";
      break;
    default:
      what = "error code";
      break;
  }
  return std::string(routine) + " info = " + std::to_string(info) + ": " + what;
}

}  // namespace

ArpackResult arpack_eigenvalues(std::size_t n_size, const LinearOperator& apply, const ShiftedSolve& solve,
                                const ArpackOptions& options) {
  options.validate(n_size);
  const bool shift_invert = options.which == ArpackWhich::nearest_shift;
  if (shift_invert && !solve) throw InvalidArgument("solve", "nearest_shift needs the shifted solve (A - s I)^{-1}");
  if (!shift_invert && !apply) throw InvalidArgument("apply", to_string(options.which) + " needs the operator action");
  const int n = static_cast<int>(n_size);
  const int nev = options.k;
  const int ncv = options.ncv > 0 ? options.ncv : std::min(n, std::max(2 * nev + 1, nev + 20));
  const int ldv = n, lworkl = 3 * ncv * ncv + 6 * ncv;
  // Shift-invert looks for the largest |1/(lambda - s)|, i.e. lambda nearest s.
  const char* which = options.which == ArpackWhich::largest_real ? "LR" : "LM";
  const char bmat = 'I';
  const double tol = options.tol;

  // ARPACK keeps state between reverse-communication calls in Fortran SAVE variables, so it is not
  // reentrant: concurrent calls (threaded sweeps) are serialised here. The one process-wide lock is
  // unavoidable for a non-reentrant library (the operator must not itself call arpack_eigenvalues).
  static std::mutex arpack_mutex;
  const std::lock_guard<std::mutex> lock(arpack_mutex);
  ArpackResult out;
  std::vector<double> resid(n_size), v(n_size * static_cast<std::size_t>(ncv)), workd(3 * n_size),
      workl(static_cast<std::size_t>(lworkl));
  start_vector(resid);
  int iparam[11] = {}, ipntr[14] = {};
  iparam[0] = 1;  // exact shifts
  iparam[2] = options.max_iterations;
  iparam[6] = shift_invert ? 3 : 1;
  int ido = 0, info = 1;  // info = 1: resid holds our start vector
  for (;;) {
    dnaupd_(&ido, &bmat, &n, which, &nev, &tol, resid.data(), &ncv, v.data(), &ldv, iparam, ipntr, workd.data(),
            workl.data(), &lworkl, &info, 1, 2);
    if (ido != -1 && ido != 1) break;
    const std::span<const double> x(workd.data() + ipntr[0] - 1, n_size);
    const std::span<double> y(workd.data() + ipntr[1] - 1, n_size);
    ++out.applications;
    if (shift_invert) {
      if (!solve(x, y)) {
        out.status = ArpackStatus::solve_failed;
        out.message = "the shifted solve (A - s I)^{-1} failed at s = " + std::to_string(options.shift) +
                      " (singular: the shift is on or too near an eigenvalue)";
        return out;
      }
    } else {
      apply(x, y);
    }
  }
  out.iterations = iparam[2];
  out.converged = iparam[4];
  if (info < 0) {
    out.status = ArpackStatus::failed;
    out.message = arpack_error("dnaupd", info);
    return out;
  }
  const bool hit_max = info == 1;
  if (info == 3) {
    out.status = ArpackStatus::failed;
    out.message = "dnaupd info = 3: no shifts could be applied; increase ncv";
    return out;
  }
  if (out.converged == 0) {
    out.status = hit_max ? ArpackStatus::max_iterations : ArpackStatus::failed;
    out.message = "no Ritz value converged after " + std::to_string(out.iterations) + " restarts";
    return out;
  }

  const int rvec = options.eigenvectors ? 1 : 0;
  const char howmny = 'A';
  std::vector<int> select(static_cast<std::size_t>(ncv), 0);
  std::vector<double> dr(static_cast<std::size_t>(nev) + 1), di(static_cast<std::size_t>(nev) + 1),
      workev(3 * static_cast<std::size_t>(ncv));
  std::vector<double> z(rvec ? n_size * (static_cast<std::size_t>(nev) + 1) : 1);
  const int ldz = rvec ? n : 1;
  const double sigmar = options.shift, sigmai = 0;  // real shift: dneupd returns A's eigenvalues (type SHIFTI)
  int info2 = 0;
  dneupd_(&rvec, &howmny, select.data(), dr.data(), di.data(), z.data(), &ldz, &sigmar, &sigmai, workev.data(), &bmat,
          &n, which, &nev, &tol, resid.data(), &ncv, v.data(), &ldv, iparam, ipntr, workd.data(), workl.data(), &lworkl,
          &info2, 1, 1, 2);
  if (info2 != 0) {
    out.status = ArpackStatus::failed;
    out.message = arpack_error("dneupd", info2);
    return out;
  }
  const int nconv = std::min(iparam[4], nev + 1);
  std::vector<std::complex<double>> values(static_cast<std::size_t>(nconv), 0.0);
  std::vector<Eigen::VectorXcd> vectors(values.size());  // empty where the partner column is missing
  // Complex pairs occupy consecutive columns (p, p+1) of z: z_p + i z_{p+1} is the eigenvector of the
  // pair's member with positive imaginary part for OP. In shift-invert mode lambda = s + 1/theta flips
  // that sign, so there it belongs to the member with negative imaginary part.
  const double base_sign = shift_invert ? -1.0 : 1.0;
  int pair_start = -1;
  for (int j = 0; j < nconv; ++j) {
    const auto uj = static_cast<std::size_t>(j);
    values[uj] = {dr[uj], di[uj]};
    const bool complex_value = di[uj] != 0;
    if (complex_value && pair_start < 0) pair_start = j;  // first column of a pair
    const int p = complex_value ? pair_start : j;
    if (complex_value && j == pair_start + 1) pair_start = -1;  // pair complete
    if (!rvec) continue;
    if (complex_value && p + 1 > nev) continue;  // its partner column was not returned
    Eigen::VectorXcd vec(n);
    const double* re = z.data() + static_cast<std::size_t>(p) * n_size;
    if (!complex_value) {
      for (int i = 0; i < n; ++i) vec[i] = re[i];
    } else {
      const double* im = re + n_size;
      const double sign = (di[uj] > 0 ? 1.0 : -1.0) * base_sign;
      for (int i = 0; i < n; ++i) vec[i] = {re[i], sign * im[i]};
    }
    vec.normalize();
    vectors[uj] = vec;
  }
  // Order best first by `which`; keep at most k.
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  auto key = [&](std::size_t i) {
    const std::complex<double> l = values[i];
    switch (options.which) {
      case ArpackWhich::largest_real:
        return -l.real();
      case ArpackWhich::largest_magnitude:
        return -std::abs(l);
      case ArpackWhich::nearest_shift:
        return std::abs(l - options.shift);
    }
    return 0.0;
  };
  // Ties (a conjugate pair) put the positive imaginary part first, deterministically.
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
    const double ka = key(a), kb = key(b);
    if (ka != kb) return ka < kb;
    return values[a].imag() > values[b].imag();
  });
  const std::size_t keep = std::min(order.size(), static_cast<std::size_t>(nev));
  out.eigenvalues.resize(static_cast<Eigen::Index>(keep));
  for (std::size_t i = 0; i < keep; ++i) out.eigenvalues[static_cast<Eigen::Index>(i)] = values[order[i]];
  bool have_vectors = rvec != 0;
  for (std::size_t i = 0; i < keep && have_vectors; ++i) have_vectors = vectors[order[i]].size() == n;
  if (have_vectors) {
    out.eigenvectors.resize(n, static_cast<Eigen::Index>(keep));
    if (apply) out.residuals.resize(static_cast<Eigen::Index>(keep));
    std::vector<double> xr(n_size), xi(n_size), yr(n_size), yi(n_size);
    for (std::size_t i = 0; i < keep; ++i) {
      const Eigen::VectorXcd& vec = vectors[order[i]];
      out.eigenvectors.col(static_cast<Eigen::Index>(i)) = vec;
      if (!apply) continue;
      for (std::size_t r = 0; r < n_size; ++r) {
        xr[r] = vec[static_cast<Eigen::Index>(r)].real();
        xi[r] = vec[static_cast<Eigen::Index>(r)].imag();
      }
      apply(xr, yr);
      apply(xi, yi);
      double s = 0;
      const std::complex<double> l = out.eigenvalues[static_cast<Eigen::Index>(i)];
      for (std::size_t r = 0; r < n_size; ++r)
        s += std::norm(std::complex<double>(yr[r], yi[r]) - l * vec[static_cast<Eigen::Index>(r)]);
      out.residuals[static_cast<Eigen::Index>(i)] = std::sqrt(s);
    }
  }
  const bool all = static_cast<int>(keep) >= nev;
  out.status = all ? ArpackStatus::converged : (hit_max ? ArpackStatus::max_iterations : ArpackStatus::failed);
  if (!all)
    out.message = std::to_string(keep) + " of " + std::to_string(nev) + " Ritz values converged in " +
                  std::to_string(out.iterations) + " restarts";
  return out;
}

ShiftedSolve shifted_inverse(const StructuredJacobian& J, double shift) {
  require(std::isfinite(shift) && shift != 0, "shift", shift,
          "a finite nonzero real (the structured solve factors (I - J/s); s = 0 is not reachable)");
  return [&J, shift](std::span<const double> x, std::span<double> y) {
    // (J - s I)^{-1} = -(1/s) (I - J/s)^{-1}
    if (!J.solve_shifted(1.0 / shift, x, y)) return false;
    for (double& value : y) value *= -1.0 / shift;
    return true;
  };
}

}  // namespace rbcstab
