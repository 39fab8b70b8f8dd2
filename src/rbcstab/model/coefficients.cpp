#include "rbcstab/model/coefficients.hpp"

#include <cmath>
#include <numbers>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"
#include "rbcstab/model/parameters.hpp"

namespace rbcstab {

namespace {
void require_mode(int l) { require(l >= 2, "l", l, "an integer >= 2"); }
}  // namespace

double d_lambda_l(double lambda, int l) {
  const double x = l;
  const double q = 2 * x * x * x + 3 * x * x;
  return (q + 4) + lambda * (q - 5);
}

double Gamma1(double lambda, int l) {
  require_mode(l);
  const double x = l;
  return -(x + 2) * (x + 1) * (x + 1) * x * x * (x - 1) / d_lambda_l(lambda, l);
}

double Gamma2(double lambda, int l) {
  require_mode(l);
  const double x = l;
  return -(x + 2) * (x + 1) * x * (x - 1) / d_lambda_l(lambda, l);
}

double Gamma3(double lambda, int l) {
  require_mode(l);
  const double x = l;
  return -4 * (x + 2) * (x - 1) / d_lambda_l(lambda, l);
}

double a_l(int l) {
  const double x = l;
  return (x + 2) * (x - 1) / 2;
}

double Pi_l(int l) {
  const double x = l;
  return x * (x + 1);
}

std::complex<double> shear_drive(double lambda, int l, int m) {
  if (l != 2 || (m != 2 && m != -2)) return {0.0, 0.0};
  const double magnitude = 4 * std::sqrt(30 * kPi) / d_lambda_l(lambda, 2);
  return {0.0, m > 0 ? -magnitude : magnitude};
}

double sigma_c(int l, double alpha) {
  const double Pi = Pi_l(l);
  return -(Pi + 4 * alpha / Pi);
}

GrowthRate Upsilon_l(const Parameters& p, int l) { return {Gamma2(p.lambda, l) / p.B, sigma_c(l, p.alpha())}; }

double Upsilon_l(const Parameters& p, int l, double sigma) { return Upsilon_l(p, l)(sigma); }

std::vector<double> wigner_column(int l, double beta) {
  require(l >= 0, "l", l, "an integer >= 0");
  require_finite("beta", beta);
  const double x = std::cos(beta);
  const double s = std::sin(beta);
  std::vector<double> col(2 * l + 1, 0.0);
  // Normalised P~_l^m = sqrt((l-m)!/(l+m)!) P_l^m for m >= 0, built up in l at fixed m.
  double pmm = 1.0;  // P~_m^m = prod_{k=1..m} sqrt((2k-1)/(2k)) s^m
  for (int m = 0; m <= l; ++m) {
    if (m > 0) pmm *= std::sqrt((2.0 * m - 1) / (2.0 * m)) * s;
    double p_prev = pmm;  // P~_{m}^m
    double value = pmm;
    if (l > m) {
      double p_curr = std::sqrt(2.0 * m + 1) * x * pmm;  // P~_{m+1}^m
      for (int k = m + 2; k <= l; ++k) {
        const double kk = k;
        const double next = ((2 * kk - 1) * x * p_curr - std::sqrt((kk - 1) * (kk - 1) - double(m) * m) * p_prev) /
                            std::sqrt(kk * kk - double(m) * m);
        p_prev = p_curr;
        p_curr = next;
      }
      value = p_curr;
    }
    col[l + m] = value;
    // D_{-m,0} = (-1)^m D_{m,0} (reality of the rotated axisymmetric shape).
    col[l - m] = (m % 2 == 0) ? value : -value;
  }
  return col;
}

std::vector<double> wigner_column_derivative(int l, double beta) {
  const std::vector<double> D = wigner_column(l, beta);
  std::vector<double> d(D.size(), 0.0);
  for (int m = -l; m <= l; ++m) {
    const double lo = m > -l ? std::sqrt(double(l + m) * (l - m + 1)) * D[static_cast<std::size_t>(l + m - 1)] : 0.0;
    const double hi = m < l ? std::sqrt(double(l - m) * (l + m + 1)) * D[static_cast<std::size_t>(l + m + 1)] : 0.0;
    d[static_cast<std::size_t>(l + m)] = 0.5 * (lo - hi);
  }
  return d;
}

}  // namespace rbcstab
