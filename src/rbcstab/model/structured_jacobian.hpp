#pragma once
// J = M + v w^T with M block diagonal: block[i] is 1 (a 1x1 block at i) or 2 (a 2x2 block at i, i+1).
// Shifted solves (I - c J) x = b cost O(n) by Sherman-Morrison.
#include <cstddef>
#include <span>
#include <vector>

namespace rbcstab {

struct StructuredJacobian {
  std::vector<int> block_start;  // size of the block starting at i (1 or 2), 0 inside a 2x2 block
  std::vector<double> diag;      // M(i, i)
  std::vector<double> upper;     // M(i, i+1) for a 2x2 block starting at i
  std::vector<double> lower;     // M(i+1, i) for a 2x2 block starting at i
  std::vector<double> v, w;      // rank-one part v w^T

  void resize(std::size_t n);
  std::size_t size() const { return diag.size(); }
  // Dense row-major n x n copy (for GSL's implicit steppers and for checks).
  void to_dense(std::span<double> out) const;
  // y = J x
  void apply(std::span<const double> x, std::span<double> y) const;
  // Solves (I - c J) x = b. Returns false if the shifted matrix is singular to working precision.
  bool solve_shifted(double c, std::span<const double> b, std::span<double> x) const;
};

}  // namespace rbcstab
