// Uses the installed headers and libraries across modules (model, integrate with GSL, io with JSON).
#include <cmath>
#include <iostream>

#include "rbcstab/integrate/simulation.hpp"
#include "rbcstab/io/json.hpp"
#include "rbcstab/model/coefficients.hpp"

int main() {
  rbcstab::Scene scene;  // the paper's Fig. 3 scene
  scene.T = 20;
  const rbcstab::SimulationResult r = rbcstab::simulate(scene);
  const auto j = rbcstab::to_json(r);
  const bool ok = r.status == rbcstab::IntegrationStatus::success && j["model"] == "modal" &&
                  std::abs(rbcstab::d_lambda_l(5.0, 2) - 147.0) < 1e-12 && std::isfinite(r.sigma_final);
  if (!ok) {
    std::cerr << "unexpected result: " << j.dump() << "\n";
    return 1;
  }
  std::cout << "rbcstab consumer ok: model " << j["model"].get<std::string>() << ", sigma(T) = " << r.sigma_final
            << "\n";
  return 0;
}
