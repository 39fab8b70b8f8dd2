#include "rbcstab/continuation/floquet_io.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "rbcstab/core/text.hpp"
#include "rbcstab/io/json.hpp"

namespace rbcstab {

nlohmann::json floquet_json(const Scene& scene, const SceneFloquetOptions& options, const SceneFloquetResult& r) {
  const Eigen::VectorXcd& mu = r.floquet.arpack.eigenvalues;
  nlohmann::json j;
  j["status"] = to_string(r.status);
  if (!r.message.empty()) j["message"] = r.message;
  j["parameters"] = to_json(scene.parameters);
  j["beta"] = scene.beta;
  j["n"] = r.dimension;
  j["relax_level"] = to_string(r.relax_level);
  j["relax_periods"] = options.relax_periods;
  j["t0"] = r.t0;
  j["period"] = r.period;
  j["periodicity_defect"] = number_or_null(r.periodicity_defect);
  j["stepper"] = to_string(r.stepper);
  j["integrations"] = r.floquet.integrations;
  j["steps"] = r.floquet.counters.steps;
  nlohmann::json list = nlohmann::json::array();
  for (Eigen::Index i = 0; i < mu.size(); ++i)
    list.push_back({{"re", number_or_null(mu(i).real())},
                    {"im", number_or_null(mu(i).imag())},
                    {"abs", number_or_null(std::abs(mu(i)))}});
  j["multipliers"] = list;
  explain_nulls(j, r.message.empty() ? nonfinite_reason(scene.parameters)
                                     : "not computed: " + to_string(r.status) + ": " + r.message);
  return j;
}

std::string floquet_text(const Scene& scene, const SceneFloquetOptions& options, const SceneFloquetResult& r) {
  const Eigen::VectorXcd& mu = r.floquet.arpack.eigenvalues;
  TextStream out;
  out << std::setprecision(8) << "full model L = " << scene.L << " (n = " << r.dimension << "), relaxed "
      << options.relax_periods << " periods at the " << to_string(r.relax_level) << " level, period " << r.period
      << ", periodicity defect " << r.periodicity_defect << ", " << to_string(r.stepper) << ", "
      << r.floquet.integrations << " actions: " << to_string(r.status) << "\n";
  for (Eigen::Index i = 0; i < mu.size(); ++i)
    out << "  mu = " << mu(i).real() << (mu(i).imag() < 0 ? " - " : " + ") << std::abs(mu(i).imag())
        << "i  |mu| = " << std::abs(mu(i)) << "\n";
  return out.str();
}

}  // namespace rbcstab
