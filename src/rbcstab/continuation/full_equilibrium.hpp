#pragma once
// Equilibria of the full model level (Eqs. eom, st; docs/theory.md) as a continuation
// problem in any ContinuationParameter. Needed when the stress-free shape has l >= 3 content
// (Scene::rest_delta_l), which only the full level holds; otherwise the modal problem is exact.
//
// Coordinates: the independent real coordinates of a real shape, scaled by the total excess area
// Delta so that the area constraint is the unit sphere. FullModel stores f_{l,m} for every m, but a
// real shape obeys f_{l,-m} = (-1)^m conj f_{l,m}; per l the unknowns are
//   x_{l,0} = sqrt(a_l/Delta) f_{l,0}  (real),   x_{l,m} = sqrt(2 a_l/Delta) (Re f_{l,m}, Im f_{l,m}), m = 1..l,
// 2l + 1 reals per l, n = (L+1)^2 - 4 in all, and |x|^2 = sum_l Delta_l / Delta (the map is an
// isometry from the area inner product). For l = 2 these are the modal coordinates: x_{2,2} = z,
// x_{2,0} = -w, x_{2,1} = v.
// Why not all 2((L+1)^2 - 4) stored reals: the real shapes are an invariant subspace of the flow and
// its complement (i times a real shape) carries a copy of the same linear spectrum (Upsilon_l +- i m/2),
// so at Upsilon_l(sigma) = 0 the m = 0 eigenvalue would be double: the branch point test function
// det[J F_p; t^T] would not change sign and the kernel would be 2-D for a simple pitchfork.
//
// F(x) = R F_full(E x) with E the embedding x -> FullModel state and R its left inverse (the
// projection onto real shapes), so every equation is FullModel's (sigma, Upsilon, drive): nothing is
// re-coded. x.F = 0 identically (area conservation), Newton solves G = F + (|x|^2 - 1) x and stability
// is DF on x^perp (detail/sphere_constraint.hpp, shared with the reduced and modal problems).
// DF = R J E with J = M + v w^T FullModel's structured Jacobian, assembled in O(n^2). The spectrum is
// block triangular: blocks (l, m) where x = 0 contribute Upsilon_l +- i m/2 exactly, only the blocks
// holding x go through a dense eigensolver. dF/dp: the engine's central differences.
//
// Which equilibria exist: the drive S_{l,m} = C_{l,m} - Gamma3_l/C g_{l,m}(0) e^{i m t/2} is constant
// only if the stress-free shape has no m != 0 content (beta = 0: axisymmetric about the vorticity
// axis) or C = inf; otherwise the problem throws InvalidArgument("beta", ...), at construction and
// (ending a branch as outside_domain) at any parameter value where the forcing would rotate.
//
// Dense linear algebra (the engine's interface): L is limited to 16 (n = 285).
#include <optional>
#include <span>
#include <vector>

#include "rbcstab/continuation/continuation_parameter.hpp"
#include "rbcstab/continuation/problem.hpp"
#include "rbcstab/model/full_model.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

// Observables of a full-model equilibrium.
struct FullEquilibriumState {
  double sigma = 0;
  double r = 0, Psi = 0;        // from f_{2,2} and Delta_2 as simulate() reads them: r = |f22| sqrt(2 a_2 / Delta_2)
  std::vector<double> Delta_l;  // l = 2..L (index l - 2)
};

class FullEquilibriumProblem final : public ContinuationProblem {
 public:
  static constexpr int max_L = 16;

  // The scene supplies every parameter but the free one, beta, rest_delta_l and L (in [2, max_L]).
  FullEquilibriumProblem(const Scene& scene, ContinuationParameter free);

  Eigen::Index dimension() const override { return n_; }
  void residual(const Eigen::VectorXd& x, double p, Eigen::VectorXd& G) const override;
  void jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& J) const override;
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& x, double p) const override;
  // The same values with first-order error bounds (inactive blocks and the dense active part alike).
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& x, double p, bool refine) const override;
  // Central differences, except for beta: zero wherever the problem is defined (see the .cpp).
  void parameter_derivative(const Eigen::VectorXd& x, double p, Eigen::VectorXd& Fp) const override;
  std::string parameter_name() const override { return to_string(free_); }

  int L() const { return L_; }
  ContinuationParameter free_parameter() const { return free_; }
  const Scene& scene() const { return scene_; }
  double start_parameter() const { return get_parameter(scene_, free_); }
  // Index of x_{l,0} (m = 0) or of Re x_{l,m} (m > 0; Im x_{l,m} follows it).
  static constexpr Eigen::Index index(int l, int m) { return l * l - 4 + (m == 0 ? 0 : 2 * m - 1); }

  // The full model at the free value p (cached for the last p); throws InvalidArgument("beta", ...)
  // when its drive rotates there.
  const FullModel& model(double p) const;
  // x -> FullModel state y (both halves of every m), and the projection of y onto real shapes.
  std::vector<double> to_full_state(const Eigen::VectorXd& x, double p) const;
  Eigen::VectorXd from_full_state(std::span<const double> y, double p) const;
  // The dynamics F = R F_full(E x) (x.F = 0) and DF = R J E, at any x != 0.
  void dynamics(const Eigen::VectorXd& x, double p, Eigen::VectorXd& F) const;
  void dynamics_jacobian(const Eigen::VectorXd& x, double p, Eigen::MatrixXd& DF) const;

  // The ellipsoidal equilibrium (f_{l>=3} = 0) from the out-of-plane closed form (analysis/
  // steady_states), embedded: exact when the scene has no rest_delta_l, else a Newton start.
  Eigen::VectorXd ellipsoidal_state(double p) const;
  // The scene's full-model state after time T from its initial shape (perturbations included),
  // projected and put on the unit sphere: a start on an attracting branch.
  Eigen::VectorXd relaxed_state(double T) const;
  FullEquilibriumState observe(const Eigen::VectorXd& x, double p) const;

 private:
  Scene scene_;
  ContinuationParameter free_;
  int L_;
  Eigen::Index n_;
  // The parameters at p (through the model cache).
  const Parameters& parameters(double p) const {
    model(p);
    return cache_q_;
  }
  mutable std::optional<FullModel> cache_;
  mutable Parameters cache_q_;
  mutable double cache_p_ = 0;
};

}  // namespace rbcstab
