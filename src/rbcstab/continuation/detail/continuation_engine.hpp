#pragma once
// Module-private: the engine behind continue_branch, which continues one direction of a branch: its
// predictor-corrector steps (continuation.cpp), the special points between two accepted points
// (special_point_detection.cpp) and the points' stability certificates (stability_certificate.cpp).
#include <array>
#include <complex>
#include <cstddef>
#include <string>
#include <vector>
#include "rbcstab/continuation/dense.hpp"

#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/continuation/problem.hpp"

namespace rbcstab::detail {

constexpr int kSlots = 4;  // test function slots: 0 LP/LPC, 1 BP, 2 HB/NS, 3 PD (cycles only)

// A corrected point with what the detectors need.
struct Pt {
  Eigen::VectorXd X;  // (x, p)
  Eigen::VectorXd t;  // unit tangent, oriented along the continuation
  Eigen::VectorXcd spectrum;
  int n_unstable = 0;
  std::array<double, kSlots> tests{};
  std::vector<double> events;
  int iterations = 0;
};

// One direction of a branch from its corrected start (run), with the work it did (counters).
class Engine {
 public:
  Engine(const ContinuationProblem& problem, const ContinuationOptions& options)
      : pr_(problem),
        o_(options),
        n_(problem.dimension()),
        N_(n_ + 1),
        cycles_(problem.stability_kind() == StabilityKind::multipliers) {}

  ContinuationCounters counters;

  bool correct(Eigen::VectorXd& X, const Eigen::VectorXd& border, const Eigen::VectorXd& X0, double s, int& iterations);
  Pt finish(const Eigen::VectorXd& X, const Eigen::VectorXd& t_prev, int iterations);
  bool probe(const Pt& a, double s, Pt& out);
  double test_value(const Pt& q, int slot, int event) const;
  bool neutral(const Pt& q, int slot) const;
  SpecialPointType slot_type(int slot) const;
  bool locate(const Pt& a, const Pt& b, int slot, int event, std::size_t after, SpecialPoint& sp);
  static int crossings(SpecialPointType type);
  SpecialPointType unresolved_type(const Pt& a, const Pt& b) const;
  void detect(const Pt& a, const Pt& b, std::size_t after, int depth, std::vector<SpecialPoint>& out);
  std::vector<SpecialPoint> unresolved_crossings(const Pt& a, const Pt& b, std::size_t after);
  void merge_coincident(std::vector<SpecialPoint>& out, std::size_t first);
  bool fold_at_bound(std::vector<SpecialPoint>& special, std::size_t first, const Pt& a, Pt& end);
  void detect_at_bound(const Pt& a, const Pt& b, std::size_t after, std::vector<SpecialPoint>& out);
  std::complex<double> critical_value(const Pt& q, SpecialPointType type) const;
  std::string unconfirmed_change(const Pt& a, const Pt& b, const std::vector<SpecialPoint>& found) const;
  // The first special point from index `first` on that is a stop event's UZ (UserEvent::stop): the points
  // after it are dropped and `end` is it, as a point of the branch (tangent oriented by a's). Returns its
  // name, or "" when there is none.
  std::string stop_event(std::vector<SpecialPoint>& special, std::size_t first, const Pt& a, Pt& end);
  StabilityCertificate certificate(const Pt& q, bool special);
  void set_certificate(SpecialPoint& sp, const Pt& q, double m_lo, double m_hi);
  double margin(const Pt& q) const;
  BranchPoint to_branch_point(const Pt& q, double arclength);
  Branch run(const Eigen::VectorXd& x0, double p0, double sign);

 private:
  void eval_F(const Eigen::VectorXd& X);
  void assemble(const Eigen::VectorXd& X, const Eigen::VectorXd& border);

  const ContinuationProblem& pr_;
  const ContinuationOptions& o_;
  Eigen::Index n_, N_;
  bool cycles_;
  Eigen::VectorXd F_, Fp_;
  Eigen::MatrixXd J_, A_;
};

}  // namespace rbcstab::detail
