#include "rbcstab/sweep/point_io.hpp"

#include <charconv>
#include <cmath>
#include <sstream>
#include <vector>

namespace rbcstab {

std::string exact(double v) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char buf[64];
  const auto r = std::to_chars(buf, buf + sizeof buf, v);
  return std::string(buf, r.ptr);
}

namespace {
bool parse_double(const std::string& s, double& out) {
  if (s == "nan") return out = std::nan(""), true;
  if (s == "inf") return out = INFINITY, true;
  if (s == "-inf") return out = -INFINITY, true;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), out);
  return r.ec == std::errc() && r.ptr == s.data() + s.size();
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
     << exact(p.growth) << ' ' << int(p.oscillating) << ' ' << exact(p.sigma_final) << ' ' << to_string(p.status)
     << ' ' << exact(p.t_reached) << ' ' << p.steps << ' ' << p.failed_steps << ' ' << p.rhs_evaluations << ' '
     << exact(p.seconds) << " |" << reason << '\n';
  return ss.str();
}

std::optional<PointResult> point_from_line(const std::string& line, const std::string& config_hash,
                                           const DiagramSpec& spec) {
  const auto bar = line.find(" |");
  if (bar == std::string::npos) return std::nullopt;
  std::istringstream ss(line.substr(0, bar));
  std::vector<std::string> f;
  for (std::string w; ss >> w;) f.push_back(w);
  if (f.size() != 14 || f[0] != "P" || f[1] != config_hash) return std::nullopt;
  PointResult p;
  int osc = 0;
  bool ok = parse_int(f[2], p.index) && p.index < spec.size() && parse_int(f[4], p.l_Delta) &&
            parse_double(f[5], p.growth) && parse_int(f[6], osc) && parse_double(f[7], p.sigma_final) &&
            parse_double(f[9], p.t_reached) && parse_int(f[10], p.steps) && parse_int(f[11], p.failed_steps) &&
            parse_int(f[12], p.rhs_evaluations) && parse_double(f[13], p.seconds);
  if (!ok) return std::nullopt;
  const auto verdict = try_from_string<Verdict>(f[3]);
  const auto status = try_from_string<IntegrationStatus>(f[8]);
  if (!verdict || !status) return std::nullopt;
  p.verdict = *verdict;
  p.status = *status;
  p.oscillating = osc != 0;
  p.reason = line.substr(bar + 2);
  while (!p.reason.empty() && (p.reason.back() == '\n' || p.reason.back() == '\r')) p.reason.pop_back();
  p.i = int(p.index % std::size_t(spec.x.count));
  p.j = int(p.index / std::size_t(spec.x.count));
  p.x = spec.x.value(p.i);
  p.y = spec.y.value(p.j);
  return p;
}

}  // namespace rbcstab
