#pragma once
// The l = 2 rest shape's unit direction in the regular coordinates of the forced systems, and its
// exact derivative in beta (the only way beta enters their dynamics).
//
// initial_state gives g_{2,m} = -sqrt(Delta0/a_2) D^(2)_{m,0}(beta), so the direction
// (z0, w0, v0) = (sqrt(2) g22, -g20, sqrt(2) g21) / norm is u / |u| with the real vector
//   u = (-sqrt(2) D_{2,0}, D_{0,0}, -sqrt(2) D_{1,0}),  |u| >= 1/2 for every beta,
// and d(u/|u|)/dbeta = (u' - g (g.u')) / |u| with u' from wigner_column_derivative (closed form).
// with_m1 = false: the reduced system's (z0, w0), which drops the m = 1 content and renormalises
// (ReducedModel); then v0 = dv0 = 0.
#include <cmath>
#include <vector>

#include "rbcstab/model/coefficients.hpp"

namespace rbcstab::detail {

struct RestDirection {
  double z0 = 0, w0 = 0, v0 = 0;     // unit direction (z0, v0 real at t = 0: D is real)
  double dz0 = 0, dw0 = 0, dv0 = 0;  // its beta-derivative
};

inline RestDirection rest_direction(double beta, bool with_m1) {
  const std::vector<double> D = wigner_column(2, beta), dD = wigner_column_derivative(2, beta);
  const double s2 = std::sqrt(2.0);
  const double m1 = with_m1 ? 1.0 : 0.0;
  const double u[3] = {-s2 * D[4], D[2], -s2 * m1 * D[3]};
  const double du[3] = {-s2 * dD[4], dD[2], -s2 * m1 * dD[3]};
  const double norm = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  const double g[3] = {u[0] / norm, u[1] / norm, u[2] / norm};
  const double gdu = g[0] * du[0] + g[1] * du[1] + g[2] * du[2];
  RestDirection r;
  r.z0 = g[0], r.w0 = g[1], r.v0 = g[2];
  r.dz0 = (du[0] - g[0] * gdu) / norm;
  r.dw0 = (du[1] - g[1] * gdu) / norm;
  r.dv0 = (du[2] - g[2] * gdu) / norm;
  return r;
}

}  // namespace rbcstab::detail
