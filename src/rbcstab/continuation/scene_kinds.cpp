// What is continued (ProblemKind), which curve (CurveKind) and the names of both and of a direction.
#include "rbcstab/continuation/scene_kinds.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

#include "rbcstab/core/constants.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {

constexpr std::array<std::pair<CurveKind, SpecialPointType>, 7> kCurves{{{CurveKind::LP, SpecialPointType::LP},
                                                                         {CurveKind::BP, SpecialPointType::BP},
                                                                         {CurveKind::HB, SpecialPointType::HB},
                                                                         {CurveKind::LPC, SpecialPointType::LPC},
                                                                         {CurveKind::PD, SpecialPointType::PD},
                                                                         {CurveKind::NS, SpecialPointType::NS},
                                                                         {CurveKind::UZ, SpecialPointType::UZ}}};

}  // namespace

ProblemKind problem_kind_from_string(const std::string& name) {
  if (const auto kind = try_from_string<ProblemKind>(name)) return *kind;
  const std::vector<std::string>& names = enum_names<ProblemKind>();
  std::string allowed;
  for (std::size_t i = 0; i < names.size(); ++i)
    allowed += (i == 0 ? "" : i + 1 == names.size() ? " or " : ", ") + names[i];
  throw InvalidArgument("kind", "kind = '" + name + "' is not available: must be " + allowed);
}

ModelLevel model_level(ProblemKind kind) {
  switch (kind) {
    case ProblemKind::full:
      return ModelLevel::full;
    case ProblemKind::modal:
    case ProblemKind::modal_orbit:
      return ModelLevel::modal;
    default:
      return ModelLevel::reduced;
  }
}

bool is_orbit(ProblemKind kind) { return kind == ProblemKind::orbit || kind == ProblemKind::modal_orbit; }

double default_beta(ProblemKind kind) { return is_orbit(kind) ? kPi / 2 : 0.0; }

TruncationUse truncation_use(ProblemKind kind) {
  return model_level(kind) == ModelLevel::reduced ? TruncationUse::reduced : TruncationUse::analysis;
}

std::string to_string(CurveKind kind) { return to_string(special_point_type(kind)); }

CurveKind curve_kind_from_string(const std::string& name) {
  for (const auto& [k, type] : kCurves)
    if (name == to_string(type)) return k;
  throw InvalidArgument("curve", "curve = '" + name + "' is not a curve: must be LP, BP, HB, LPC, PD, NS or UZ");
}

SpecialPointType special_point_type(CurveKind kind) {
  for (const auto& [k, type] : kCurves)
    if (k == kind) return type;
  throw std::logic_error("unknown curve kind");
}

Direction direction_from_string(const std::string& name) { return from_string<Direction>(name, "direction"); }

}  // namespace rbcstab
