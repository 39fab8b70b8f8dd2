#include "rbcstab/model/rotating_wave.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/core/phasor.hpp"

namespace rbcstab {
namespace {

double max_abs(std::span<const double> v) {
  double s = 0;
  for (const double x : v) s = std::max(s, std::abs(x));
  return s;
}

}  // namespace

RotatingWave rotating_wave(const FullModel& model, std::span<const double> state, int l,
                           std::span<const std::complex<double>> direction, double tol) {
  const int L = model.L();
  require(l >= 3 && l <= L, "l", l, "an integer in [3, L = " + std::to_string(L) + "]");
  require(std::isfinite(tol) && tol > 0 && tol < 1, "tol", tol, "in (0, 1)");
  require(state.size() == model.dimension(), "state", static_cast<double>(state.size()),
          "a FullModel state of " + std::to_string(model.dimension()) + " numbers");
  require(static_cast<int>(direction.size()) == l + 1, "direction", static_cast<double>(direction.size()),
          "l + 1 = " + std::to_string(l + 1) + " amplitudes c_0..c_l");
  require(model.unforced(l), "l", l, "an unforced block (S_{l,m} = 0 for every m: no rest content in l)");
  if (!model.autonomous())
    throw InvalidArgument("state",
                          "state: the model's drive rotates (rest content with m != 0 at finite C), so it "
                          "has no equilibrium to turn into a rotating wave");
  double c2 = 0;  // sum over m = -l..l of |c_m|^2 (the real shape's both halves)
  int period_gcd = 0;
  for (int m = 0; m <= l; ++m) {
    const std::complex<double> c = direction[static_cast<std::size_t>(m)];
    require(std::isfinite(c.real()) && std::isfinite(c.imag()), "direction", std::abs(c), "finite amplitudes");
    c2 += (m == 0 ? 1.0 : 2.0) * std::norm(c);
    if (m > 0 && c != 0.0) period_gcd = std::gcd(period_gcd, m);
  }
  require(direction[0].imag() == 0.0, "direction", direction[0].imag(), "c_0 real (Im c_0 = 0: a real shape)");
  if (period_gcd == 0)
    throw InvalidArgument("direction", "direction: every c_m with m >= 1 is 0 (c_0 alone is the equilibrium itself)");
  for (const double v : state) require_finite("state", v);
  std::vector<double> F(state.size());
  model.rhs(0, state, F);
  const double residual = max_abs(F);
  require(residual <= tol * (1 + max_abs(state)), "state", residual,
          "an equilibrium (|F| <= tol (1 + |y|) = " + format_value(tol * (1 + max_abs(state))) + ")");
  double block2 = 0;
  for (int m = -l; m <= l; ++m) {
    const std::size_t k = 2 * ModeAmplitudes::index(l, m);
    block2 += state[k] * state[k] + state[k + 1] * state[k + 1];
  }
  if (!(block2 > 0))
    throw InvalidArgument("state", "state: its l = " + std::to_string(l) +
                                       " block is zero (a point of the branch born at that block's BP is needed)");
  RotatingWave w;
  w.L = L;
  w.l = l;
  w.period = 4 * kPi / period_gcd;
  w.y.assign(state.begin(), state.end());
  const double scale = std::sqrt(block2 / c2);
  for (int m = 0; m <= l; ++m) {
    const std::complex<double> f = scale * direction[static_cast<std::size_t>(m)];
    const std::complex<double> g = (m % 2 == 0 ? 1.0 : -1.0) * std::conj(f);  // f_{l,-m}
    const std::size_t kp = 2 * ModeAmplitudes::index(l, m), km = 2 * ModeAmplitudes::index(l, -m);
    w.y[kp] = f.real(), w.y[kp + 1] = f.imag();
    w.y[km] = g.real(), w.y[km + 1] = g.imag();
  }
  return w;
}

RotatingWave rotating_wave(const FullModel& model, std::span<const double> state, int l, int m, double tol) {
  require(l >= 3 && l <= model.L(), "l", l, "an integer in [3, L = " + std::to_string(model.L()) + "]");
  require(m >= 1 && m <= l, "m", m, "an integer in [1, l = " + std::to_string(l) + "]");
  std::vector<std::complex<double>> c(static_cast<std::size_t>(l + 1), 0.0);
  c[static_cast<std::size_t>(m)] = 1.0;
  return rotating_wave(model, state, l, c, tol);
}

std::vector<double> rotating_wave_at(const RotatingWave& wave, double t) {
  require_finite("t", t);
  std::vector<double> y = wave.y;
  for (int m = -wave.l; m <= wave.l; ++m) {
    const std::size_t k = 2 * ModeAmplitudes::index(wave.l, m);
    const std::complex<double> f = std::complex<double>(y[k], y[k + 1]) * unit_phasor(0.5 * m * t);
    y[k] = f.real(), y[k + 1] = f.imag();
  }
  return y;
}

}  // namespace rbcstab
