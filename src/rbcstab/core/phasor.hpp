#pragma once
// e^{ix} = (cos x, sin x) for the rotating stress-free shape and drive, which every right-hand side of the
// modal, full and reduced levels evaluates once per call: libm's sincos was 20 % of a phase diagram's time
// (perf, App. E(b)). This one is about twice as fast and, for |x| <= 2^19 pi/2, within one ulp of the exact values
// (2^-53 absolute where they are below that; tested against long double): fdlibm's medium-size argument reduction
// (pi/2 in three parts, two rounds) and its sin/cos kernels on [-pi/4, pi/4] with the reduction's tail; larger or
// non-finite x go to std::polar.
//
// The reduction constants and kernel coefficients are fdlibm's (its rem_pio2 and its sin and cos kernels):
// Copyright (C) 1993 by Sun Microsystems, Inc. All rights reserved. Developed at SunSoft, a Sun Microsystems,
// Inc. business. Permission to use, copy, modify, and distribute this software is freely granted, provided
// that this notice is preserved.
#include <cmath>
#include <complex>

namespace rbcstab {

namespace phasor_detail {
// sin(x + y) and cos(x + y) for |x + y| <= pi/4, y the tail of the reduced argument (fdlibm's kernels).
inline double kernel_sin(double x, double y) {
  constexpr double S1 = -1.66666666666666324348e-01, S2 = 8.33333333332248946124e-03, S3 = -1.98412698298579493134e-04,
                   S4 = 2.75573137070700676789e-06, S5 = -2.50507602534068634195e-08, S6 = 1.58969099521155010221e-10;
  const double z = x * x, v = z * x, r = S2 + z * (S3 + z * (S4 + z * (S5 + z * S6)));
  return x - ((z * (0.5 * y - v * r) - y) - v * S1);
}
inline double kernel_cos(double x, double y) {
  constexpr double C1 = 4.16666666666666019037e-02, C2 = -1.38888888888741095749e-03, C3 = 2.48015872894767294178e-05,
                   C4 = -2.75573143513906633035e-07, C5 = 2.08757232129817482790e-09, C6 = -1.13596475577881948265e-11;
  const double z = x * x, r = z * (C1 + z * (C2 + z * (C3 + z * (C4 + z * (C5 + z * C6)))));
  const double hz = 0.5 * z, w = 1.0 - hz;
  return w + (((1.0 - w) - hz) + (z * r - x * y));
}
}  // namespace phasor_detail

// (cos x, sin x).
inline std::complex<double> unit_phasor(double x) {
  constexpr double kLimit = 823549.6123541676;  // 2^19 pi/2: two reduction rounds keep 118 bits below it
  if (!(std::abs(x) <= kLimit)) return std::polar(1.0, x);
  constexpr double invpio2 = 6.36619772367581382433e-01, pio2_1 = 1.57079632673412561417e+00,
                   pio2_1t = 6.07710050650619224932e-11, pio2_2 = 6.07710050630396597660e-11,
                   pio2_2t = 2.02226624879595063154e-21;
  const double fn = std::nearbyint(x * invpio2);
  // x - fn pi/2 as r + tail, with pi/2 split so that fn * pio2_1 and fn * pio2_2 are exact.
  double r = x - fn * pio2_1, w = fn * pio2_1t;
  const double t = r;
  w = fn * pio2_2;
  r = t - w;
  w = fn * pio2_2t - ((t - r) - w);
  const double y0 = r - w, y1 = (r - y0) - w;
  const double s = phasor_detail::kernel_sin(y0, y1), c = phasor_detail::kernel_cos(y0, y1);
  switch (static_cast<long long>(fn) & 3) {
    case 0:
      return {c, s};
    case 1:
      return {-s, c};
    case 2:
      return {-c, -s};
    default:
      return {s, -c};
  }
}

}  // namespace rbcstab
