#pragma once
// Adapters from our one-parameter physical problems (built from a Scene and one free
// ContinuationParameter) to the two-parameter interfaces of the curve continuations: the second
// parameter p2 is written into the scene (with_parameter) and the one-parameter problem at that p2
// does all the work, so no equation is re-coded. p1 is set after p2, which is why the pair must be
// independent (require_independent).
//   SceneTwoParameterProblem<ReducedEquilibriumProblem>, <ModalEquilibriumProblem>: LP, HB, BP curves
//   of equilibria (FoldCurveProblem, HopfCurveProblem, BranchPointCurveProblem);
//   ReducedForcedSystem2: LPC and PD curves of the forced in-plane orbits (OrbitTwoParameterProblem), NS
//   curves (NeimarkSackerCurveProblem); ModalForcedSystem2: the same for the modal model's orbits.
#include <memory>
#include <utility>
#include <vector>

#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/fold_curve.hpp"
#include "rbcstab/continuation/forced_system.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/orbit_two_parameter.hpp"

namespace rbcstab {

namespace detail {
// The last few one-parameter objects by p2 value: curve Newton steps and the engine's central
// differences in p2 alternate between about three p2 values, each object costs a model setup.
template <class T>
class ByP2 {
 public:
  ByP2(const Scene& scene, ContinuationParameter p1, ContinuationParameter p2) : scene_(scene), p1_(p1), p2_(p2) {
    require_independent(p1, p2, "p2");
  }
  const T& at(double p2) const {
    for (const auto& [v, t] : cache_)
      if (v == p2) return *t;
    Scene s = scene_;
    s = with_parameter(s, p2_, p2);  // throws InvalidArgument outside p2's domain
    if (cache_.size() >= 4) cache_.erase(cache_.begin());
    cache_.emplace_back(p2, std::make_unique<T>(s, p1_));
    return *cache_.back().second;
  }
  const Scene& scene() const { return scene_; }
  ContinuationParameter p1() const { return p1_; }
  ContinuationParameter p2() const { return p2_; }

 private:
  Scene scene_;
  ContinuationParameter p1_, p2_;
  mutable std::vector<std::pair<double, std::unique_ptr<T>>> cache_;
};
}  // namespace detail

// P: ReducedEquilibriumProblem or ModalEquilibriumProblem (constructible from (Scene, ContinuationParameter)).
// Throws InvalidArgument("p2", ...) for a coupled pair, and whatever P throws for the scene.
template <class P>
class SceneTwoParameterProblem final : public TwoParameterProblem {
 public:
  SceneTwoParameterProblem(const Scene& scene, ContinuationParameter p1, ContinuationParameter p2)
      : by_(scene, p1, p2), n_(at(start_parameter2()).dimension()) {}
  Eigen::Index dimension() const override { return n_; }
  void residual(const Eigen::VectorXd& x, double p1, double p2, Eigen::VectorXd& F) const override {
    at(p2).residual(x, p1, F);
  }
  void jacobian(const Eigen::VectorXd& x, double p1, double p2, Eigen::MatrixXd& J) const override {
    at(p2).jacobian(x, p1, J);
  }
  void parameter_derivative(const Eigen::VectorXd& x, double p1, double p2, Eigen::VectorXd& Fp) const override {
    at(p2).parameter_derivative(x, p1, Fp);
  }
  // The dynamics' spectrum on the sphere's tangent plane (not the Newton system's Jacobian).
  Eigen::VectorXcd spectrum(const Eigen::VectorXd& x, double p1, double p2) const override {
    return at(p2).spectrum(x, p1);
  }
  CertifiedSpectrum certified_spectrum(const Eigen::VectorXd& x, double p1, double p2, bool refine) const override {
    return at(p2).certified_spectrum(x, p1, refine);
  }
  std::string name1() const override { return to_string(by_.p1()); }
  std::string name2() const override { return to_string(by_.p2()); }
  double start_parameter2() const { return get_parameter(by_.scene(), by_.p2()); }
  const P& at(double p2) const { return by_.at(p2); }  // the one-parameter problem in p1 at p2

 private:
  detail::ByP2<P> by_;
  Eigen::Index n_;
};

// The forced in-plane reduced system in two parameters (ReducedForcedSystem at each p2).
class ReducedForcedSystem2 final : public ForcedSystem2 {
 public:
  ReducedForcedSystem2(const Scene& scene, ContinuationParameter p1, ContinuationParameter p2) : by_(scene, p1, p2) {}
  Eigen::Index dimension() const override { return 3; }
  void rhs(double t, std::span<const double> x, double p1, double p2, std::span<double> f) const override {
    by_.at(p2).rhs(t, x, p1, f);
  }
  void jacobian(double t, std::span<const double> x, double p1, double p2, Eigen::MatrixXd& J) const override {
    by_.at(p2).jacobian(t, x, p1, J);
  }
  void parameter_derivative(double t, std::span<const double> x, double p1, double p2,
                            std::span<double> fp) const override {
    by_.at(p2).parameter_derivative(t, x, p1, fp);  // analytic in p1
  }
  bool conserves_norm() const override { return true; }
  std::string name1() const override { return to_string(by_.p1()); }
  std::string name2() const override { return to_string(by_.p2()); }
  double start_parameter2() const { return get_parameter(by_.scene(), by_.p2()); }
  const ReducedForcedSystem& at(double p2) const { return by_.at(p2); }

 private:
  detail::ByP2<ReducedForcedSystem> by_;
};

// The forced modal model in two parameters (ModalForcedSystem at each p2; scene.parameters.Delta is
// the total excess area, as for ModalForcedSystem: build it from total_area_scene(simulated)).
class ModalForcedSystem2 final : public ForcedSystem2 {
 public:
  ModalForcedSystem2(const Scene& scene, ContinuationParameter p1, ContinuationParameter p2)
      : by_(scene, p1, p2), n_(by_.at(start_parameter2()).dimension()) {}
  Eigen::Index dimension() const override { return n_; }
  void rhs(double t, std::span<const double> x, double p1, double p2, std::span<double> f) const override {
    by_.at(p2).rhs(t, x, p1, f);
  }
  void jacobian(double t, std::span<const double> x, double p1, double p2, Eigen::MatrixXd& J) const override {
    by_.at(p2).jacobian(t, x, p1, J);
  }
  void parameter_derivative(double t, std::span<const double> x, double p1, double p2,
                            std::span<double> fp) const override {
    by_.at(p2).parameter_derivative(t, x, p1, fp);  // exact in x (modal_orbit.hpp)
  }
  bool conserves_norm() const override { return true; }
  std::string name1() const override { return to_string(by_.p1()); }
  std::string name2() const override { return to_string(by_.p2()); }
  double start_parameter2() const { return get_parameter(by_.scene(), by_.p2()); }
  const ModalForcedSystem& at(double p2) const { return by_.at(p2); }

 private:
  detail::ByP2<ModalForcedSystem> by_;
  Eigen::Index n_;
};

}  // namespace rbcstab
