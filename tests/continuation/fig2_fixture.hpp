#pragma once
// Fig. 2's in-plane reduced scene (lambda = 5, Delta0 = 0.01, B = 2, C = 0.04, no l >= 3 content) at
// excess area Delta and orientation beta: the orbit tests' and benchmarks' material.
#include <cmath>

#include "rbcstab/model/scene.hpp"

namespace rbcstab::test {

inline Scene fig2_in_plane(double Delta, double beta = M_PI / 2) {
  Scene s;
  s.name = "fig2_ip";
  s.parameters.lambda = 5;
  s.parameters.Delta = Delta;
  s.parameters.Delta0 = 0.01;
  s.parameters.B = 2;
  s.parameters.C = 0.04;
  s.beta = beta;
  s.delta = 0;
  s.L = 2;
  s.model = ModelLevel::reduced;
  return s;
}

}  // namespace rbcstab::test
