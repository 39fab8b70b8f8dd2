#include "rbcstab/integrate/detail/prince_dormand.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <cstring>

namespace rbcstab::detail {

namespace {
// The RK8(7)13M tableau: nodes c_s, the nonzero a_{s,j} of each stage in increasing j, and the weights of the
// eighth-order solution (b) and of the seventh-order one (bhat) that estimates its error.
struct Term {
  int j;
  double a;
};
constexpr double c[13] = {0.0,
                          1.0 / 18.0,
                          1.0 / 12.0,
                          1.0 / 8.0,
                          5.0 / 16.0,
                          3.0 / 8.0,
                          59.0 / 400.0,
                          93.0 / 200.0,
                          5490023248.0 / 9719169821.0,
                          13.0 / 20.0,
                          1201146811.0 / 1299019798.0,
                          1.0,
                          1.0};
constexpr Term s2[] = {{0, 1.0 / 48.0}, {1, 1.0 / 16.0}};
constexpr Term s3[] = {{0, 1.0 / 32.0}, {2, 3.0 / 32.0}};
constexpr Term s4[] = {{0, 5.0 / 16.0}, {2, -75.0 / 64.0}, {3, 75.0 / 64.0}};
constexpr Term s5[] = {{0, 3.0 / 80.0}, {3, 3.0 / 16.0}, {4, 3.0 / 20.0}};
constexpr Term s6[] = {{0, 29443841.0 / 614563906.0},
                       {3, 77736538.0 / 692538347.0},
                       {4, -28693883.0 / 1125000000.0},
                       {5, 23124283.0 / 1800000000.0}};
constexpr Term s7[] = {{0, 16016141.0 / 946692911.0},
                       {3, 61564180.0 / 158732637.0},
                       {4, 22789713.0 / 633445777.0},
                       {5, 545815736.0 / 2771057229.0},
                       {6, -180193667.0 / 1043307555.0}};
constexpr Term s8[] = {{0, 39632708.0 / 573591083.0},    {3, -433636366.0 / 683701615.0},
                       {4, -421739975.0 / 2616292301.0}, {5, 100302831.0 / 723423059.0},
                       {6, 790204164.0 / 839813087.0},   {7, 800635310.0 / 3783071287.0}};
constexpr Term s9[] = {{0, 246121993.0 / 1340847787.0},  {3, -37695042795.0 / 15268766246.0},
                       {4, -309121744.0 / 1061227803.0}, {5, -12992083.0 / 490766935.0},
                       {6, 6005943493.0 / 2108947869.0}, {7, 393006217.0 / 1396673457.0},
                       {8, 123872331.0 / 1001029789.0}};
constexpr Term s10[] = {{0, -1028468189.0 / 846180014.0},   {3, 8478235783.0 / 508512852.0},
                        {4, 1311729495.0 / 1432422823.0},   {5, -10304129995.0 / 1701304382.0},
                        {6, -48777925059.0 / 3047939560.0}, {7, 15336726248.0 / 1032824649.0},
                        {8, -45442868181.0 / 3398467696.0}, {9, 3065993473.0 / 597172653.0}};
constexpr Term s11[] = {
    {0, 185892177.0 / 718116043.0},   {3, -3185094517.0 / 667107341.0}, {4, -477755414.0 / 1098053517.0},
    {5, -703635378.0 / 230739211.0},  {6, 5731566787.0 / 1027545527.0}, {7, 5232866602.0 / 850066563.0},
    {8, -4093664535.0 / 808688257.0}, {9, 3962137247.0 / 1805957418.0}, {10, 65686358.0 / 487910083.0}};
constexpr Term s12[] = {
    {0, 403863854.0 / 491063109.0},   {3, -5068492393.0 / 434740067.0}, {4, -411421997.0 / 543043805.0},
    {5, 652783627.0 / 914296604.0},   {6, 11173962825.0 / 925320556.0}, {7, -13158990841.0 / 6184727034.0},
    {8, 3936647629.0 / 1978049680.0}, {9, -160528059.0 / 685178525.0},  {10, 248638103.0 / 1413531060.0}};
// y + h sum_q a_q k_{j_q}, each component's sum in the order of j (as GSL's): the terms are compile-time
// constants, so the sum of every component stays in registers.
template <std::size_t N>
inline void combine(const Term (&terms)[N], const double* k, std::size_t n, const double* y, double h, double* out) {
  for (std::size_t i = 0; i < n; ++i) {
    double sum = terms[0].a * k[std::size_t(terms[0].j) * n + i];
    for (std::size_t q = 1; q < N; ++q) sum += terms[q].a * k[std::size_t(terms[q].j) * n + i];
    out[i] = y[i] + h * sum;
  }
}
constexpr double a10 = 1.0 / 18.0;
constexpr Term b[] = {
    {0, 14005451.0 / 335480064.0},   {5, -59238493.0 / 1068277825.0},   {6, 181606767.0 / 758867731.0},
    {7, 561292985.0 / 797845732.0},  {8, -1041891430.0 / 1371343529.0}, {9, 760417239.0 / 1151165299.0},
    {10, 118820643.0 / 751138087.0}, {11, -528747749.0 / 2220607170.0}, {12, 1.0 / 4.0}};
constexpr Term bhat[] = {{0, 13451932.0 / 455176623.0},     {5, -808719846.0 / 976000145.0},
                         {6, 1757004468.0 / 5645159321.0},  {7, 656045339.0 / 265891186.0},
                         {8, -3867574721.0 / 1518517206.0}, {9, 465885868.0 / 322736535.0},
                         {10, 53011238.0 / 667516719.0},    {11, 2.0 / 45.0}};
constexpr unsigned order = 8;
}  // namespace

PrinceDormand87::PrinceDormand87(std::size_t n, Rhs rhs, void* params, double atol, double rtol, CompactForm* form)
    : n_(n), rhs_(rhs), params_(params), atol_(atol), rtol_(rtol), form_(form), k_(13 * n), x0_(n), ytmp_(n), err_(n) {}

double PrinceDormand87::error_ratio(const double* x, const double* err) const {
  // max_k |e_k| / |D_k| from DBL_MIN up, a NaN ratio (0/0 with atol = 0) leaving the maximum as it is.
  double rmax = DBL_MIN;
  auto take = [&](double e, double y) {
    const double r = std::fabs(e) / std::fabs(rtol_ * std::fabs(y) + atol_);
    rmax = r > rmax ? r : rmax;
  };
  if (form_ == nullptr) {
    for (std::size_t i = 0; i < n_; ++i) take(err[i], x[i]);
  } else {
    const std::span<const double> xs(x, n_);
    for (std::size_t k = 0; k < form_->source.size(); ++k)
      take(form_->scale[k] * err[form_->source[k]], form_->y(k, xs));
  }
  return rmax;
}

int PrinceDormand87::apply(double& t, double t1, double& h, std::span<double> x) {
  const double t0 = t, dt = t1 - t0;
  double h0 = h;
  double* const y = x.data();
  double* const k = k_.data();
  double* const ytmp = ytmp_.data();
  std::memcpy(x0_.data(), y, n_ * sizeof(double));
  if (const int s = rhs_(t0, y, k, params_)) return s;
  if (form_ != nullptr) form_->center({k, n_});
  for (;;) {
    const bool final_step = h0 > dt;
    if (final_step) h0 = dt;
    int status = 0;
    for (int s = 1; s < 13 && status == 0; ++s) {
      switch (s) {
        case 1: {
          const double ah = a10 * h0;
          for (std::size_t i = 0; i < n_; ++i) ytmp[i] = y[i] + ah * k[i];
          break;
        }
        case 2:
          combine(s2, k, n_, y, h0, ytmp);
          break;
        case 3:
          combine(s3, k, n_, y, h0, ytmp);
          break;
        case 4:
          combine(s4, k, n_, y, h0, ytmp);
          break;
        case 5:
          combine(s5, k, n_, y, h0, ytmp);
          break;
        case 6:
          combine(s6, k, n_, y, h0, ytmp);
          break;
        case 7:
          combine(s7, k, n_, y, h0, ytmp);
          break;
        case 8:
          combine(s8, k, n_, y, h0, ytmp);
          break;
        case 9:
          combine(s9, k, n_, y, h0, ytmp);
          break;
        case 10:
          combine(s10, k, n_, y, h0, ytmp);
          break;
        case 11:
          combine(s11, k, n_, y, h0, ytmp);
          break;
        default:
          combine(s12, k, n_, y, h0, ytmp);
          break;
      }
      // The last two nodes are 1: t0 + h0 exactly.
      status = rhs_(s >= 11 ? t0 + h0 : t0 + c[s] * h0, ytmp, k + std::size_t(s) * n_, params_);
    }
    if (status != 0) {
      // The right-hand side failed at a trial state: halve h while that changes t by at least one ulp.
      const double h_old = h0;
      h0 *= 0.5;
      if (std::fabs(h0) < std::fabs(h_old) && t0 + h0 != t0) {
        ++failed_;
        continue;
      }
      h = h0;
      t = t0;
      return status;
    }
    for (std::size_t i = 0; i < n_; ++i) {
      double s8 = b[0].a * k[i], s7 = bhat[0].a * k[i];
      for (std::size_t q = 1; q < std::size(b); ++q) s8 += b[q].a * k[std::size_t(b[q].j) * n_ + i];
      for (std::size_t q = 1; q < std::size(bhat); ++q) s7 += bhat[q].a * k[std::size_t(bhat[q].j) * n_ + i];
      y[i] += h0 * s8;
      err_[i] = h0 * (s7 - s8);
    }
    const double t_new = final_step ? t1 : t0 + h0;
    const double h_old = h0;
    const double rmax = error_ratio(y, err_.data());
    if (rmax > 1.1) {
      double r = 0.9 / std::pow(rmax, 1.0 / order);
      if (r < 0.2) r = 0.2;
      h0 = r * h_old;
      if (std::fabs(h0) < std::fabs(h_old) && t_new + h0 != t_new) {
        std::memcpy(y, x0_.data(), n_ * sizeof(double));
        ++failed_;
        continue;
      }
      h = h0;
      t = t_new;
      return -1;
    }
    if (rmax < 0.5) {
      double r = 0.9 / std::pow(rmax, 1.0 / (order + 1.0));
      r = std::clamp(r, 1.0, 5.0);
      h0 = r * h_old;
    }
    if (!final_step) h = h0;
    t = t_new;
    return 0;
  }
}

}  // namespace rbcstab::detail
