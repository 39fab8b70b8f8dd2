#include "rbcstab/io/simulation_io.hpp"

#include <iomanip>
#include <sstream>
#include <string>

#include "rbcstab/core/text.hpp"
#include "rbcstab/io/json.hpp"

namespace rbcstab {

nlohmann::json simulation_json(const SceneFile& file, const SimulationResult& r) {
  nlohmann::json j = to_json(r, file.scene.parameters);
  j["parameters"] = to_json(file.scene.parameters);
  j["reason"] = run_reason(r, file.scene.parameters);
  j["stepper"] = to_string(file.options.integrator.stepper);
  j["rtol"] = file.options.integrator.rtol;
  j["atol"] = file.options.integrator.atol;
  put_truncation(j, file);
  put_physical(j, file.scene);
  return j;
}

std::string simulation_text(const SceneFile& file, const SimulationResult& r) {
  TextStream out;
  out << std::setprecision(6) << "model " << to_string(r.level.level) << ", status " << to_string(r.status)
      << ", l_Delta = " << r.l_Delta << ", sigma(T) = " << r.sigma_final << ", drift = " << r.excess_area_drift
      << ", steps = " << r.counters.steps << "\n"
      << file.L_reason << "\n";
  if (file.scene.physical)
    out << "time unit 1/gamma = " << 1 / file.scene.physical->shear_rate << " s: T = " << file.scene.T << " is "
        << file.scene.T / file.scene.physical->shear_rate << " s\n";
  if (r.early.terminated)
    out << "terminated early at t = " << r.early.terminated_at << " on a certified " << r.early.kind
        << " (margin 1 - max |mu| = " << r.early.margin << "), resumed at t = " << r.early.resumed_at
        << (r.trajectory.rows() == 0 ? std::string()
                                     : ": " + std::to_string(r.trajectory.integrated_count()) + " of " +
                                           std::to_string(r.trajectory.rows()) + " samples integrated")
        << "\n";
  return out.str();
}

std::string trajectory_csv(const SimulationResult& r) {
  std::ostringstream ss;
  ss << "t";
  for (int l = 2; l <= r.L; ++l) ss << ",Delta_" << l;
  ss << ",sigma,r,Psi,integrated\n";
  const Trajectory& tr = r.trajectory;
  const std::string skipped_fields(std::size_t(r.L) + 3, ',');  // Delta_2..Delta_L, sigma, r, Psi empty; then 0
  for (std::size_t row = 0; row < tr.rows(); ++row) {
    ss << csv_number(tr.time(row));
    if (!tr.integrated(row)) {
      ss << skipped_fields << "0\n";
      continue;
    }
    const std::size_t k = tr.sample(row);
    for (double d : tr.Delta_l[k]) ss << ',' << csv_number(d);
    ss << ',' << csv_number(tr.sigma[k]) << ',' << csv_number(tr.r[k]) << ',' << csv_number(tr.Psi[k]) << ",1\n";
  }
  return ss.str();
}

}  // namespace rbcstab
