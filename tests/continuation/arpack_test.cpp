// ARPACK (matrix-free Arnoldi) against dense Eigen eigenvalues and closed forms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <thread>
#include <vector>

#include <Eigen/Eigenvalues>

#include "continuation/full_model_fixture.hpp"
#include "rbcstab/continuation/eigen_arpack.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

// A = S D S^-1 with D block diagonal (real eigenvalues and 2x2 rotation blocks a +- ib), S = I + 0.1 R
// (well conditioned): the eigenvalues are known exactly and A is genuinely nonsymmetric.
struct KnownMatrix {
  Eigen::MatrixXd A;
  std::vector<std::complex<double>> eigenvalues;
};

KnownMatrix known_matrix(int n) {
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(n, n);
  KnownMatrix k;
  int i = 0;
  for (int b = 0; i < n; ++b) {
    const double a = -0.05 * b * b + 0.3 * std::sin(b);  // spread, distinct real parts
    if (b % 3 == 1 && i + 1 < n) {
      const double w = 0.5 + 0.1 * b;
      D(i, i) = D(i + 1, i + 1) = a;
      D(i, i + 1) = -w;
      D(i + 1, i) = w;
      k.eigenvalues.push_back({a, w});
      k.eigenvalues.push_back({a, -w});
      i += 2;
    } else {
      D(i, i) = a;
      k.eigenvalues.push_back(a);
      i += 1;
    }
  }
  Eigen::MatrixXd R(n, n);
  for (int r = 0; r < n; ++r)
    for (int c = 0; c < n; ++c) R(r, c) = std::sin(1.0 + 3.7 * r + 1.3 * c * c);
  const Eigen::MatrixXd S = Eigen::MatrixXd::Identity(n, n) + 0.1 * R / std::sqrt(double(n));
  k.A = S * D * S.inverse();
  return k;
}

std::vector<std::complex<double>> sorted_by(std::vector<std::complex<double>> v, ArpackWhich which, double shift) {
  auto key = [&](std::complex<double> l) {
    return which == ArpackWhich::largest_real        ? -l.real()
           : which == ArpackWhich::largest_magnitude ? -std::abs(l)
                                                     : std::abs(l - shift);
  };
  std::stable_sort(v.begin(), v.end(), [&](auto a, auto b) {
    if (key(a) != key(b)) return key(a) < key(b);
    return a.imag() > b.imag();
  });
  return v;
}

LinearOperator dense_operator(const Eigen::MatrixXd& A) {
  return [&A](std::span<const double> x, std::span<double> y) {
    Eigen::Map<Eigen::VectorXd>(y.data(), Eigen::Index(y.size())) =
        A * Eigen::Map<const Eigen::VectorXd>(x.data(), Eigen::Index(x.size()));
  };
}

// Relative 1e-9: ARPACK's tol 1e-12 bounds the Ritz residual relative to |theta|; the eigenvalue
// error is that times the eigenvector condition number (cond(S) ~ 1.3 here), far below 1e-9.
TEST(Arpack, ReproducesKnownSpectrumInEveryMode) {
  const int n = 200;
  const KnownMatrix km = known_matrix(n);
  const auto A = dense_operator(km.A);
  const Eigen::PartialPivLU<Eigen::MatrixXd> lu(km.A - 0.35 * Eigen::MatrixXd::Identity(n, n));
  const ShiftedSolve solve = [&lu](std::span<const double> x, std::span<double> y) {
    Eigen::Map<Eigen::VectorXd>(y.data(), Eigen::Index(y.size())) =
        lu.solve(Eigen::Map<const Eigen::VectorXd>(x.data(), Eigen::Index(x.size())));
    return true;
  };
  for (const ArpackWhich which :
       {ArpackWhich::largest_real, ArpackWhich::largest_magnitude, ArpackWhich::nearest_shift}) {
    ArpackOptions o;
    o.k = 8;
    o.which = which;
    o.shift = 0.35;
    o.eigenvectors = true;
    const ArpackResult r = arpack_eigenvalues(std::size_t(n), A, solve, o);
    ASSERT_EQ(r.status, ArpackStatus::converged) << to_string(which) << ": " << r.message;
    const auto want = sorted_by(km.eigenvalues, which, o.shift);
    ASSERT_EQ(r.eigenvalues.size(), 8);
    for (int i = 0; i < 8; ++i) {
      EXPECT_LT(std::abs(r.eigenvalues[i] - want[std::size_t(i)]), 1e-9 * (1 + std::abs(want[std::size_t(i)])))
          << to_string(which) << " #" << i << ": " << r.eigenvalues[i] << " vs " << want[std::size_t(i)];
      // The Ritz pairs are eigenpairs of A: residual |A v - lambda v| at the tol * |A| level.
      EXPECT_LT(r.residuals[i], 1e-9) << to_string(which) << " #" << i;
    }
    EXPECT_GT(r.applications, 8u);
    if (which == ArpackWhich::nearest_shift) {
      EXPECT_LT(r.applications, 200u);  // shift-invert converges fast
    }
  }
}

// ARPACK is not reentrant; concurrent calls are serialised and give the serial answer bit for bit
// (deterministic start vector).
TEST(Arpack, ConcurrentCallsAgreeWithSerial) {
  const KnownMatrix km = known_matrix(120);
  const auto A = dense_operator(km.A);
  ArpackOptions o;
  o.k = 6;
  const ArpackResult serial = arpack_eigenvalues(120, A, {}, o);
  ASSERT_EQ(serial.status, ArpackStatus::converged);
  std::vector<ArpackResult> par(4);
  std::vector<std::thread> threads;
  for (std::size_t i = 0; i < par.size(); ++i)
    threads.emplace_back([&, i] { par[i] = arpack_eigenvalues(120, A, {}, o); });
  for (auto& t : threads) t.join();
  for (const auto& r : par) {
    ASSERT_EQ(r.status, ArpackStatus::converged);
    EXPECT_EQ(r.applications, serial.applications);
    for (Eigen::Index i = 0; i < 6; ++i) EXPECT_EQ(r.eigenvalues[i], serial.eigenvalues[i]);
  }
}

TEST(Arpack, BadOptionsAreInvalidArgumentAndSingularShiftIsAStatus) {
  const KnownMatrix km = known_matrix(20);
  const auto A = dense_operator(km.A);
  ArpackOptions o;
  o.k = 19;
  EXPECT_THROW(arpack_eigenvalues(20, A, {}, o), InvalidArgument);  // k > n - 2
  o.k = 4;
  o.ncv = 5;
  EXPECT_THROW(arpack_eigenvalues(20, A, {}, o), InvalidArgument);  // ncv < k + 2
  o.ncv = 0;
  o.which = ArpackWhich::nearest_shift;
  EXPECT_THROW(arpack_eigenvalues(20, A, {}, o), InvalidArgument);  // no solve
  const ShiftedSolve singular = [](std::span<const double>, std::span<double>) { return false; };
  const ArpackResult r = arpack_eigenvalues(20, A, singular, o);
  EXPECT_EQ(r.status, ArpackStatus::solve_failed);
  EXPECT_NE(r.message.find("singular"), std::string::npos);
  StructuredJacobian J;
  J.resize(4);
  EXPECT_THROW(shifted_inverse(J, 0.0), InvalidArgument);
}

}  // namespace
}  // namespace rbcstab
