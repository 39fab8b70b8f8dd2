#pragma once
// Dense output of a run: the observables at every accepted step, and their value at any time between steps
// by local polynomial interpolation of degree kDenseNodes - 1 through the nearest accepted steps of the same
// integrated segment. Its error, ~ h^8 |y^(8)| (0.5 1.5 2.5 3.5)^2 / 8! on steps of size h, is of rk8pd's order
// (it falls as rtol^(8/9)) but with a larger constant than the integrator's local error: measured ~5e3 rtol
// in Delta_l and ~5e4 rtol relative in sigma at rtol 1e-10 on Fig. 3 (test SimulationOutput.DenseOutput*).
// Samples at the integrator's own error: SimulationOptions::t_eval.
#include <cstddef>
#include <vector>

namespace rbcstab {

constexpr std::size_t kDenseNodes = 8;

class DenseOutput {
 public:
  DenseOutput() = default;
  explicit DenseOutput(std::size_t columns) : columns_(columns) {}
  // Rebuilt from its parts (the Python module pickles it): throws InvalidArgument on inconsistent sizes.
  DenseOutput(std::size_t columns, std::vector<double> t, std::vector<double> values,
              std::vector<std::size_t> segment_starts);

  // A new integrated segment starts at the next point (the run resumed after a certified skip).
  void start_segment() { segment_starts_.push_back(t_.size()); }
  // The observables at an accepted step: t after the last one of its segment, `columns` values.
  void add(double t, const std::vector<double>& values);

  std::size_t columns() const { return columns_; }
  const std::vector<double>& t() const { return t_; }
  const std::vector<double>& values() const { return values_; }  // [point * columns + column]
  const std::vector<std::size_t>& segment_starts() const { return segment_starts_; }
  bool empty() const { return t_.empty(); }

  // The interpolated observables at t; NaN outside the integrated segments (a certified skip, or beyond the
  // run's ends). A point of the run is returned exactly.
  std::vector<double> operator()(double t) const;

 private:
  std::size_t columns_ = 0;
  std::vector<double> t_, values_;
  std::vector<std::size_t> segment_starts_{0};
};

}  // namespace rbcstab
