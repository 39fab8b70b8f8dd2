#pragma once
#include <cmath>
#include <limits>

namespace rbcstab::detail {

// The step of a central difference in v: cbrt(eps) (1 + |v|) balances truncation (h^2) against rounding (eps/h).
inline double fd_step(double v) { return std::cbrt(std::numeric_limits<double>::epsilon()) * (1 + std::abs(v)); }

}  // namespace rbcstab::detail
