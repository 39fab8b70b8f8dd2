#include "rbcstab/io/work_precision_io.hpp"

#include <iomanip>
#include <limits>
#include <sstream>

#include "rbcstab/core/text.hpp"
#include "rbcstab/io/json.hpp"

namespace rbcstab {

std::string work_precision_csv(const WorkPrecisionTable& t) {
  std::ostringstream ss;
  ss << std::setprecision(10);
  ss << "level,stepper,rtol,status,rhs_evaluations,jacobian_evaluations,steps,seconds,error_Delta,error_sigma,l_Delta,"
        "verdict_changed\n";
  for (const auto& r : t.rows)
    ss << to_string(r.level) << ',' << to_string(r.stepper) << ',' << csv_number(r.rtol) << ',' << to_string(r.status)
       << ',' << r.rhs_evaluations << ',' << r.jacobian_evaluations << ',' << r.steps << ',' << csv_number(r.seconds)
       << ',' << csv_number(r.error_Delta) << ',' << csv_number(r.error_sigma) << ',' << r.l_Delta << ','
       << (r.verdict_changed ? 1 : 0) << '\n';
  return ss.str();
}

nlohmann::json work_precision_json(const SceneFile& file, const WorkPrecisionTable& t) {
  const Parameters& p = file.scene.parameters;
  const bool reference_ok = t.reference_status == IntegrationStatus::success;
  const double none = std::numeric_limits<double>::quiet_NaN();
  nlohmann::json ref{{"level", "full"},
                     {"stepper", "rk8pd"},
                     {"rtol", t.reference_rtol},
                     {"status", to_string(t.reference_status)},
                     {"reason", t.reference_reason},
                     {"Delta_final", by_mode(t.reference_Delta)},
                     {"l_Delta", t.reference_l_Delta}};
  const std::string ref_reason = row_reason(t.reference_status, t.reference_reason, p);
  put_number(ref, "sigma_final", reference_ok ? t.reference_sigma : none, ref_reason);
  put_number(ref, "spread_vs_modal", reference_ok ? t.reference_spread : none, ref_reason);
  explain_nulls(ref, ref_reason);
  nlohmann::json j{{"scene", to_json(file.scene)}, {"reference", ref}, {"rows", nlohmann::json::array()}};
  for (const auto& r : t.rows) {
    nlohmann::json row{{"level", to_string(r.level)},
                       {"stepper", to_string(r.stepper)},
                       {"rtol", r.rtol},
                       {"status", to_string(r.status)},
                       {"rhs_evaluations", r.rhs_evaluations},
                       {"jacobian_evaluations", r.jacobian_evaluations},
                       {"steps", r.steps},
                       {"seconds", r.seconds},
                       {"l_Delta", r.l_Delta},
                       {"verdict_changed", r.verdict_changed}};
    const std::string why = row_reason(r.status, r.reason, p);
    put_number(row, "error_Delta", r.error_Delta, why);
    put_number(row, "error_sigma", r.error_sigma, why);
    j["rows"].push_back(row);
  }
  put_truncation(j, file);
  return j;
}

std::string work_precision_text(const WorkPrecisionTable& t) {
  TextStream s;
  s << "scene " << t.scene_name << ": reference full/rk8pd rtol " << t.reference_rtol
    << ", l_Delta = " << t.reference_l_Delta << ", spread vs modal " << t.reference_spread << "\n";
  s << std::setw(8) << "level" << std::setw(12) << "stepper" << std::setw(8) << "rtol" << std::setw(12) << "RHS evals"
    << std::setw(10) << "Jac" << std::setw(11) << "seconds" << std::setw(12) << "err Delta" << std::setw(12)
    << "err sigma"
    << "  l_Delta\n";
  for (const auto& r : t.rows)
    s << std::setw(8) << to_string(r.level) << std::setw(12) << to_string(r.stepper) << std::setw(8)
      << std::setprecision(0) << std::scientific << r.rtol << std::defaultfloat << std::setprecision(4) << std::setw(12)
      << r.rhs_evaluations << std::setw(10) << r.jacobian_evaluations << std::setw(11) << r.seconds << std::setw(12)
      << r.error_Delta << std::setw(12) << r.error_sigma << "  " << r.l_Delta << (r.verdict_changed ? " (changed)" : "")
      << (r.status != IntegrationStatus::success ? "  " + to_string(r.status) : "") << "\n";
  return s.str();
}

}  // namespace rbcstab
