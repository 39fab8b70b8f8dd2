#include "rbcstab/sweep/point_record.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

namespace {
constexpr std::size_t kFields = 16;

// A non-finite value (a failed point's growth or sigma_final) is "-": the journal never holds "nan".
std::string number_text(double v) { return std::isfinite(v) ? exact(v) : "-"; }
bool parse_double(const std::string& s, double& out) {
  if (s == "-") return out = std::nan(""), true;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size() && std::isfinite(out);
}
template <class Int>
bool parse_int(const std::string& s, Int& out) {
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
}
}  // namespace

std::string point_to_line(const PointResult& p, const std::string& config_hash) {
  std::string reason = p.reason;
  for (char& c : reason)
    if (c == '\n' || c == '\r') c = ' ';
  std::ostringstream ss;
  ss << "P " << config_hash << ' ' << p.index << ' ' << to_string(p.verdict) << ' ' << p.l_Delta << ' '
     << number_text(p.growth) << ' ' << int(p.oscillating) << ' ' << number_text(p.sigma_final) << ' '
     << to_string(p.status) << ' ' << number_text(p.t_reached) << ' ' << p.steps << ' ' << p.failed_steps << ' '
     << p.rhs_evaluations << ' ' << number_text(p.seconds) << ' ' << number_text(p.terminated_at) << ' '
     << number_text(p.margin) << " |" << reason;
  return seal_record(ss.str());
}

FieldError point_value_error(const PointResult& p, const DiagramSpec& spec, int L) {
  if (p.index >= spec.size())
    return {"index",
            "index " + std::to_string(p.index) + " is outside the grid (0.." + std::to_string(spec.size() - 1) + ")"};
  if (p.l_Delta < 2 || p.l_Delta > L)
    return {"l_Delta", "l_Delta " + std::to_string(p.l_Delta) + " is outside [2, " + std::to_string(L) + "]"};
  const Verdict v = verdict_of(p.status, p.l_Delta);
  if (p.verdict != v)
    return {"verdict", "verdict " + to_string(p.verdict) + " contradicts status " + to_string(p.status) +
                           " and l_Delta " + std::to_string(p.l_Delta) + " (which give " + to_string(v) + ")"};
  if (p.verdict != Verdict::failed) {
    if (!std::isfinite(p.growth))
      return {"growth", "growth " + exact(p.growth) + " of a " + to_string(p.verdict) + " point is not finite"};
    if (!std::isfinite(p.sigma_final))
      return {"sigma_final",
              "sigma_final " + exact(p.sigma_final) + " of a " + to_string(p.verdict) + " point is not finite"};
  }
  if (!(std::isfinite(p.t_reached) && p.t_reached >= 0))
    return {"t_reached", "t_reached " + exact(p.t_reached) + " is not finite and >= 0"};
  if (!(std::isfinite(p.seconds) && p.seconds >= 0))
    return {"seconds", "seconds " + exact(p.seconds) + " is not finite and >= 0"};
  return {};
}

ParsedPoint parse_point_line(const std::string& line, const std::string& config_hash, const DiagramSpec& spec, int L) {
  UnsealedRecord sealed = unseal_record(line);
  if (!sealed.body) return {std::nullopt, sealed.error};
  const std::string& body = *sealed.body;
  const auto bar = body.find(" |");
  if (bar == std::string::npos) return {std::nullopt, "malformed record (no ' |' before the reason)"};
  std::istringstream ss(body.substr(0, bar));
  std::vector<std::string> f;
  for (std::string w; ss >> w;) f.push_back(w);
  if (f.size() != kFields || f[0] != "P")
    return {std::nullopt, "malformed record (" + std::to_string(f.size()) + " fields, expected 'P' and " +
                              std::to_string(kFields - 1) + ")"};
  if (f[1] != config_hash)
    return {std::nullopt, "record of another configuration (hash " + f[1] + ", this run's is " + config_hash + ")"};
  PointResult p;
  int osc = 0;
  const std::pair<const char*, bool> checks[] = {{"index", parse_int(f[2], p.index)},
                                                 {"l_Delta", parse_int(f[4], p.l_Delta)},
                                                 {"growth", parse_double(f[5], p.growth)},
                                                 {"oscillating", parse_int(f[6], osc) && (osc == 0 || osc == 1)},
                                                 {"sigma_final", parse_double(f[7], p.sigma_final)},
                                                 {"t_reached", parse_double(f[9], p.t_reached)},
                                                 {"steps", parse_int(f[10], p.steps)},
                                                 {"failed_steps", parse_int(f[11], p.failed_steps)},
                                                 {"rhs_evaluations", parse_int(f[12], p.rhs_evaluations)},
                                                 {"seconds", parse_double(f[13], p.seconds)},
                                                 {"terminated_at", parse_double(f[14], p.terminated_at)},
                                                 {"margin", parse_double(f[15], p.margin)}};
  static const std::size_t field_of[] = {2, 4, 5, 6, 7, 9, 10, 11, 12, 13, 14, 15};
  for (std::size_t k = 0; k < std::size(checks); ++k)
    if (!checks[k].second)
      return {std::nullopt, std::string(checks[k].first) + " '" + f[field_of[k]] + "' is not valid"};
  try {
    p.verdict = from_string<Verdict>(f[3], "verdict");
    p.status = from_string<IntegrationStatus>(f[8], "status");
  } catch (const InvalidArgument& e) {
    return {std::nullopt, e.what()};
  }
  p.oscillating = osc != 0;
  p.reason = body.substr(bar + 2);
  if (FieldError e = point_value_error(p, spec, L); !e.empty()) return {std::nullopt, e.why};
  p.i = int(p.index % std::size_t(spec.x.count));
  p.j = int(p.index / std::size_t(spec.x.count));
  p.x = spec.x.value(p.i);
  p.y = spec.y.value(p.j);
  return {p, {}};
}

std::optional<PointResult> point_from_line(const std::string& line, const std::string& config_hash,
                                           const DiagramSpec& spec) {
  return parse_point_line(line, config_hash, spec).point;
}

}  // namespace rbcstab
