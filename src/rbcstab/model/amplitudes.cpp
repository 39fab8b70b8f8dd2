#include "rbcstab/model/amplitudes.hpp"

#include <complex>

#include "rbcstab/model/coefficients.hpp"

namespace rbcstab {

double ModeAmplitudes::excess_area(int l) const {
  double s = 0;
  for (int m = -l; m <= l; ++m) s += std::norm(at(l, m));
  return a_l(l) * s;
}

double ModeAmplitudes::total_excess_area() const {
  double s = 0;
  for (int l = 2; l <= L; ++l) s += excess_area(l);
  return s;
}

}  // namespace rbcstab
