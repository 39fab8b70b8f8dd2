#pragma once
// The names a scene continuation is asked in: what is continued (ProblemKind), the curve of which special
// point (CurveKind) and the system that continues it (CurveSystem), and a branch's direction by name.
#include <string>

#include "rbcstab/analysis/truncation.hpp"
#include "rbcstab/continuation/continuation.hpp"
#include "rbcstab/core/enum_table.hpp"
#include "rbcstab/model/system.hpp"

namespace rbcstab {

// What is continued: equilibria of the reduced system, of the modal model or of the full model, or
// periodic orbits of the forced in-plane reduced system or modal model.
enum class ProblemKind { equilibrium, modal, full, orbit, modal_orbit };
template <>
struct EnumTable<ProblemKind> {  // in the order messages list the kinds
  static constexpr EnumName<ProblemKind> entries[] = {{ProblemKind::equilibrium, "equilibrium"},
                                                      {ProblemKind::orbit, "orbit"},
                                                      {ProblemKind::modal, "modal"},
                                                      {ProblemKind::modal_orbit, "modal-orbit"},
                                                      {ProblemKind::full, "full"}};
};
ProblemKind problem_kind_from_string(const std::string& name);  // throws InvalidArgument("kind", ...)
ModelLevel model_level(ProblemKind kind);                       // reduced, modal or full
bool is_orbit(ProblemKind kind);
// How the truncation policy treats a kind's L: the reduced kinds do not use it; modal and full equilibria
// and modal orbits are analyses with no simulation horizon (resolve_truncation).
TruncationUse truncation_use(ProblemKind kind);
// The rest shape's orientation a kind needs when the user gives none: equilibria need an autonomous
// system (rest shape out of plane, 0), periodic orbits a forced one (in plane, pi/2).
double default_beta(ProblemKind kind);

// direction_from_string throws InvalidArgument("direction", ...) naming the allowed directions.
Direction direction_from_string(const std::string& name);

// The curve of a special point in two parameters: LP, BP, HB of equilibria; LPC, PD, NS, BP of orbits;
// UZ: a user event's zero set (orbits: the swinging <-> tumbling transition, event_curve.hpp).
enum class CurveKind { LP, BP, HB, LPC, PD, NS, UZ };
std::string to_string(CurveKind kind);
CurveKind curve_kind_from_string(const std::string& name);  // throws InvalidArgument("curve", ...)
SpecialPointType special_point_type(CurveKind kind);

// The system that continues a curve: the fold (LP, LPC), Hopf and period-doubling minimal augmentations,
// the Neimark-Sacker system, the generic 2n + 2 branch-point system, and the two symmetry-reduced BP
// systems: ModalBranchPointCurve (modal equilibria) and ModalOrbitBranchPointCurve (Z2-reduced, the
// in-plane ellipsoidal modal orbit); event: F = 0 plus the event's smooth form (EventCurveProblem).
enum class CurveSystem {
  fold,
  hopf,
  period_doubling,
  neimark_sacker,
  branch_point,
  modal_branch_point,
  ellipsoidal_orbit_branch_point,
  event
};
template <>
struct EnumTable<CurveSystem> {
  static constexpr EnumName<CurveSystem> entries[] = {
      {CurveSystem::fold, "fold"},
      {CurveSystem::hopf, "hopf"},
      {CurveSystem::period_doubling, "period_doubling"},
      {CurveSystem::neimark_sacker, "neimark_sacker"},
      {CurveSystem::branch_point, "branch_point"},
      {CurveSystem::modal_branch_point, "modal_branch_point"},
      {CurveSystem::ellipsoidal_orbit_branch_point, "ellipsoidal_orbit_branch_point"},
      {CurveSystem::event, "event"}};
};

}  // namespace rbcstab
