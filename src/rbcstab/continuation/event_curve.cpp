#include "rbcstab/continuation/event_curve.hpp"

#include <cmath>
#include <limits>
#include <sstream>
#include <utility>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

void CurveEvent::jacobian(const Eigen::VectorXd& x, double p1, const Eigen::VectorXd& a, double p2,
                          Eigen::MatrixXd& D) const {
  const Eigen::Index n = x.size(), m = a.size();
  Eigen::VectorXd v(n + 1 + m);
  v << x, p1, a;
  Eigen::VectorXd Gp, Gm;
  auto eval = [&](const Eigen::VectorXd& w, Eigen::VectorXd& G) { residual(w.head(n), w[n], w.tail(m), p2, G); };
  Eigen::VectorXd w = v;
  for (Eigen::Index j = 0; j < v.size(); ++j) {
    const double h = std::cbrt(std::numeric_limits<double>::epsilon()) * (1 + std::abs(v[j]));
    w[j] = v[j] + h;
    eval(w, Gp);
    w[j] = v[j] - h;
    eval(w, Gm);
    w[j] = v[j];
    if (j == 0) D.resize(Gp.size(), v.size());
    D.col(j) = (Gp - Gm) / (2 * h);
  }
}

ScalarCurveEvent::ScalarCurveEvent(std::string name, Function g) : name_(std::move(name)), g_(std::move(g)) {
  if (!g_) throw InvalidArgument("event", "event '" + name_ + "' has no function");
}

void ScalarCurveEvent::residual(const Eigen::VectorXd& x, double p1, const Eigen::VectorXd&, double p2,
                                Eigen::VectorXd& G) const {
  G.resize(1);
  G[0] = g_(x, p1, p2);
}

// ---- the orbit's passage through z = 0

void OrbitPassageEvent::residual(const Eigen::VectorXd& X, double p1, const Eigen::VectorXd& a, double p2,
                                 Eigen::VectorXd& G) const {
  const OrbitPoint pt = base_.point_at(X, p1, p2, a[0]);
  G.resize(2);
  // A failed integration: NaN makes the corrector fail and shrink the step (as the shooting residual).
  if (!pt.ok)
    G.setConstant(std::numeric_limits<double>::quiet_NaN());
  else
    G = pt.x.head(2);
}

void OrbitPassageEvent::jacobian(const Eigen::VectorXd& X, double p1, const Eigen::VectorXd& a, double p2,
                                 Eigen::MatrixXd& D) const {
  const OrbitPoint pt = base_.point_at(X, p1, p2, a[0]);
  const Eigen::Index n = X.size(), k = pt.dt.size();
  D.setZero(2, n + 2);
  if (!pt.ok) {
    D.setConstant(std::numeric_limits<double>::quiet_NaN());
    return;
  }
  D.block(0, pt.segment * k, 2, k) = pt.dx.topRows(2);  // only the segment's start moves z(t*)
  D.col(n) = pt.dp.head(2);
  D.col(n + 1) = pt.dt.head(2);
}

Eigen::VectorXd OrbitPassageEvent::auxiliary_start(const Eigen::VectorXd& X, double p1, double p2) const {
  const OrbitSummary s = base_.summary(X, p1, p2);
  if (!(s.r_min < max_start_distance)) {
    std::ostringstream m;
    m << "event " << name_ << ": the start orbit does not pass through z = 0 (r_min = " << s.r_min << ", must be < "
      << max_start_distance << "): not a swinging <-> tumbling transition";
    throw InvalidArgument("event", m.str());
  }
  return Eigen::VectorXd::Constant(1, s.t_r_min);
}

// ---- the curve

EventCurveProblem::EventCurveProblem(const TwoParameterProblem& base, const CurveEvent& event, const SpecialPoint& uz,
                                     double p2)
    : base_(base), event_(event), n_(base.dimension()), m_(event.auxiliary_dimension()) {
  if (uz.type != SpecialPointType::UZ || uz.status != LocationStatus::located)
    throw InvalidArgument("uz", "an event curve starts from a located UZ point (got " + to_string(uz.type) + ", " +
                                    to_string(uz.status) + ")");
  require(uz.x.size() == n_, "uz", static_cast<double>(uz.x.size()), "a point of the base problem's dimension");
  const Eigen::VectorXd a = event.auxiliary_start(uz.x, uz.p, p2);
  require(a.size() == m_, "event", static_cast<double>(a.size()), "auxiliary_dimension() auxiliary unknowns");
  start_.resize(n_ + 1 + m_);
  start_ << uz.x, uz.p, a;
}

void EventCurveProblem::residual(const Eigen::VectorXd& X, double p2, Eigen::VectorXd& R) const {
  Eigen::VectorXd F, G;
  base_.residual(X.head(n_), X[n_], p2, F);
  event_.residual(X.head(n_), X[n_], X.tail(m_), p2, G);
  R.resize(n_ + 1 + m_);
  R << F, G;
}

void EventCurveProblem::jacobian(const Eigen::VectorXd& X, double p2, Eigen::MatrixXd& J) const {
  const Eigen::VectorXd x = X.head(n_), a = X.tail(m_);
  const double p1 = X[n_];
  Eigen::MatrixXd Fx, D;
  Eigen::VectorXd Fp;
  base_.jacobian(x, p1, p2, Fx);
  base_.parameter_derivative(x, p1, p2, Fp);
  event_.jacobian(x, p1, a, p2, D);
  J.setZero(dimension(), dimension());
  J.topLeftCorner(n_, n_) = Fx;
  J.block(0, n_, n_, 1) = Fp;
  J.bottomRows(1 + m_) = D;
}

Eigen::VectorXcd EventCurveProblem::spectrum(const Eigen::VectorXd& X, double p2) const {
  return base_.spectrum(X.head(n_), X[n_], p2);
}

CertifiedSpectrum EventCurveProblem::certified_spectrum(const Eigen::VectorXd& X, double p2, bool refine) const {
  return base_.certified_spectrum(X.head(n_), X[n_], p2, refine);
}

}  // namespace rbcstab
