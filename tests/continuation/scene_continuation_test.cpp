// scene_continuation.hpp: each kind continued from a scene is, bit for bit, the branch of the direct
// problem calls it stands for (same problem, start, engine options, events); the start-point selection
// per kind; the choice of the BP-curve system (symmetry-reduced or generic); curves and branch switching
// against their direct calls; and validate() naming the field.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "continuation/ellipsoidal_orbit_bp_fixture.hpp"
#include "continuation/fig2_fixture.hpp"
#include "continuation/full_fixtures.hpp"
#include "continuation/invalid_argument_fixture.hpp"
#include "continuation/modal_fixtures.hpp"
#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_point_curve.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/equilibrium.hpp"
#include "rbcstab/continuation/fold_curve.hpp"
#include "rbcstab/continuation/full_equilibrium.hpp"
#include "rbcstab/continuation/modal_equilibrium.hpp"
#include "rbcstab/continuation/modal_orbit.hpp"
#include "rbcstab/continuation/scene_branch.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/continuation/scene_measures.hpp"
#include "rbcstab/continuation/scene_start.hpp"
#include "rbcstab/continuation/two_parameter.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {
namespace {

using P = ContinuationParameter;
using test::curve_of;
using test::invalid_parameter;
using test::modal_spec;
using test::orbit_spec;
using test::spec_of;

// Bit for bit: every point (state, parameter, spectrum, stability), every special point, the status.
void expect_same_branch(const Branch& a, const Branch& b) {
  EXPECT_EQ(a.parameter_names, b.parameter_names);
  ASSERT_EQ(a.points.size(), b.points.size());
  for (std::size_t k = 0; k < a.points.size(); ++k) {
    EXPECT_EQ(a.points[k].p, b.points[k].p) << k;
    EXPECT_TRUE(a.points[k].x == b.points[k].x) << k;
    EXPECT_TRUE(a.points[k].spectrum == b.points[k].spectrum) << k;
    EXPECT_EQ(a.points[k].n_unstable, b.points[k].n_unstable) << k;
  }
  ASSERT_EQ(a.special_points.size(), b.special_points.size());
  for (std::size_t k = 0; k < a.special_points.size(); ++k) {
    EXPECT_EQ(a.special_points[k].type, b.special_points[k].type) << k;
    EXPECT_EQ(a.special_points[k].p, b.special_points[k].p) << k;
    EXPECT_TRUE(a.special_points[k].x == b.special_points[k].x) << k;
  }
  EXPECT_EQ(a.status, b.status);
  EXPECT_EQ(a.message, b.message);
}

using test::invalid_parameter;

TEST(SceneContinuation, EquilibriumIsTheDirectBranchWithPolarMeasures) {
  const BranchSpec spec =
      spec_of(modal_fixtures::scene(0.08, 2), ProblemKind::equilibrium, P::lambda, 0.5, 3, Direction::both);
  const SceneBranch r = continue_scene(spec);
  const ReducedEquilibriumProblem pr(spec.scene, P::lambda);
  const Branch direct = continue_branch(pr, pr.relaxed_state(200), pr.start_parameter(), spec.engine);
  expect_same_branch(r.branch.branch, direct);
  ASSERT_GT(direct.points.size(), 5u);
  EXPECT_EQ(r.branch.measure_names, (std::vector<std::string>{"r", "Psi"}));
  EXPECT_EQ(r.branch.spectrum_kind, StabilityKind::eigenvalues);
  for (std::size_t k = 0; k < direct.points.size(); ++k) {
    const PolarState s = polar(direct.points[k].x);
    EXPECT_EQ(r.branch.number(k, "r"), s.r);
    EXPECT_EQ(r.branch.number(k, "Psi"), s.Psi);
  }
  EXPECT_FALSE(r.switched);
}

TEST(SceneContinuation, ModalIsTheDirectBranchAndSwitchesAtItsFirstBP) {
  BranchSpec spec = modal_spec();
  spec.switch_at_bp = true;
  const SceneBranch r = continue_scene(spec);
  const ModalEquilibriumProblem pr(spec.scene, P::C);
  const double p0 = pr.start_parameter();
  const Branch direct = continue_branch(pr, pr.ellipsoidal_state(p0), p0, spec.engine);
  expect_same_branch(r.branch.branch, direct);
  EXPECT_EQ(r.start.method, StartMethod::ellipsoidal);
  EXPECT_FALSE(r.start.newton);
  EXPECT_EQ(r.branch.measure_names, measure_names(ProblemKind::modal, 6));
  EXPECT_EQ(r.branch.measure_names.back(), "Delta_6");
  for (std::size_t k = 0; k < direct.points.size(); ++k) {
    const ModalState st = pr.observe(direct.points[k].x, direct.points[k].p);
    EXPECT_EQ(r.branch.number(k, "sigma"), st.sigma);
    EXPECT_EQ(r.branch.number(k, "Delta_3"), st.Delta_l[1]);
  }
  // The switched branch: switch_branch at the first BP with the branch's engine options.
  const SpecialPoint* bp = find_special_point(direct, SpecialPointType::BP);
  ASSERT_NE(bp, nullptr);
  BranchSwitchOptions so;
  so.continuation = spec.engine;
  const BranchSwitchResult sw = switch_branch(pr, direct, *bp, so);
  ASSERT_TRUE(r.switched);
  ASSERT_TRUE(sw.switched);
  EXPECT_TRUE(r.switched->switched);
  EXPECT_EQ(r.switched->bp_number, 1);
  expect_same_branch(r.switched->branch.branch, sw.branch);
  // switch_at_bp on the result is the same call.
  const SwitchedBranch again = switch_at_bp(r);
  expect_same_branch(again.branch.branch, sw.branch);
  // The second BP (l = 4) switches too; a BP number beyond the branch's says how many there are.
  EXPECT_TRUE(switch_at_bp(r, 2).switched);
  const SwitchedBranch none = switch_at_bp(r, 99);
  EXPECT_FALSE(none.switched);
  EXPECT_NE(none.message.find("no BP number 99"), std::string::npos) << none.message;
  // A branch run with its switched branch still has curves (continue_curve from the result).
  EXPECT_TRUE(continue_curve(r, curve_of(CurveKind::BP, P::B, 0.9, 1.1)).started);
}

TEST(SceneContinuation, FullStartsFromTheRelaxedSceneWithRestContentAndFromTheEllipsoidWithout) {
  const BranchSpec spec =
      spec_of(full_fixtures::forced_scene(0.08, 5, 1e-3), ProblemKind::full, P::C, 0.03, 0.08, Direction::backward);
  const SceneBranch r = continue_scene(spec);
  const FullEquilibriumProblem pr(spec.scene, P::C);
  const double p0 = pr.start_parameter();
  const NewtonResult start = solve_fixed_parameter(pr, pr.relaxed_state(200), p0);
  ASSERT_TRUE(start.converged);
  EXPECT_EQ(r.start.method, StartMethod::relaxed);
  EXPECT_TRUE(r.start.newton);
  EXPECT_TRUE(r.start.x == start.x);
  expect_same_branch(r.branch.branch, continue_branch(pr, start.x, p0, spec.engine));
  EXPECT_EQ(r.branch.measure_names, measure_names(ProblemKind::full, 5));

  // No stress-free l >= 3 content: Newton from the ellipsoidal closed form.
  const BranchSpec plain =
      spec_of(full_fixtures::forced_scene(0.08, 4, 0), ProblemKind::full, P::C, 0.05, 0.08, Direction::backward);
  const StartPoint s = find_start(plain);
  const FullEquilibriumProblem pp(plain.scene, P::C);
  EXPECT_EQ(s.method, StartMethod::ellipsoidal);
  EXPECT_TRUE(s.converged);
  EXPECT_TRUE(s.x == solve_fixed_parameter(pp, pp.ellipsoidal_state(0.08), 0.08).x);
}

TEST(SceneContinuation, OrbitIsTheDirectBranchWithTheTransitionEventAndOrbitMeasures) {
  const BranchSpec spec = orbit_spec();
  const SceneBranch r = continue_scene(spec);
  const ReducedForcedSystem sys(spec.scene, P::Delta);
  const PeriodicOrbitProblem pr(sys, spec.orbit);
  const OrbitRelaxation relaxed = pr.relax(sys.relaxed_state(200), 0.3, spec.relax_tol, spec.relax_max_periods);
  const NewtonResult start = solve_fixed_parameter(pr, pr.shooting_guess(relaxed.x, 0.3), 0.3);
  ASSERT_TRUE(start.converged);
  ContinuationOptions engine = spec.engine;
  engine.events.push_back(pr.transition_event());
  const Branch direct = continue_branch(pr, start.x, 0.3, engine);
  expect_same_branch(r.branch.branch, direct);
  EXPECT_EQ(r.start.method, StartMethod::relaxed);
  EXPECT_TRUE(r.start.newton);
  EXPECT_EQ(r.branch.spectrum_kind, StabilityKind::multipliers);
  ASSERT_EQ(direct.special_points.size(), 1u);
  EXPECT_EQ(direct.special_points[0].name, "swing_tumble");
  const std::size_t last = direct.points.size() - 1;
  for (std::size_t k : {std::size_t{0}, last}) {
    const BranchPoint& pt = direct.points[k];
    const OrbitSummary s = pr.summary(pt.x, pt.p);
    EXPECT_EQ(r.branch.number(k, "r_min"), s.r_min);
    EXPECT_EQ(r.branch.number(k, "Psi_max"), s.Psi_max);
    EXPECT_EQ(r.branch.number(k, "winding"), s.winding);
    EXPECT_EQ(std::get<std::string>(r.branch.measure(k, "kind")), to_string(s.kind));
    EXPECT_EQ(r.branch.number(k, "trivial_multiplier"), *pr.floquet(pt.x, pt.p).trivial);
  }
  EXPECT_EQ(std::get<std::string>(r.branch.measure(0, "kind")), "swinging");
  EXPECT_EQ(std::get<std::string>(r.branch.measure(last, "kind")), "tumbling");
  EXPECT_EQ(invalid_parameter([&] { (void)r.branch.number(0, "kind"); }), "measure");  // a label
  EXPECT_EQ(invalid_parameter([&] { (void)r.branch.measure(0, "sigma"); }), "measure");
  // The special point carries the same measures.
  ASSERT_EQ(r.branch.special_measures.size(), 1u);
  EXPECT_EQ(r.branch.special_measures[0].size(), r.branch.measure_names.size());
}

TEST(SceneContinuation, ModalOrbitRunsOnTheTotalAreaSceneFromTheRelaxedModalState) {
  Scene s = test::fig2_in_plane(1.0);
  s.L = 5;
  s.delta = 1e-3;
  s.model = ModelLevel::automatic;
  BranchSpec spec = spec_of(s, ProblemKind::modal_orbit, P::lambda, 4.9, 5.1, Direction::both);
  spec.relax_T = 600;
  spec.engine.max_points = 3;
  const SceneBranch r = continue_scene(spec);
  const Scene total = total_area_scene(s);
  EXPECT_EQ(r.problem_scene.parameters.Delta, total.parameters.Delta);
  const ModalForcedSystem sys(total, P::lambda);
  const PeriodicOrbitProblem pr(sys, spec.orbit);
  const OrbitRelaxation relaxed = pr.relax(sys.relaxed_state(s, 600), 5.0, spec.relax_tol, spec.relax_max_periods);
  const NewtonResult start = solve_fixed_parameter(pr, pr.shooting_guess(relaxed.x, 5.0), 5.0);
  ASSERT_TRUE(start.converged);
  ContinuationOptions engine = spec.engine;
  engine.events.push_back(pr.transition_event());
  const Branch direct = continue_branch(pr, start.x, 5.0, engine);
  expect_same_branch(r.branch.branch, direct);
  EXPECT_EQ(r.branch.measure_names, measure_names(ProblemKind::modal_orbit, 5));
  const ModalState st = sys.observe(0.0, pr.state_at_zero(direct.points[0].x), direct.points[0].p);
  EXPECT_EQ(r.branch.number(0, "Delta_3"), st.Delta_l[1]);
  EXPECT_GT(st.Delta_l[1], 0.5);  // the post-instability orbit: mode 3 carries the area
}

TEST(SceneContinuation, BoundsLandOnTheParameterDomainEdges) {
  BranchSpec spec =
      spec_of(modal_fixtures::scene(0.08, 2), ProblemKind::equilibrium, P::lambda, -5, 1.5, Direction::backward);
  const SceneBranch r = continue_scene(spec);
  EXPECT_EQ(r.spec.engine.p_min, 0.0);
  EXPECT_EQ(r.branch.branch.points.back().p, 0.0);  // landed on exactly
  ContinuationOptions e;
  set_domain_bounds(e, P::beta, -1, 10);
  EXPECT_EQ(e.p_min, 0.0);
  EXPECT_EQ(e.p_max, M_PI);
  set_domain_bounds(e, P::C, -1, 10);  // C's domain is open: no edge to land on
  EXPECT_EQ(e.p_min, -1.0);
  EXPECT_EQ(e.p_max, 10.0);
}

// ---- curves ----

TEST(SceneCurve, VesicleFoldCurveIsTheDirectFoldCurve) {
  Scene s = modal_fixtures::scene(INFINITY, 2);
  s.parameters.lambda = 5;
  s.parameters.Delta = 0.2;
  s.parameters.Delta0 = 0;
  const BranchSpec spec = spec_of(s, ProblemKind::equilibrium, P::lambda, 0, 20, Direction::both);
  const SceneCurve c = continue_curve(spec, curve_of(CurveKind::LP, P::Delta, 0.1, 2));
  ASSERT_TRUE(c.started) << c.message;
  EXPECT_EQ(c.system, CurveSystem::fold);
  const SpecialPoint* lp = find_special_point(c.one.branch.branch, SpecialPointType::LP);
  ASSERT_NE(lp, nullptr);
  const Scene at = with_parameter(s, P::lambda, lp->p);
  const SceneTwoParameterProblem<ReducedEquilibriumProblem> base(at, P::lambda, P::Delta);
  const FoldCurveProblem fold(base, *lp, 0.2);
  ContinuationOptions engine = spec.engine;
  engine.p_min = 0.1;
  engine.p_max = 2;
  const Branch direct = continue_branch(fold, fold.start(), 0.2, engine);
  expect_same_branch(c.curve.branch, direct);
  EXPECT_EQ(c.start_p2, 0.2);
  EXPECT_EQ(c.curve.measure_names, (std::vector<std::string>{"r", "Psi"}));
  // Lambda(lambda, Delta) = 1 along the curve, where r = 1 (closed form; Newton to 1e-12).
  for (std::size_t k = 0; k < direct.points.size(); ++k) {
    Parameters q = s.parameters;
    q.lambda = direct.points[k].parameters[0];
    q.Delta = direct.points[k].parameters[1];
    EXPECT_NEAR(q.Lambda(), 1.0, 1e-9);
    EXPECT_NEAR(c.curve.number(k, "r"), 1.0, 1e-9);
  }
}

TEST(SceneCurve, ModalBPCurveUsesTheSymmetryBreakingSystem) {
  const SceneCurve c = continue_curve(modal_spec(), curve_of(CurveKind::BP, P::B, 0.5, 2));
  ASSERT_TRUE(c.started) << c.message;
  EXPECT_EQ(c.system, CurveSystem::modal_branch_point);
  const Scene at = with_parameter(modal_fixtures::scene(0.08, 6), P::C, c.start.p);
  const SceneTwoParameterProblem<ModalEquilibriumProblem> base(at, P::C, P::B);
  const ModalBranchPointCurve curve(at, P::C, P::B, critical_mode(base.at(1.0), c.start.x, c.start.p));
  EXPECT_EQ(curve.mode(), 3);
  ContinuationOptions engine = modal_spec().engine;
  engine.p_min = 0.5;
  engine.p_max = 2;
  engine.direction = Direction::both;
  expect_same_branch(c.curve.branch, continue_branch(curve, curve.start(c.start.x, c.start.p), 1.0, engine));
  EXPECT_EQ(c.curve.measure_names, measure_names(ProblemKind::modal, 6));
  EXPECT_EQ(c.curve.number(0, "Delta_3"), 0.0);  // on the ellipsoidal branch
}

TEST(SceneCurve, NoLocatedPointIsAReasonNotAnException) {
  const SceneCurve c = continue_curve(orbit_spec(), curve_of(CurveKind::NS, P::C, -INFINITY, INFINITY));
  EXPECT_FALSE(c.started);
  EXPECT_NE(c.message.find("no located NS point number 1"), std::string::npos) << c.message;
  EXPECT_TRUE(c.curve.branch.points.empty());
}

// The Z2-reduced BP system of the ellipsoidal modal orbit against the generic one: decided from the
// start point's state (v~, a_l within symmetric_tol), the rest shape's tilt and whether beta is free.
TEST(SceneCurve, BranchPointSystemChoice) {
  const Scene s = test::in_plane_modal(1, 2, 0.07, 4);  // beta = pi/2: no m = 1 forcing
  SpecialPoint sp;
  sp.type = SpecialPointType::BP;
  sp.x = Eigen::VectorXd::Zero(2 * 7);  // two segments of (Re z, Im z, w, Re v~, Im v~, a_3, a_4)
  sp.x.head(3) << 0.6, -0.2, 0.77;
  sp.x.tail(7).setConstant(0.3);  // only the first segment (the state at t = 0) decides
  const auto system = [&](ProblemKind kind, P q1, P q2, const Scene& scene) {
    return curve_system(kind, CurveKind::BP, scene, q1, q2, sp);
  };
  EXPECT_EQ(system(ProblemKind::modal_orbit, P::C, P::B, s), CurveSystem::ellipsoidal_orbit_branch_point);
  sp.x[5] = 1e-8;  // a_3 at the tolerance: still the ellipsoidal orbit
  EXPECT_EQ(system(ProblemKind::modal_orbit, P::C, P::B, s), CurveSystem::ellipsoidal_orbit_branch_point);
  sp.x[5] = 2e-8;  // l >= 3 content: the generic system
  EXPECT_EQ(system(ProblemKind::modal_orbit, P::C, P::B, s), CurveSystem::branch_point);
  EXPECT_EQ(curve_system(ProblemKind::modal_orbit, CurveKind::BP, s, P::C, P::B, sp, 1e-7),
            CurveSystem::ellipsoidal_orbit_branch_point);
  sp.x[5] = 0;
  sp.x[3] = 1e-3;  // v~ != 0: a tilted orbit
  EXPECT_EQ(system(ProblemKind::modal_orbit, P::C, P::B, s), CurveSystem::branch_point);
  sp.x[3] = 0;
  EXPECT_EQ(system(ProblemKind::modal_orbit, P::beta, P::B, s), CurveSystem::branch_point);  // beta free
  EXPECT_EQ(system(ProblemKind::modal_orbit, P::C, P::beta, s), CurveSystem::branch_point);
  Scene tilted = s;
  tilted.beta = 1.0;  // the rest shape's m = 1 content forces v~
  EXPECT_EQ(system(ProblemKind::modal_orbit, P::C, P::B, tilted), CurveSystem::branch_point);
  tilted.parameters.C = INFINITY;  // no elastic memory: no forcing, whatever the tilt
  EXPECT_EQ(system(ProblemKind::modal_orbit, P::lambda, P::B, tilted), CurveSystem::ellipsoidal_orbit_branch_point);
  EXPECT_EQ(system(ProblemKind::modal, P::C, P::B, s), CurveSystem::modal_branch_point);
  for (ProblemKind k : {ProblemKind::equilibrium, ProblemKind::full, ProblemKind::orbit})
    EXPECT_EQ(system(k, P::C, P::B, s), CurveSystem::branch_point) << to_string(k);
  for (const auto& [type, expected] :
       {std::pair{CurveKind::LP, CurveSystem::fold}, std::pair{CurveKind::LPC, CurveSystem::fold},
        std::pair{CurveKind::HB, CurveSystem::hopf}, std::pair{CurveKind::PD, CurveSystem::period_doubling},
        std::pair{CurveKind::NS, CurveSystem::neimark_sacker}})
    EXPECT_EQ(curve_system(ProblemKind::modal_orbit, type, s, P::C, P::B, sp), expected) << to_string(type);
}

// ---- names and validation ----

TEST(SceneContinuation, KindAndCurveNamesRoundTrip) {
  for (ProblemKind k :
       {ProblemKind::equilibrium, ProblemKind::modal, ProblemKind::full, ProblemKind::orbit, ProblemKind::modal_orbit})
    EXPECT_EQ(problem_kind_from_string(to_string(k)), k);
  EXPECT_EQ(to_string(ProblemKind::modal_orbit), "modal-orbit");
  std::string m;
  EXPECT_EQ(invalid_parameter([] { (void)problem_kind_from_string("cycle"); }, &m), "kind");
  EXPECT_NE(m.find("kind = 'cycle' is not available: must be equilibrium, orbit, modal, modal-orbit or full"),
            std::string::npos)
      << m;
  for (CurveKind c : {CurveKind::LP, CurveKind::BP, CurveKind::HB, CurveKind::LPC, CurveKind::PD, CurveKind::NS})
    EXPECT_EQ(curve_kind_from_string(to_string(c)), c);
  EXPECT_EQ(invalid_parameter([] { (void)curve_kind_from_string("EP"); }), "curve");
  EXPECT_EQ(model_level(ProblemKind::modal_orbit), ModelLevel::modal);
  EXPECT_EQ(default_beta(ProblemKind::orbit), M_PI / 2);
  EXPECT_EQ(default_beta(ProblemKind::full), 0.0);
  EXPECT_FALSE(is_csv_measure("trivial_multiplier"));
  EXPECT_TRUE(is_csv_measure("r_min"));
}

TEST(SceneContinuation, ValidateNamesTheField) {
  std::string m;
  EXPECT_NO_THROW(BranchSpec{}.validate());  // the defaults (Fig. 3's parameters, lambda) are valid
  BranchSpec s = orbit_spec();
  s.switch_at_bp = true;
  EXPECT_EQ(invalid_parameter([&] { s.validate(); }, &m), "switch_at_bp");
  EXPECT_NE(m.find("available for --kind equilibrium, modal and full"), std::string::npos) << m;
  s = orbit_spec();
  s.orbit.segments = 0;
  EXPECT_EQ(invalid_parameter([&] { s.validate(); }, &m), "segments");
  s = orbit_spec();
  s.scene.model = ModelLevel::modal;
  EXPECT_EQ(invalid_parameter([&] { s.validate(); }, &m), "model");
  EXPECT_NE(m.find("model = modal is not available for --kind orbit: must be reduced (or auto)"), std::string::npos)
      << m;
  s = orbit_spec();
  s.relax_T = -1;
  EXPECT_EQ(invalid_parameter([&] { s.validate(); }), "relax_T");
  s = orbit_spec();
  s.engine.initial_step = -1;
  EXPECT_EQ(invalid_parameter([&] { s.validate(); }), "initial_step");
  // The branch starts at the scene's value, which must lie within the (domain-clipped) bounds.
  s = spec_of(test::fig2_in_plane(1.0), ProblemKind::orbit, P::beta, 0, 1, Direction::both);
  EXPECT_EQ(invalid_parameter([&] { s.validate(); }, &m), "min");
  EXPECT_NE(m.find("beta = 1.570796327, outside [--min, --max] = [0, 1]"), std::string::npos) << m;
  EXPECT_EQ(invalid_parameter([&] { (void)continue_scene(s); }), "min");  // before any work

  CurveSpec c;
  c.parameter2 = P::B;
  c.type = CurveKind::LPC;
  EXPECT_EQ(invalid_parameter([&] { c.validate(BranchSpec{}); }, &m), "curve");
  EXPECT_NE(m.find("curve = LPC is not available for --kind equilibrium: must be LP, BP or HB"), std::string::npos)
      << m;
  c.type = CurveKind::LP;
  EXPECT_EQ(invalid_parameter([&] { c.validate(orbit_spec()); }, &m), "curve");
  EXPECT_NE(m.find("curve = LP"), std::string::npos) << m;
  EXPECT_NO_THROW(c.validate(BranchSpec{}));
  c.type = CurveKind::BP;
  EXPECT_NO_THROW(c.validate(orbit_spec()));  // BPs of cycles
  CurveSpec none = c;
  none.parameter2.reset();
  EXPECT_EQ(invalid_parameter([&] { none.validate(BranchSpec{}); }), "parameter2");
  BranchSpec lam;
  lam.parameter = P::Lambda;
  CurveSpec coupled = c;
  coupled.parameter2 = P::Delta;
  EXPECT_EQ(invalid_parameter([&] { coupled.validate(lam); }, &m), "parameter2");
  EXPECT_NE(m.find("parameter2 = Delta"), std::string::npos) << m;
  CurveSpec range = c;
  range.p2_min = 2;
  range.p2_max = 1;
  EXPECT_EQ(invalid_parameter([&] { range.validate(BranchSpec{}); }), "min2");
  CurveSpec point = c;
  point.point = 0;
  EXPECT_EQ(invalid_parameter([&] { point.validate(BranchSpec{}); }), "point");
  BranchSpec sw;
  sw.switch_at_bp = true;
  EXPECT_EQ(invalid_parameter([&] { c.validate(sw); }), "switch_at_bp");
  SceneBranch orbit;
  orbit.spec.kind = ProblemKind::orbit;
  EXPECT_EQ(invalid_parameter([&] { (void)switch_at_bp(orbit); }), "switch_at_bp");
}

}  // namespace
}  // namespace rbcstab
