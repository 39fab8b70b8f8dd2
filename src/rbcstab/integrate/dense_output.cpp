#include "rbcstab/integrate/dense_output.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

DenseOutput::DenseOutput(std::size_t columns, std::vector<double> t, std::vector<double> values,
                         std::vector<std::size_t> segment_starts)
    : columns_(columns), t_(std::move(t)), values_(std::move(values)), segment_starts_(std::move(segment_starts)) {
  if (values_.size() != t_.size() * columns_)
    throw InvalidArgument("values", "values has " + std::to_string(values_.size()) + " entries, expected " +
                                        std::to_string(t_.size()) + " times " + std::to_string(columns_) + " columns");
  if (segment_starts_.empty() || segment_starts_.front() != 0 ||
      !std::is_sorted(segment_starts_.begin(), segment_starts_.end()) || segment_starts_.back() > t_.size())
    throw InvalidArgument("segment_starts", "segment_starts must start at 0 and increase up to the point count");
  for (std::size_t k = 1; k < t_.size(); ++k)
    if (!(t_[k] >= t_[k - 1]))
      throw InvalidArgument("t", "t must be finite and increasing (t[" + std::to_string(k) + "])");
}

void DenseOutput::add(double t, const std::vector<double>& values) {
  if (values.size() != columns_)
    throw InvalidArgument("values",
                          std::to_string(values.size()) + " values for " + std::to_string(columns_) + " columns");
  // A repeated time (a grid stop reported twice) adds nothing; the interpolation needs distinct nodes.
  if (!t_.empty() && t_.size() > segment_starts_.back() && !(t > t_.back())) return;
  t_.push_back(t);
  values_.insert(values_.end(), values.begin(), values.end());
}

std::vector<double> DenseOutput::operator()(double t) const {
  std::vector<double> out(columns_, std::numeric_limits<double>::quiet_NaN());
  // The segment holding t: [t of its first point, t of its last].
  for (std::size_t s = 0; s < segment_starts_.size(); ++s) {
    const std::size_t a = segment_starts_[s], b = s + 1 < segment_starts_.size() ? segment_starts_[s + 1] : t_.size();
    if (b <= a || !(t >= t_[a] && t <= t_[b - 1])) continue;
    // The interval [t_i, t_i+1] holding t, and kDenseNodes nodes centred on it within the segment.
    const auto i =
        std::size_t(std::upper_bound(t_.begin() + std::ptrdiff_t(a), t_.begin() + std::ptrdiff_t(b), t) - t_.begin());
    if (i > a && t_[i - 1] == t) {
      std::copy_n(values_.begin() + std::ptrdiff_t((i - 1) * columns_), columns_, out.begin());
      return out;
    }
    const std::size_t n = std::min(kDenseNodes, b - a);
    const std::size_t lo = std::clamp(i >= n / 2 ? i - n / 2 : std::size_t{0}, a, b - n);
    // Lagrange weights at t.
    std::vector<double> w(n, 1.0);
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t m = 0; m < n; ++m)
        if (m != j) w[j] *= (t - t_[lo + m]) / (t_[lo + j] - t_[lo + m]);
    std::fill(out.begin(), out.end(), 0.0);
    for (std::size_t j = 0; j < n; ++j)
      for (std::size_t c = 0; c < columns_; ++c) out[c] += w[j] * values_[(lo + j) * columns_ + c];
    return out;
  }
  return out;
}

}  // namespace rbcstab
