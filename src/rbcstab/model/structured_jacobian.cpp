#include "rbcstab/model/structured_jacobian.hpp"

#include <algorithm>
#include <cmath>

namespace rbcstab {

void StructuredJacobian::resize(std::size_t n) {
  block_start.assign(n, 1);
  diag.assign(n, 0.0);
  upper.assign(n, 0.0);
  lower.assign(n, 0.0);
  v.assign(n, 0.0);
  w.assign(n, 0.0);
}

void StructuredJacobian::to_dense(std::span<double> out) const {
  const std::size_t n = size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = 0; j < n; ++j) out[i * n + j] = v[i] * w[j];
  for (std::size_t i = 0; i < n; ++i) {
    out[i * n + i] += diag[i];
    if (block_start[i] == 2) {
      out[i * n + i + 1] += upper[i];
      out[(i + 1) * n + i] += lower[i];
    }
  }
}

void StructuredJacobian::apply(std::span<const double> x, std::span<double> y) const {
  const std::size_t n = size();
  double wx = 0;
  for (std::size_t i = 0; i < n; ++i) wx += w[i] * x[i];
  for (std::size_t i = 0; i < n; ++i) y[i] = diag[i] * x[i] + v[i] * wx;
  for (std::size_t i = 0; i < n; ++i)
    if (block_start[i] == 2) {
      y[i] += upper[i] * x[i + 1];
      y[i + 1] += lower[i] * x[i];
    }
}

namespace {
// Solves (I - c M) x = b block by block.
bool solve_block_diagonal(const StructuredJacobian& J, double c, std::span<const double> b, std::span<double> x) {
  const std::size_t n = J.size();
  for (std::size_t i = 0; i < n;) {
    if (J.block_start[i] == 2) {
      const double a11 = 1 - c * J.diag[i], a12 = -c * J.upper[i];
      const double a21 = -c * J.lower[i], a22 = 1 - c * J.diag[i + 1];
      const double det = a11 * a22 - a12 * a21;
      const double scale = std::max({std::abs(a11 * a22), std::abs(a12 * a21), 1e-300});
      if (!(std::abs(det) > 1e-14 * scale)) return false;
      x[i] = (a22 * b[i] - a12 * b[i + 1]) / det;
      x[i + 1] = (a11 * b[i + 1] - a21 * b[i]) / det;
      i += 2;
    } else {
      const double a = 1 - c * J.diag[i];
      if (!(std::abs(a) > 1e-14 * std::max(1.0, std::abs(c * J.diag[i])))) return false;
      x[i] = b[i] / a;
      i += 1;
    }
  }
  return true;
}
}  // namespace

bool StructuredJacobian::solve_shifted(double c, std::span<const double> b, std::span<double> x) const {
  // (A - c v w^T) x = b with A = I - c M:  x = A^-1 b + c A^-1 v (w^T A^-1 b) / (1 - c w^T A^-1 v).
  const std::size_t n = size();
  std::vector<double> z(n);
  if (!solve_block_diagonal(*this, c, b, x) || !solve_block_diagonal(*this, c, v, z)) return false;
  double wx = 0, wz = 0, wscale = 0;
  for (std::size_t i = 0; i < n; ++i) {
    wx += w[i] * x[i];
    wz += w[i] * z[i];
    wscale += std::abs(w[i] * z[i]);
  }
  const double denom = 1 - c * wz;
  if (!(std::abs(denom) > 1e-14 * std::max(1.0, std::abs(c) * wscale))) return false;
  const double factor = c * wx / denom;
  for (std::size_t i = 0; i < n; ++i) x[i] += factor * z[i];
  return std::all_of(x.begin(), x.end(), [](double value) { return std::isfinite(value); });
}

}  // namespace rbcstab
