#include <algorithm>
#include <cmath>
#include <limits>

#include "rbcstab/inverse/detail/profile_refit.hpp"

namespace rbcstab::detail {

CellModel cell_at(const CellModel& base, std::span<const FitParameterInfo> info, std::span<const double> x) {
  CellModel c = base;
  for (std::size_t j = 0; j < info.size(); ++j) set_value(c, info[j].id, info[j].log_scale ? std::exp(x[j]) : x[j]);
  return c;
}

bool residuals_at(std::span<const ObservedRow> rows, const CellModel& cell, const ForwardOptions& options,
                  std::vector<double>& r, std::string& reason) {
  r.clear();
  std::vector<Prediction> p;
  try {
    cell.validate();
    p = predict_all(cell, rows, options);
  } catch (const InvalidArgument& e) {
    reason = e.what();
    return false;
  }
  for (std::size_t i = 0; i < rows.size(); ++i) {
    if (!p[i].ok()) {
      reason = "line " + std::to_string(rows[i].line) + ": " + p[i].reason;
      return false;
    }
    r.push_back((p[i].value - rows[i].value) / rows[i].uncertainty);
  }
  return true;
}

namespace {

// Solves the symmetric positive definite a x = b in place by Cholesky (n <= a few); false when not positive definite.
bool refit_cholesky_solve(std::vector<std::vector<double>> a, std::vector<double>& b) {
  const std::size_t n = b.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < i; ++k) a[i][i] -= a[i][k] * a[i][k];
    if (!(a[i][i] > 0)) return false;
    a[i][i] = std::sqrt(a[i][i]);
    for (std::size_t j = i + 1; j < n; ++j) {
      for (std::size_t k = 0; k < i; ++k) a[j][i] -= a[j][k] * a[i][k];
      a[j][i] /= a[i][i];
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t k = 0; k < i; ++k) b[i] -= a[i][k] * b[k];
    b[i] /= a[i][i];
  }
  for (std::size_t i = n; i-- > 0;) {
    for (std::size_t k = i + 1; k < n; ++k) b[i] -= a[k][i] * b[k];
    b[i] /= a[i][i];
  }
  return true;
}

// (A + mu (diag A + floor)) d = -g; empty when the system is singular.
std::vector<double> refit_damped_step(const std::vector<std::vector<double>>& A, const std::vector<double>& g,
                                      double mu, double floor) {
  std::vector<std::vector<double>> m = A;
  std::vector<double> d(g.size());
  for (std::size_t i = 0; i < g.size(); ++i) {
    m[i][i] += mu * (A[i][i] + floor) + floor * 1e-12;
    d[i] = -g[i];
  }
  if (!refit_cholesky_solve(m, d)) return {};
  return d;
}

double refit_chi2(std::span<const double> r) {
  double c = 0;
  for (double v : r) c += v * v;
  return c;
}

}  // namespace

LeastSquaresRefit least_squares_refit(std::span<const ObservedRow> rows, std::span<const FitParameter> free,
                                      const CellModel& cell, const FitOptions& options, std::vector<double> start,
                                      int held, std::span<const double> lo, std::span<const double> hi,
                                      const std::function<bool()>& keep_going) {
  LeastSquaresRefit out;
  out.x = std::move(start);
  std::vector<FitParameterInfo> info;
  for (FitParameter q : free) info.push_back(fit_parameter_info(q, cell));
  // The Jacobian of the re-fitted coordinates only (the held one is the cell's value): a column fewer to compute.
  std::vector<FitParameter> sub;
  std::vector<std::size_t> cols;
  for (std::size_t k = 0; k < free.size(); ++k)
    if (static_cast<int>(k) != held) sub.push_back(free[k]), cols.push_back(k);
  auto linearise_at = [&](const std::vector<double>& x) {
    ++out.evaluations;
    return linearise(rows, sub, cell_at(cell, info, x), options, options.fd_step);
  };
  Linearisation lin = linearise_at(out.x);
  if (!lin.ok) {
    out.reason = lin.reason;
    return out;
  }
  out.chi2 = refit_chi2(lin.r);
  double mu = 1e-3;
  for (int it = 0; it < options.max_iterations; ++it) {
    if (keep_going && !keep_going()) {
      out.reason = "interrupted";
      return out;
    }
    ++out.iterations;
    // Half the gradient of chi^2 and the Gauss-Newton matrix over the coordinates free to move: one at a bound with
    // the gradient pushing it outward stays there.
    std::vector<std::size_t> act;  // indices into sub
    std::vector<double> g;
    for (std::size_t c = 0; c < sub.size(); ++c) {
      double gc = 0;
      for (std::size_t i = 0; i < lin.r.size(); ++i) gc += lin.J[i][c] * lin.r[i];
      const std::size_t k = cols[c];
      const double tol = 1e-12 * (1 + std::abs(out.x[k]));
      if ((out.x[k] <= lo[k] + tol && gc > 0) || (out.x[k] >= hi[k] - tol && gc < 0)) continue;
      act.push_back(c);
      g.push_back(gc);
    }
    if (act.empty()) {
      out.converged = true;
      return out;
    }
    std::vector<std::vector<double>> A(act.size(), std::vector<double>(act.size(), 0.0));
    double diag_max = 0;
    for (std::size_t a = 0; a < act.size(); ++a) {
      for (std::size_t b = 0; b < act.size(); ++b)
        for (std::size_t i = 0; i < lin.r.size(); ++i) A[a][b] += lin.J[i][act[a]] * lin.J[i][act[b]];
      diag_max = std::max(diag_max, A[a][a]);
    }
    const double floor = 1e-12 * std::max(diag_max, std::numeric_limits<double>::min());
    // The chi^2 decrease the undamped Gauss-Newton step predicts, g^T A^-1 g (quadratic model of |r + J d|^2):
    // below 1e-9 max(chi^2, 1) the point's chi^2 is the minimum's to far less than the 1e-3 the profile resolves.
    const std::vector<double> gn = refit_damped_step(A, g, 0.0, floor);
    double predicted = std::numeric_limits<double>::infinity();
    if (!gn.empty()) {
      predicted = 0;
      for (std::size_t a = 0; a < act.size(); ++a) predicted -= g[a] * gn[a];
    }
    if (predicted <= 1e-9 * std::max(out.chi2, 1.0)) {
      out.converged = true;
      return out;
    }
    bool accepted = false;
    while (!accepted) {
      const std::vector<double> d = mu == 0 ? gn : refit_damped_step(A, g, mu, floor);
      if (d.empty() || mu > 1e10) {
        out.reason = "Levenberg-Marquardt: no decrease of chi^2 at damping " + std::to_string(mu);
        return out;
      }
      std::vector<double> xn = out.x;
      double moved = 0;
      for (std::size_t a = 0; a < act.size(); ++a) {
        const std::size_t k = cols[act[a]];
        xn[k] = std::clamp(out.x[k] + d[a], lo[k], hi[k]);
        moved = std::max(moved, std::abs(xn[k] - out.x[k]));
      }
      std::vector<double> r;
      std::string why;
      ++out.evaluations;
      if (residuals_at(rows, cell_at(cell, info, xn), options.forward, r, why) && refit_chi2(r) < out.chi2) {
        const double decrease = out.chi2 - refit_chi2(r);
        out.x = xn;
        lin = linearise_at(out.x);
        if (!lin.ok) {
          out.reason = lin.reason;
          return out;
        }
        out.chi2 = refit_chi2(lin.r);
        mu = std::max(mu / 3, 1e-9);
        accepted = true;
        // A step that changes nothing any longer (coordinates to 1e-10, chi^2 to 1e-12 relative): the noise floor
        // of the predictions, where the quadratic model's test above may never pass.
        if (moved < 1e-10 && decrease < 1e-12 * std::max(out.chi2, 1.0)) {
          out.converged = true;
          return out;
        }
      } else {
        mu *= 4;
      }
    }
  }
  out.reason = "Levenberg-Marquardt: " + std::to_string(options.max_iterations) + " iterations";
  return out;
}

}  // namespace rbcstab::detail
