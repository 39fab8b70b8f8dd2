#pragma once
// Complex spherical-harmonic amplitudes f_{l,m} (or g_{l,m}), l = 2..L, m = -l..l (Eq. rho_rho0).
#include <complex>
#include <cstddef>
#include <vector>

namespace rbcstab {

struct ModeAmplitudes {
  int L = 2;
  std::vector<std::complex<double>> values;  // index(l, m)

  explicit ModeAmplitudes(int L_max = 2) : L(L_max), values(count(L_max)) {}
  static std::size_t count(int L_max) { return std::size_t((L_max + 1) * (L_max + 1) - 4); }
  static std::size_t index(int l, int m) { return std::size_t(l * l - 4 + m + l); }
  std::complex<double>& at(int l, int m) { return values[index(l, m)]; }
  const std::complex<double>& at(int l, int m) const { return values[index(l, m)]; }
  // Delta_l = a_l sum_m |f_{l,m}|^2                                          (Eq. excess_f)
  double excess_area(int l) const;
  double total_excess_area() const;
};

}  // namespace rbcstab
