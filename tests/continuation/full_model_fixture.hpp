#pragma once
// Full-model states with no l >= 3 content (ellipsoidal shapes), shared by the ARPACK and Floquet tests.
#include <Eigen/Dense>
#include <cmath>
#include <complex>
#include <cstddef>
#include <limits>
#include <vector>

#include "rbcstab/analysis/steady_states.hpp"
#include "rbcstab/model/coefficients.hpp"
#include "rbcstab/model/full_model.hpp"
#include "rbcstab/model/reduced_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab::test {

// The paper's Fig. 3 material with an out-of-plane (beta = 0) rest shape and no perturbation.
inline Scene ellipsoidal_scene(int L, double beta) {
  Scene s;
  s.beta = beta;
  s.delta = 0;
  s.L = L;
  return s;
}

// The full model at the exact out-of-plane equilibrium of the reduced system (docs/theory.md),
// embedded with f_{l>=3} = 0 through ReducedModel::amplitudes.
struct OutOfPlaneFullState {
  InitialState init;
  std::vector<double> y;
  double sigma = 0;
};

inline OutOfPlaneFullState out_of_plane_full_state(int L) {
  const Scene s = ellipsoidal_scene(L, 0.0);
  OutOfPlaneFullState st;
  st.init = initial_state(s);
  const ReducedModel red(s.parameters, st.init);
  const OutOfPlaneEquilibrium eq = out_of_plane_equilibrium(s.parameters);
  const std::vector<double> yr = {eq.r * std::cos(eq.Psi), -eq.r * std::sin(eq.Psi), eq.w};
  st.init.f = red.amplitudes(0, yr);
  const FullModel full(s.parameters, st.init);
  st.y = full.initial_state();
  st.sigma = full.sigma(0, st.y);
  return st;
}

}  // namespace rbcstab::test

namespace rbcstab::test {

// Dense copy of the leading k x k block of a structured Jacobian (k = 0: all of it).
inline Eigen::MatrixXd dense(const StructuredJacobian& J, std::size_t k = 0) {
  const std::size_t n = k == 0 ? J.size() : k;
  Eigen::MatrixXd D(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) {
      double a = J.v[i] * J.w[j];
      if (i == j) a += J.diag[i];
      if (J.block_start[i] == 2 && j == i + 1) a += J.upper[i];
      if (j + 1 == i && J.block_start[j] == 2) a += J.lower[j];
      D(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(j)) = a;
    }
  return D;
}

// Multiset distance: for `got` (in order), remove the nearest unused member of `want`; returns the
// largest such distance relative to (1 + |want|). Used with multiplicities intact.
inline double multiset_distance(const std::vector<std::complex<double>>& got, std::vector<std::complex<double>> want) {
  double worst = 0;
  for (const auto& g : got) {
    std::size_t best = 0;
    double dbest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < want.size(); ++i)
      if (std::abs(g - want[i]) < dbest) {
        dbest = std::abs(g - want[i]);
        best = i;
      }
    if (want.empty()) return std::numeric_limits<double>::infinity();
    worst = std::max(worst, dbest / (1 + std::abs(want[best])));
    want.erase(want.begin() + static_cast<std::ptrdiff_t>(best));
  }
  return worst;
}

}  // namespace rbcstab::test
