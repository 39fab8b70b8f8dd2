#pragma once
// A closed-form quantity together with the domain it was evaluated in: never NaN. Outside its
// domain a formula returns status outside_domain, a finite placeholder value (0) and the reason.
#include <string>
#include <utility>

#include "rbcstab/core/enum_table.hpp"

namespace rbcstab {

enum class DomainStatus {
  ok,              // inside the formula's domain
  limit,           // at an edge of the domain: value is the finite limit (reason says which)
  outside_domain,  // the formula does not apply: value is 0, reason says why
};
template <>
struct EnumTable<DomainStatus> {
  static constexpr EnumName<DomainStatus> entries[] = {
      {DomainStatus::ok, "ok"}, {DomainStatus::limit, "limit"}, {DomainStatus::outside_domain, "outside_domain"}};
};

struct Quantity {
  double value = 0;
  DomainStatus status = DomainStatus::ok;
  std::string reason;  // empty when ok

  bool valid() const { return status != DomainStatus::outside_domain; }
  static Quantity of(double v) { return {v, DomainStatus::ok, {}}; }
  static Quantity at_limit(double v, std::string why) { return {v, DomainStatus::limit, std::move(why)}; }
  static Quantity outside(std::string why) { return {0.0, DomainStatus::outside_domain, std::move(why)}; }
};

}  // namespace rbcstab
