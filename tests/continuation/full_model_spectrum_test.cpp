// Leading eigenvalues of the full model's Jacobian (n = 2((L+1)^2 - 4)) by ARPACK shift-invert with
// the O(n) structured solve, against dense Eigen and against the closed form of the decoupled
// l >= 3 block at an ellipsoidal state.
//
// Closed form: at f_{l>=3} = 0 the rank-one part v w^T of J has v ∝ f (FullModel::jacobian), so the
// rows of l >= 3 hold only their 2x2 blocks [[Ups_l, -m/2], [m/2, Ups_l]]: J is block triangular and
// its spectrum is that of the l = 2 block (10 x 10, the L = 2 model) together with
// Upsilon_l(sigma) +- i m/2 for every l >= 3, m = -l..l (each value twice: m and -m).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <vector>

#include "continuation/full_model_fixture.hpp"
#include "rbcstab/continuation/eigen_arpack.hpp"

namespace rbcstab {
namespace {

struct FullJacobian {
  test::OutOfPlaneFullState st;
  Parameters p;
  StructuredJacobian J;
};

FullJacobian full_jacobian(int L) {
  FullJacobian f;
  f.st = test::out_of_plane_full_state(L);
  f.p = test::ellipsoidal_scene(L, 0.0).parameters;
  const FullModel full(f.p, f.st.init);
  std::vector<double> dfdt(full.dimension());
  full.jacobian(0, f.st.y, f.J, dfdt);
  return f;
}

std::vector<std::complex<double>> to_vector(const Eigen::VectorXcd& v) { return {v.data(), v.data() + v.size()}; }

// The closed-form spectrum: dense eigenvalues of the l = 2 block (rows/columns 0..9) and the l >= 3 values.
std::vector<std::complex<double>> closed_form_spectrum(const FullJacobian& f, int L) {
  const Eigen::MatrixXd D2 = test::dense(f.J, 10);
  auto all = to_vector(Eigen::EigenSolver<Eigen::MatrixXd>(D2, false).eigenvalues());
  for (int l = 3; l <= L; ++l) {
    const double ups = Upsilon_l(f.p, l, f.st.sigma);
    for (int m = -l; m <= l; ++m) {
      all.push_back({ups, 0.5 * m});
      all.push_back({ups, -0.5 * m});
    }
  }
  return all;
}

TEST(FullModelSpectrum, DecoupledBlockClosedFormMatchesDenseEigenvalues) {
  const int L = 8;
  const FullJacobian f = full_jacobian(L);
  // The embedded reduced equilibrium is an equilibrium of the full model (the modal reduction is exact).
  const FullModel full(f.p, f.st.init);
  std::vector<double> F(full.dimension());
  full.rhs(0, f.st.y, F);
  for (double x : F) EXPECT_LT(std::abs(x), 1e-13);
  const auto dense = to_vector(Eigen::EigenSolver<Eigen::MatrixXd>(test::dense(f.J), false).eigenvalues());
  const auto closed = closed_form_spectrum(f, L);
  ASSERT_EQ(dense.size(), closed.size());
  // 1e-10: dense QR error ~ eps |J| (|J| ~ |Upsilon_8| ~ 14) for these semisimple double eigenvalues.
  EXPECT_LT(test::multiset_distance(dense, closed), 1e-10);
  // The claim is not vacuous: l = 3, 4 are unstable here and lead the spectrum.
  EXPECT_GT(Upsilon_l(f.p, 4, f.st.sigma), Upsilon_l(f.p, 3, f.st.sigma));
  EXPECT_GT(Upsilon_l(f.p, 3, f.st.sigma), 0);
}

// Relative 1e-9: ARPACK's tol 1e-12 bounds the Ritz residual relative to |theta| = 1/|lambda - s|,
// i.e. |dlambda| <~ 1e-12 |lambda - s|^2 |theta| ~ 1e-12 here; dense QR adds eps |J| ~ 1e-13.
void check_nearest_shift(int L, bool with_dense) {
  const FullJacobian f = full_jacobian(L);
  const std::size_t n = f.J.size();
  ASSERT_EQ(n, static_cast<std::size_t>(2 * ((L + 1) * (L + 1) - 4)));
  ArpackOptions o;
  o.k = 16;
  o.which = ArpackWhich::nearest_shift;
  o.shift = 1.5;
  o.eigenvectors = true;
  const LinearOperator A = [&f](std::span<const double> x, std::span<double> y) { f.J.apply(x, y); };
  const ArpackResult r = arpack_eigenvalues(n, A, shifted_inverse(f.J, o.shift), o);
  ASSERT_EQ(r.status, ArpackStatus::converged) << r.message;
  ASSERT_EQ(r.eigenvalues.size(), 16);
  EXPECT_LT(r.applications, 300u);
  for (Eigen::Index i = 0; i < r.residuals.size(); ++i) EXPECT_LT(r.residuals[i], 1e-8);
  std::vector<std::vector<std::complex<double>>> oracles = {closed_form_spectrum(f, L)};
  if (with_dense)
    oracles.push_back(to_vector(Eigen::EigenSolver<Eigen::MatrixXd>(test::dense(f.J), false).eigenvalues()));
  for (auto want : oracles) {
    // The 16 values nearest the shift, with multiplicity: distances must agree one by one.
    std::sort(want.begin(), want.end(), [&](auto a, auto b) { return std::abs(a - o.shift) < std::abs(b - o.shift); });
    for (Eigen::Index i = 0; i < 16; ++i)
      EXPECT_NEAR(std::abs(r.eigenvalues[i] - o.shift), std::abs(want[std::size_t(i)] - o.shift), 1e-9) << i;
    EXPECT_LT(test::multiset_distance(to_vector(r.eigenvalues), want), 1e-9);
  }
}

TEST(FullModelSpectrum, ArpackShiftInvertMatchesDenseAndClosedFormAtL16) { check_nearest_shift(16, true); }

// n = 7434: dense eigenvalues are out of reach in a unit test (minutes), ARPACK takes ~0.2 s.
TEST(FullModelSpectrum, ArpackShiftInvertMatchesClosedFormAtL60) { check_nearest_shift(60, false); }

}  // namespace
}  // namespace rbcstab
