#pragma once
// Private: the rk8pd stepper. The explicit embedded Runge-Kutta pair RK8(7)13M of Prince and Dormand
// (J. Comput. Appl. Math. 7 (1981) 67-75) with the standard local error control
//   r = max_k |e_k| / (rtol |y_k| + atol),  r > 1.1: retry with h 0.9 r^(-1/8) (>= h/5),
//   r < 0.5: next h 0.9 r^(-1/9) (<= 5 h, never smaller),
// taken in the order and with the arithmetic of gsl_odeiv2_evolve_apply driving GSL's rk8pd with that control
// (a_y = 1, a_dydt = 0): on the same system both take the same steps and reach the same state bit for bit
// (tests/integrate/prince_dormand_test.cpp). It exists to step a system's compact form (model/system.hpp): x is
// stepped while the error is controlled on every component of y = Y(x), e_{y,k} = scale_k e_{x,source_k}.
#include <cstddef>
#include <span>
#include <vector>

#include "rbcstab/model/system.hpp"

namespace rbcstab::detail {

class PrinceDormand87 {
 public:
  // x' = F(t, x); returns 0, or a nonzero code that rejects the trial step (as a GSL right-hand side does).
  using Rhs = int (*)(double t, const double* x, double* dxdt, void* params);
  // form: the compact form being stepped (x = its state; its references are centred at each step's start), or
  // nullptr (x = y).
  PrinceDormand87(std::size_t n, Rhs rhs, void* params, double atol, double rtol, CompactForm* form = nullptr);

  // One accepted step from t towards t1 > t, never beyond it, updating t, x and the suggested next h (kept when
  // the step was cut to end at t1). Returns 0; the right-hand side's code when it fails at the start or keeps
  // failing as h is halved to the last representable decrease (t, x unchanged); -1 when the error cannot be
  // brought under control by a representable decrease of h (t, x then hold the rejected step, as GSL's).
  int apply(double& t, double t1, double& h, std::span<double> x);
  std::size_t failed_steps() const { return failed_; }

 private:
  double error_ratio(const double* x, const double* err) const;
  std::size_t n_;
  Rhs rhs_;
  void* params_;
  double atol_, rtol_;
  CompactForm* form_;
  std::vector<double> k_;  // 13 stage slopes, n each
  std::vector<double> x0_, ytmp_, err_;
  std::size_t failed_ = 0;
};

}  // namespace rbcstab::detail
