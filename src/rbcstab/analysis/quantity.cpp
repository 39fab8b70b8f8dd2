#include "rbcstab/analysis/quantity.hpp"

namespace rbcstab {

std::string to_string(DomainStatus s) {
  switch (s) {
    case DomainStatus::ok: return "ok";
    case DomainStatus::limit: return "limit";
    case DomainStatus::outside_domain: return "outside_domain";
  }
  return "unknown";
}

}  // namespace rbcstab
