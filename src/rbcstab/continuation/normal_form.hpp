#pragma once
// The normal form of an equilibrium branch's special point (LP, BP, HB) as plain data: what it is, its
// coefficients by name, its criticality and the amplitude law of the branch (or orbit) it predicts. Computed by
// normal_form_analysis.hpp; conventions and formulas in docs/continuation.md ("Normal forms").
#include <limits>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <utility>
#include <vector>

#include "rbcstab/core/enum_table.hpp"

namespace rbcstab {

// branch_point: unclassified; fold_of_cycles, period_doubling, neimark_sacker: an LPC, PD, NS of a forced orbit's
// period map
enum class NormalFormKind {
  fold,
  transcritical,
  pitchfork,
  branch_point,
  hopf,
  period_doubling,
  fold_of_cycles,
  neimark_sacker
};
template <>
struct EnumTable<NormalFormKind> {
  static constexpr EnumName<NormalFormKind> entries[] = {{NormalFormKind::fold, "fold"},
                                                         {NormalFormKind::transcritical, "transcritical"},
                                                         {NormalFormKind::pitchfork, "pitchfork"},
                                                         {NormalFormKind::branch_point, "branch_point"},
                                                         {NormalFormKind::hopf, "hopf"},
                                                         {NormalFormKind::period_doubling, "period_doubling"},
                                                         {NormalFormKind::fold_of_cycles, "fold_of_cycles"},
                                                         {NormalFormKind::neimark_sacker, "neimark_sacker"}};
};

// supercritical: the emanating branch (orbit, invariant circle) exists where the known branch is unstable, and is
// stable in the critical direction (a pitchfork) / soft (a Hopf with l1 < 0); subcritical: the opposite; degenerate:
// the deciding coefficient vanishes to its accuracy, or the point is not simple (note says which); not_applicable: a
// fold or a transcritical point (no such notion); not_computed: note says why.
enum class Criticality { supercritical, subcritical, degenerate, not_applicable, not_computed };
template <>
struct EnumTable<Criticality> {
  static constexpr EnumName<Criticality> entries[] = {{Criticality::supercritical, "supercritical"},
                                                      {Criticality::subcritical, "subcritical"},
                                                      {Criticality::degenerate, "degenerate"},
                                                      {Criticality::not_applicable, "not_applicable"},
                                                      {Criticality::not_computed, "not_computed"}};
};

struct NormalForm {
  NormalFormKind kind = NormalFormKind::branch_point;
  std::vector<std::pair<std::string, double>> coefficients;  // by name, in a fixed order per kind
  Criticality criticality = Criticality::not_computed;
  // The amplitude law of the emanating branch (LP: the branch itself; HB: the orbit's peak |x - x*|_2; LPC, PD,
  // NS: the orbit's, the doubled orbit's, the invariant circle's state at t = 0):
  //   |x - x*|_2 ~ amplitude |p - p*|^exponent   on the side sign(p - p*) = side (0: both sides).
  // NaN where unknown.
  double amplitude = std::numeric_limits<double>::quiet_NaN();
  double exponent = std::numeric_limits<double>::quiet_NaN();
  double side = std::numeric_limits<double>::quiet_NaN();
  std::string note;  // why degenerate or not computed; "" otherwise

  // The coefficient `name`; NaN if it has none of that name.
  double coefficient(const std::string& name) const;
};

// {"kind", "criticality", "coefficients": {name: value}, "amplitude", "exponent", "side" (null where unknown), "note"}:
// the "normal_form" of a special point in the Branch JSON and the branch files; from_json reads it back and throws
// InvalidArgument("normal_form", ...) naming a missing or wrong key.
nlohmann::json to_json(const NormalForm& nf);
NormalForm normal_form_from_json(const nlohmann::json& j);

// "pitchfork, supercritical, |x - x*| ~ 0.53 |p - p*|^(1/2) for p > p*" (the text summary's words).
std::string to_text(const NormalForm& nf, const std::string& parameter);

}  // namespace rbcstab
