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
// Growth rate Upsilon_l(sigma) = [Gamma_1 + sigma Gamma_2]/B + Gamma_3/C    (Eq. eom_sup_ups)
// evaluated as (Gamma_2/B)(Pi + sigma + 4 alpha/Pi), which is exact and stays finite for C = inf.
double Upsilon(const Parameters& p, int l, double sigma);
// Critical tension sigma_l^c = -(Pi + 4 alpha / Pi): mode l grows iff sigma < sigma_l^c.
double sigma_critical(int l, double alpha);

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
