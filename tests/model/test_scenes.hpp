#pragma once
// Scenes and generic states shared by the model and integration tests.
#include <cmath>
#include <numbers>
#include <ostream>
#include <random>
#include <vector>

#include "rbcstab/model/scene.hpp"

namespace rbcstab {
// Readable names of parameterised cases in gtest output.
inline void PrintTo(const Scene& s, std::ostream* os) {
  *os << "{lambda " << s.parameters.lambda << ", Delta " << s.parameters.Delta << ", Delta0 " << s.parameters.Delta0
      << ", B " << s.parameters.B << ", C " << s.parameters.C << ", beta " << s.beta << ", delta " << s.delta << ", L "
      << s.L << ", T " << s.T << "}";
}
}  // namespace rbcstab

namespace rbcstab::testing {

// The paper's Fig. 3 scene (B = 2, C = 0.04, lambda = 5, Delta = 1, Delta0 = 0.01, delta = 1e-3, L = 10).
inline Scene fig3_scene(double beta) {
  Scene s;
  s.parameters = Parameters{5.0, 1.0, 0.01, 2.0, 0.04};
  s.beta = beta;
  s.delta = 1e-3;
  s.L = 10;
  s.T = 500;
  s.dt = 1;
  return s;
}

// The paper's Fig. 2 scene (reduced: C = 0.04, lambda = 5, Delta0 = 0.01, no perturbation).
inline Scene fig2_scene(double Delta, double beta) {
  Scene s;
  s.parameters = Parameters{5.0, Delta, 0.01, 2.0, 0.04};
  s.beta = beta;
  s.delta = 0;
  s.L = 2;
  s.T = 50;
  s.dt = 0.5;
  return s;
}

// A scene without any symmetry: generic beta (m = +-1 content), a stress-free shape with l = 2
// content (explicit time dependence), and optionally stress-free l >= 3 content (full level only).
inline Scene generic_scene(int L, bool rest_high) {
  Scene s;
  s.parameters = Parameters{2.5, 0.8, 0.05, 1.7, 0.3};
  s.beta = 0.7;
  s.delta = 2e-2;
  s.L = L;
  if (rest_high) s.rest_delta_l = {{3, 4e-3}, {L, 1e-3}};
  return s;
}

// y0 perturbed by independent relative noise of size eps (deterministic seed).
inline std::vector<double> perturbed(std::vector<double> y, double eps, unsigned seed = 7) {
  std::mt19937 gen(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (double& v : y) v = v * (1 + eps * u(gen)) + 1e-3 * eps * u(gen);
  return y;
}

}  // namespace rbcstab::testing
