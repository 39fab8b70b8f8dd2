#pragma once
// Mode coefficients of the perturbative model (paper Appendix B, Eqs. gammas; Appendix A).
#include <complex>
#include <vector>

namespace rbcstab {

struct Parameters;

// d(lambda, l) = (2l^3 + 3l^2 + 4) + lambda (2l^3 + 3l^2 - 5)            (Eq. gammas)
double d_lambda_l(double lambda, int l);
// Gamma_1^l = -(l+2)(l+1)^2 l^2 (l-1) / d                                  (Eq. gammas)
double Gamma1(double lambda, int l);
// Gamma_2^l = -(l+2)(l+1) l (l-1) / d                                      (Eq. gammas)
double Gamma2(double lambda, int l);
// Gamma_3^l = -4 (l+2)(l-1) / d                                            (Eq. gammas)
double Gamma3(double lambda, int l);
// a_l = (l+2)(l-1)/2: excess-area weight of mode l                        (Eq. excess_f)
double a_l(int l);
// Pi = l(l+1)                                                             (Eq. inst)
double Pi_l(int l);
// Shear drive C_{l,m}: only C_{2,+-2} = -+ 4 i sqrt(30 pi) / (32 + 23 lambda) are non-zero.
std::complex<double> shear_drive(double lambda, int l, int m);
// Critical tension sigma_l^c = -(Pi + 4 alpha/Pi): mode l grows iff sigma < sigma_l^c       (Eq. inst)
double sigma_c(int l, double alpha);

// Growth rate of mode l (Eq. eom_sup_ups) in its affine form. Eq. gammas gives Gamma_1/Gamma_2 = Pi and
// Gamma_3/Gamma_2 = 4/Pi exactly, so
//   Upsilon_l(sigma) = [Gamma_1 + sigma Gamma_2]/B + Gamma_3/C = (Gamma_2/B)(Pi + sigma + 4 alpha/Pi)
//                    = slope (sigma - sigma_l^c),
// finite for C = inf. Hot loops keep the two numbers per mode instead of re-evaluating the rationals.
struct GrowthRate {
  double slope = 0;    // dUpsilon_l/dsigma = Gamma_2^l / B (< 0)
  double sigma_c = 0;  // its zero, sigma_l^c
  double operator()(double sigma) const { return slope * (sigma - sigma_c); }
  // The inverse: the tension at which the rate equals `rate` (the reduced model's sigma_R from mu = Upsilon_2).
  double sigma_at(double rate) const { return rate / slope + sigma_c; }
};
GrowthRate Upsilon_l(const Parameters& p, int l);
double Upsilon_l(const Parameters& p, int l, double sigma);  // = Upsilon_l(p, l)(sigma)

// Wigner column D^(l)_{m,0}(beta), m = -l..l (index m + l), in the paper's convention
// (Appendix A: D^(2)_{1,0} = +sqrt(3/2) cos(beta) sin(beta)), i.e.
// D^(l)_{m,0}(beta) = sqrt((l-m)!/(l+m)!) P_l^m(cos beta) without the Condon-Shortley phase.
// Computed by the normalised three-term recursion: no factorials, accurate for large l.
std::vector<double> wigner_column(int l, double beta);
// d/dbeta of wigner_column(l, beta) (index m + l), from the ladder identity of the same convention
//   dD_{m,0}/dbeta = (sqrt((l+m)(l-m+1)) D_{m-1,0} - sqrt((l-m)(l+m+1)) D_{m+1,0}) / 2
// (e.g. l = 2: dD_{0,0} = -3 sin cos, dD_{2,0} = sqrt(3/2) sin cos, dD_{1,0} = sqrt(3/2) cos 2beta).
std::vector<double> wigner_column_derivative(int l, double beta);

}  // namespace rbcstab
