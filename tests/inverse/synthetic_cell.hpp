#pragma once
// A synthetic cell and its observations, made by the forward model itself with noise from a fixed seed.
#include <algorithm>
#include <random>
#include <string>
#include <vector>

#include "rbcstab/inverse/fit.hpp"
#include "rbcstab/inverse/forward.hpp"

namespace rbcstab {

// Lambda = 0.6 (lambda = 5, Delta = 0.1): swinging exists; S = 1.6 at 150 1/s and 1 mPa s.
inline CellModel synthetic_cell() {
  CellModel c;
  c.bending_modulus = 2e-19;
  c.shear_modulus = 6e-6;
  c.radius = 2.8e-6;
  c.lambda = 5;
  c.Delta = 0.1;
  c.Delta0 = 0.05;
  return c;
}

// Inclination angle and swinging amplitude at two shear rates and two viscosities, each with an uncertainty of
// 0.5 degree; noise: `noise` times the uncertainty times a standard normal draw from `seed`.
inline ObservationData synthetic_data(const CellModel& truth, double noise, unsigned seed) {
  ObservationData d;
  d.path = "synthetic";
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  const double sigma = 0.5 * 3.141592653589793 / 180;
  int line = 2;
  for (double viscosity : {1e-3, 2e-3})
    for (double rate : {150.0, 600.0})
      for (Observable o : {Observable::inclination_angle, Observable::swinging_amplitude}) {
        ObservedRow row;
        row.line = line++;
        row.observable = o;
        row.shear_rate = rate;
        row.viscosity = viscosity;
        row.unit = "rad";
        row.uncertainty = sigma;
        const Prediction p = predict(truth, row);
        row.value = p.value + noise * sigma * normal(rng);
        d.rows.push_back(row);
      }
  return d;
}

// The rows at the first viscosity (1 mPa s) only: four rows at two conditions, for the tests that need a fit but
// not its statistics (a fit of lambda alone in well under a second).
inline ObservationData one_viscosity(ObservationData d) {
  std::erase_if(d.rows, [&](const ObservedRow& r) { return r.viscosity != d.rows.front().viscosity; });
  return d;
}

// Delta chi^2 of the profile at coordinate x (exactly a recorded point).
inline double profile_at(const Profile& p, double x) {
  for (std::size_t k = 0; k < p.coordinate.size(); ++k)
    if (std::abs(p.coordinate[k] - x) < 1e-12) return p.delta_chi2[k];
  return kNotGiven;
}

// Largest |a - b| over the largest |b| of each column (a column's scale is its parameter's).
inline double column_gap(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b) {
  double worst = 0;
  for (std::size_t j = 0; j < b.front().size(); ++j) {
    double scale = 0, gap = 0;
    for (std::size_t i = 0; i < b.size(); ++i) {
      scale = std::max(scale, std::abs(b[i][j]));
      gap = std::max(gap, std::abs(a[i][j] - b[i][j]));
    }
    worst = std::max(worst, gap / scale);
  }
  return worst;
}

struct SensitivityCase {
  CellModel cell;
  ObservationData data;
  std::vector<FitParameter> free;
};

inline std::vector<SensitivityCase> sensitivity_cases() {
  std::vector<SensitivityCase> out;
  // The synthetic cell (Lambda = 0.6, S = 1.6 to 13): mu and lambda free.
  out.push_back({synthetic_cell(),
                 synthetic_data(synthetic_cell(), 0.0, 1),
                 {FitParameter::shear_modulus, FitParameter::lambda}});
  // Another cell with the inner viscosity given (lambda changes with eta), and Delta and Delta0 free.
  CellModel c = synthetic_cell();
  c.inner_viscosity = 4e-3;
  c.Delta = 0.3;
  c.Delta0 = 0.1;
  c.shear_modulus = 3e-6;
  ObservationData d = synthetic_data(c, 0.0, 2);
  std::rotate(d.rows.begin(), d.rows.begin() + 6, d.rows.end());  // first: 600 1/s at 2 mPa s
  out.push_back(
      {c, d, {FitParameter::inner_viscosity, FitParameter::Delta, FitParameter::Delta0, FitParameter::radius}});
  return out;
}

}  // namespace rbcstab
