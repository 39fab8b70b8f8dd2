#pragma once
// Rotating waves of an unforced l >= 3 block of the full model (Eq. eom with S_{l,m} = 0).
//
// Such a block obeys f_l' = (i M/2 + Upsilon_l(sigma)) f_l, M = diag(m), and sigma (Eq. st) sees it only through
// Delta_l = a_l sum_m |f_{l,m}|^2: every Upsilon_l is real and the same for all m, and the work W has no term
// of the block. So f_l(t) = e^{i M t/2} g(t) with g' = Upsilon_l(sigma(t)) g: the block's direction is frozen in
// the rotating frame and only its magnitude evolves, coupled to the rest as the m = 0 amplitude is. An
// equilibrium with the block in m = 0 (a point of the branch born at the l-block's BP) therefore gives exact
// periodic solutions: the same state with the block's magnitude put in any direction (c_0, ..., c_l) of the
// block, rotating with e^{i m t/2}. Their period is 4 pi / gcd of the m present (4 pi / m for one m). Which
// direction is selected this model does not decide: a whole sphere of them, with the same sigma and Delta_l.
#include <complex>
#include <span>
#include <vector>

#include "rbcstab/model/full_model.hpp"

namespace rbcstab {

struct RotatingWave {
  int L = 3, l = 3;
  std::vector<double> y;  // the FullModel state at t = 0
  double period = 0;      // 4 pi / gcd{m >= 1 : c_m != 0}
};

// The rotating wave through `state` (a FullModel state that is an equilibrium: |F| <= tol (1 + |y|), max norms;
// a time-independent drive; the l-block unforced and not zero) with the l-block's area put in `direction`:
// c_m for m = 0..l (c_0 real, at least one c_m != 0 with m >= 1; any scale: it is normalised in the area
// metric), f_{l,-m} = (-1)^m conj f_{l,m} (a real shape). Throws InvalidArgument naming l, direction, state
// or tol.
RotatingWave rotating_wave(const FullModel& model, std::span<const double> state, int l,
                           std::span<const std::complex<double>> direction, double tol = 1e-8);
// The same with the block all in mode m (1..l), phase 0: f_{l,+-m} real-shape halves of |f_l| / sqrt(2).
RotatingWave rotating_wave(const FullModel& model, std::span<const double> state, int l, int m, double tol = 1e-8);
// The wave's state at time t: the block turned by e^{i m t/2}, the rest as at t = 0 (exact).
std::vector<double> rotating_wave_at(const RotatingWave& wave, double t);

}  // namespace rbcstab
