#pragma once
// An in-plane (beta = pi/2) ellipsoidal orbit of the full model and its exact monodromy, shared by the
// Floquet tests and benchmarks/arpack_bench.cpp.
//
// Along a trajectory with f_{l>=3} = 0 the full model's Jacobian J = M + v w^T is block diagonal: v is
// proportional to f and w to (f, S), both zero for l >= 3 (the shear drive S acts on l = 2 only when the
// rest shape has no l >= 3 content). So each (l, m), l >= 3, obeys f' = (Upsilon_l(sigma(t)) + i m/2) f
// alone and over one period T = 2 pi is multiplied by exp(int Upsilon_l dt) e^{i pi m} =
// (-1)^m exp(T Upsilon_l(sigma_bar)) (Upsilon_l affine in sigma, sigma_bar the period mean of sigma); the
// real 2x2 block is that value times the identity. The l = 2 block (10 x 10) is the L = 2 model's
// monodromy, computed densely. Hence Phi = diag(Phi_2, closed form) applies exactly in O(n).
#include <Eigen/Dense>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <span>
#include <vector>

#include "full_model_fixture.hpp"
#include "rbcstab/continuation/monodromy.hpp"
#include "rbcstab/core/constants.hpp"
#include "rbcstab/integrate/integrator.hpp"

namespace rbcstab::test {

// An in-plane orbit state at t0 = 2 pi k: the reduced model (exact for ellipsoidal states) relaxed over
// 30 forcing periods, embedded with f_{l>=3} = 0.
struct InPlaneOrbit {
  Parameters p;
  InitialState init;
  double t0 = 0;
  bool ok = false;  // the relaxation integrated successfully
};

inline InPlaneOrbit in_plane_orbit(int L) {
  InPlaneOrbit o;
  const Scene s = ellipsoidal_scene(L, std::numbers::pi / 2);
  o.p = s.parameters;
  o.init = initial_state(s);
  const ReducedModel red(o.p, o.init);
  o.t0 = 30 * kTwoPi;
  const double grid[1] = {o.t0};
  IntegratorOptions io;
  io.rtol = 1e-11;
  io.atol = 1e-13;
  const IntegrationResult r = integrate(red, red.initial_state(), 0.0, grid, io, {});
  o.ok = r.status == IntegrationStatus::success;
  o.init.f = red.amplitudes(o.t0, r.y);
  return o;
}

// The orbit truncated to l = 2: same sigma(t) (f_{l>=3} = 0 adds nothing to sigma's sums).
inline FullModel l2_model(const InPlaneOrbit& o) {
  InitialState init2 = o.init;
  ModeAmplitudes f2(2);
  for (int m = -2; m <= 2; ++m) f2.at(2, m) = o.init.f.at(2, m);
  init2.f = f2;
  return FullModel(o.p, init2);
}

// Mean of sigma over one period (composite Simpson, 4000 intervals: error ~ h^4 |sigma''''| ~ 1e-12
// relative for this smooth periodic sigma), on the L = 2 model.
inline double mean_sigma(const InPlaneOrbit& o) {
  const FullModel full2 = l2_model(o);
  const int N = 4000;
  std::vector<double> grid(N + 1), sig;
  for (int i = 0; i <= N; ++i) grid[std::size_t(i)] = o.t0 + kTwoPi * i / N;
  IntegratorOptions io;
  io.rtol = 1e-12;
  io.atol = 1e-14;
  integrate(full2, full2.initial_state(), o.t0, grid, io,
            [&](double t, std::span<const double> y) { sig.push_back(full2.sigma(t, y)); });
  if (sig.size() != std::size_t(N + 1)) return std::nan("");
  double s = sig.front() + sig.back();
  for (int i = 1; i < N; ++i) s += (i % 2 ? 4 : 2) * sig[std::size_t(i)];
  return s / (3.0 * N);  // (h/3) sum / T with h = T/N
}

struct ExactInPlaneMonodromy {
  Parameters p;
  int L = 2;
  double sigma_bar = 0;
  Eigen::MatrixXd Phi2;  // the l = 2 block (rk8pd, rtol 1e-12)

  double factor(int l, int m) const {
    const double E = std::exp(kTwoPi * Upsilon_l(p, l, sigma_bar));
    return m % 2 ? -E : E;
  }
  // out = Phi v
  void apply(std::span<const double> v, std::span<double> out) const {
    const Eigen::VectorXd u = Phi2 * Eigen::Map<const Eigen::VectorXd>(v.data(), 10);
    for (Eigen::Index i = 0; i < 10; ++i) out[std::size_t(i)] = u(i);
    for (int l = 3; l <= L; ++l)
      for (int m = -l; m <= l; ++m) {
        const std::size_t i = 2 * ModeAmplitudes::index(l, m);
        out[i] = factor(l, m) * v[i];
        out[i + 1] = factor(l, m) * v[i + 1];
      }
  }
  // Every multiplier with multiplicity, largest modulus first.
  std::vector<std::complex<double>> multipliers() const {
    const Eigen::VectorXcd e = Eigen::EigenSolver<Eigen::MatrixXd>(Phi2, false).eigenvalues();
    std::vector<std::complex<double>> all(e.data(), e.data() + e.size());
    for (int l = 3; l <= L; ++l)
      for (int m = -l; m <= l; ++m) all.insert(all.end(), 2, factor(l, m));
    std::stable_sort(all.begin(), all.end(), [](auto a, auto b) { return std::abs(a) > std::abs(b); });
    return all;
  }
};

inline ExactInPlaneMonodromy exact_in_plane_monodromy(const InPlaneOrbit& o, int L) {
  ExactInPlaneMonodromy x;
  x.p = o.p;
  x.L = L;
  x.sigma_bar = mean_sigma(o);
  const FullModel full2 = l2_model(o);
  MonodromyOptions mo;
  mo.integrator.rtol = 1e-12;
  mo.integrator.atol = 1e-14;
  x.Phi2 = MonodromyAction(full2, full2.initial_state(), o.t0, mo).dense();
  return x;
}

// A fixed pseudo-random unit vector (deterministic across platforms: an LCG, not std::rand).
inline std::vector<double> test_vector(std::size_t n) {
  std::vector<double> v(n);
  std::uint64_t s = 12345;
  double norm = 0;
  for (auto& x : v) {
    s = s * 6364136223846793005ULL + 1442695040888963407ULL;
    x = double(s >> 11) / double(1ULL << 53) - 0.5;
    norm += x * x;
  }
  for (auto& x : v) x /= std::sqrt(norm);
  return v;
}

}  // namespace rbcstab::test
