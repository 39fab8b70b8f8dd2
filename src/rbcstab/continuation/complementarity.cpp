#include "rbcstab/continuation/complementarity.hpp"

#include <algorithm>
#include <cmath>

#include <IpIpoptApplication.hpp>
#include <IpSolveStatistics.hpp>
#include <IpTNLP.hpp>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

void ComplementarityOptions::validate() const {
  require(std::isfinite(tol) && tol > 0 && tol < 1, "tol", tol, "in (0, 1)");
  require(max_iterations >= 1, "max_iterations", max_iterations, "an integer >= 1");
  require(std::isfinite(start_area_fraction) && start_area_fraction > 0 && start_area_fraction < 1,
          "start_area_fraction", start_area_fraction, "in (0, 1)");
  require(std::isfinite(surviving_threshold) && surviving_threshold > 0 && surviving_threshold < 1,
          "surviving_threshold", surviving_threshold, "in (0, 1)");
  require(print_level >= 0 && print_level <= 12, "print_level", print_level, "an integer in [0, 12]");
}

namespace {

using Ipopt::Index;
using Ipopt::Number;

// Variables v = (x_2 [0..4], sigma [5], d_l [6 + l - 3]); constraints g = (l = 2 equations [0..4],
// area [5], Upsilon_l [6 + l - 3]).
class SurvivingModesNlp final : public Ipopt::TNLP {
 public:
  SurvivingModesNlp(const ModalCoefficients& c, Eigen::VectorXd start)
      : c_(c), nl_(c.L - 2), start_(std::move(start)) {}

  Eigen::VectorXd solution;
  Ipopt::SolverReturn solver_status = Ipopt::UNASSIGNED;

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag, IndexStyleEnum& style) override {
    n = m = 6 + nl_;
    nnz_jac_g = 30 + 5 + 2 * nl_;
    nnz_h_lag = 10 + nl_;
    style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l, Number* g_u) override {
    for (Index i = 0; i < n; ++i) {
      x_l[i] = i < 6 ? -2e19 : 0.0;  // d_l >= 0
      x_u[i] = 2e19;
    }
    for (Index k = 0; k < m; ++k) {
      g_l[k] = k < 6 ? 0.0 : -2e19;  // equalities, then Upsilon_l <= 0
      g_u[k] = 0.0;
    }
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool, Number*, Number*, Index, bool, Number*) override {
    if (init_x)
      for (Index i = 0; i < n; ++i) x[i] = start_[i];
    return true;
  }

  bool eval_f(Index, const Number* v, bool, Number& f) override {
    f = 0;
    for (int l = 3; l <= c_.L; ++l) f -= d(v, l) * c_.upsilon(l, v[5]);
    return true;
  }

  bool eval_grad_f(Index n, const Number* v, bool, Number* g) override {
    std::fill(g, g + n, 0.0);
    for (int l = 3; l <= c_.L; ++l) {
      g[5] -= d(v, l) * slope(l);
      g[di(l)] = -c_.upsilon(l, v[5]);
    }
    return true;
  }

  bool eval_g(Index, const Number* v, bool, Index, Number* g) override {
    const Eigen::Map<const Eigen::VectorXd> x2(v, 5);
    Eigen::VectorXd F2;
    ModalEquilibriumProblem::l2_dynamics(c_, x2, v[5], F2);
    for (int i = 0; i < 5; ++i) g[i] = F2[i];
    g[5] = x2.squaredNorm() - 1;
    for (int l = 3; l <= c_.L; ++l) {
      g[5] += d(v, l);
      g[di(l)] = c_.upsilon(l, v[5]);
    }
    return true;
  }

  bool eval_jac_g(Index, const Number* v, bool, Index, Index, Index* row, Index* col, Number* val) override {
    if (!val) {
      Index k = 0;
      for (Index i = 0; i < 5; ++i)
        for (Index j = 0; j < 6; ++j) row[k] = i, col[k++] = j;
      for (Index j = 0; j < 5; ++j) row[k] = 5, col[k++] = j;
      for (int l = 3; l <= c_.L; ++l) row[k] = 5, col[k++] = di(l);
      for (int l = 3; l <= c_.L; ++l) row[k] = di(l), col[k++] = 5;
      return true;
    }
    Eigen::MatrixXd J2;
    ModalEquilibriumProblem::l2_jacobian(c_, v[5], J2);
    Index k = 0;
    for (int i = 0; i < 5; ++i) {
      for (int j = 0; j < 5; ++j) val[k++] = J2(i, j);
      val[k++] = slope(2) * v[i];  // d/dsigma of Upsilon_2 x_i
    }
    for (int j = 0; j < 5; ++j) val[k++] = 2 * v[j];
    for (int l = 3; l <= c_.L; ++l) val[k++] = 1.0;
    for (int l = 3; l <= c_.L; ++l) val[k++] = slope(l);
    return true;
  }

  bool eval_h(Index, const Number*, bool, Number obj_factor, Index, const Number* lambda, bool, Index, Index* row,
              Index* col, Number* val) override {
    if (!val) {
      Index k = 0;
      for (Index j = 0; j < 5; ++j) row[k] = 5, col[k++] = j;
      for (Index j = 0; j < 5; ++j) row[k] = j, col[k++] = j;
      for (int l = 3; l <= c_.L; ++l) row[k] = di(l), col[k++] = 5;
      return true;
    }
    Index k = 0;
    for (int j = 0; j < 5; ++j) val[k++] = lambda[j] * slope(2);        // d2(Upsilon_2 x_j)/dsigma dx_j
    for (int j = 0; j < 5; ++j) val[k++] = 2 * lambda[5];               // the area's |x_2|^2
    for (int l = 3; l <= c_.L; ++l) val[k++] = -obj_factor * slope(l);  // d2(-d_l Upsilon_l)/dd_l dsigma
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn status, Index n, const Number* v, const Number*, const Number*, Index,
                         const Number*, const Number*, Number, const Ipopt::IpoptData*,
                         Ipopt::IpoptCalculatedQuantities*) override {
    solver_status = status;
    solution = Eigen::Map<const Eigen::VectorXd>(v, n);
  }

 private:
  static Index di(int l) { return 6 + (l - 3); }
  static double d(const Number* v, int l) { return v[di(l)]; }
  double slope(int l) const { return c_.rate(l).slope; }

  const ModalCoefficients& c_;
  int nl_;
  Eigen::VectorXd start_;
};

}  // namespace

ComplementarityResult solve_surviving_modes(const ModalEquilibriumProblem& problem, double p,
                                            const ComplementarityOptions& options) {
  options.validate();
  const ModalCoefficients c = problem.coefficients(p);
  const int nl = c.L - 2;
  // Start: the ellipsoidal l = 2 state, sigma no lower than every sigma_l^c (so Upsilon_l <= 0 holds),
  // every d_l = start_area_fraction.
  const Eigen::VectorXd xe = problem.ellipsoidal_state(p);
  double sigma0 = ModalEquilibriumProblem::sigma(c, xe);
  double sigma_c_max = -1e300;
  for (int l = 3; l <= c.L; ++l) sigma_c_max = std::max(sigma_c_max, c.rate(l).sigma_c);
  sigma0 = std::max(sigma0, sigma_c_max + 1e-2 * (1 + std::abs(sigma_c_max)));
  Eigen::VectorXd start(6 + nl);
  start.head(5) = xe.head(5);
  start[5] = sigma0;
  start.tail(nl).setConstant(options.start_area_fraction);

  Ipopt::SmartPtr<SurvivingModesNlp> nlp = new SurvivingModesNlp(c, start);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetNumericValue("tol", options.tol);
  app->Options()->SetIntegerValue("max_iter", options.max_iterations);
  app->Options()->SetIntegerValue("print_level", options.print_level);
  app->Options()->SetStringValue("sb", "yes");  // no banner: only apps/ print
  // Ipopt relaxes bounds by 1e-8 by default; d_l >= 0 and Upsilon_l <= 0 are meant exactly.
  app->Options()->SetNumericValue("bound_relax_factor", 0.0);
  ComplementarityResult r;
  if (app->Initialize() != Ipopt::Solve_Succeeded) {
    r.status = "Initialize failed";
    r.message = "Ipopt could not be initialised";
    return r;
  }
  const Ipopt::ApplicationReturnStatus st = app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(GetRawPtr(nlp)));
  r.status = ipopt_status_name(static_cast<int>(st));
  r.converged = st == Ipopt::Solve_Succeeded || st == Ipopt::Solved_To_Acceptable_Level;
  if (Ipopt::IsValid(app->Statistics())) r.iterations = app->Statistics()->IterationCount();
  if (nlp->solution.size() != 6 + nl) {
    r.converged = false;
    r.message = "Ipopt returned no iterate (" + r.status + ")";
    return r;
  }
  const Eigen::VectorXd& v = nlp->solution;
  r.sigma = v[5];
  r.x = Eigen::VectorXd::Zero(problem.dimension());
  r.x.head(5) = v.head(5);
  r.Delta_l.assign(static_cast<std::size_t>(c.L - 1), 0.0);
  const double Delta = c.parameters.Delta;
  r.Delta_l[0] = Delta * v.head(5).squaredNorm();
  double area = v.head(5).squaredNorm() - 1;
  for (int l = 3; l <= c.L; ++l) {
    const double dl = std::max(0.0, v[6 + (l - 3)]);
    r.Delta_l[static_cast<std::size_t>(l - 2)] = Delta * dl;
    // An interior point leaves d_l ~ tol on the inactive bound; its square root (~1e-6) would be
    // noise in the amplitude, so a non-surviving mode's a_l is its complementary value 0.
    if (dl > options.surviving_threshold) {
      r.surviving.push_back(l);
      r.x[ModalEquilibriumProblem::index_of_mode(l)] = std::sqrt(dl);
    }
    r.complementarity -= dl * c.upsilon(l, r.sigma);
    r.max_constraint_violation = std::max(r.max_constraint_violation, std::max(0.0, c.upsilon(l, r.sigma)));
    area += v[6 + (l - 3)];
  }
  Eigen::VectorXd F2;
  ModalEquilibriumProblem::l2_dynamics(c, v.head(5), r.sigma, F2);
  r.max_constraint_violation = std::max({r.max_constraint_violation, F2.lpNorm<Eigen::Infinity>(), std::abs(area)});
  r.message = r.converged ? "" : "Ipopt did not converge: " + r.status;
  return r;
}

std::string ipopt_status_name(int status) {
  switch (static_cast<Ipopt::ApplicationReturnStatus>(status)) {
    case Ipopt::Solve_Succeeded:
      return "Solve_Succeeded";
    case Ipopt::Solved_To_Acceptable_Level:
      return "Solved_To_Acceptable_Level";
    case Ipopt::Infeasible_Problem_Detected:
      return "Infeasible_Problem_Detected";
    case Ipopt::Maximum_Iterations_Exceeded:
      return "Maximum_Iterations_Exceeded";
    case Ipopt::Restoration_Failed:
      return "Restoration_Failed";
    case Ipopt::Error_In_Step_Computation:
      return "Error_In_Step_Computation";
    case Ipopt::Invalid_Number_Detected:
      return "Invalid_Number_Detected";
    case Ipopt::User_Requested_Stop:
      return "User_Requested_Stop";
    default:
      return "Ipopt status " + std::to_string(status);
  }
}

}  // namespace rbcstab
