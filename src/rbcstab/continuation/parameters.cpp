#include "rbcstab/continuation/parameters.hpp"

#include <cmath>

#include "rbcstab/core/error.hpp"

namespace rbcstab {

const std::vector<std::string>& continuation_parameter_names() {
  static const std::vector<std::string> names{"lambda", "Delta", "Delta0", "B", "C", "Lambda", "S", "beta"};
  return names;
}

std::string to_string(ContinuationParameter q) {
  return continuation_parameter_names()[static_cast<std::size_t>(q)];
}

ContinuationParameter continuation_parameter_from_string(const std::string& name) {
  const auto& names = continuation_parameter_names();
  for (std::size_t k = 0; k < names.size(); ++k)
    if (names[k] == name) return static_cast<ContinuationParameter>(k);
  throw InvalidArgument("parameter", "parameter = '" + name +
                                         "' is not a continuation parameter: must be one of lambda, Delta, "
                                         "Delta0, B, C, Lambda, S, beta");
}

namespace {
[[noreturn]] void beta_is_a_scene_parameter() {
  throw InvalidArgument("parameter", "parameter = beta is the rest shape's orientation, a scene parameter, not a "
                                     "material one (internal: use the Scene overload)");
}
}  // namespace

double get_parameter(const Parameters& p, ContinuationParameter q) {
  switch (q) {
    case ContinuationParameter::lambda: return p.lambda;
    case ContinuationParameter::Delta: return p.Delta;
    case ContinuationParameter::Delta0: return p.Delta0;
    case ContinuationParameter::B: return p.B;
    case ContinuationParameter::C: return p.C;
    case ContinuationParameter::Lambda: return p.Lambda();
    case ContinuationParameter::S: return p.S();
    case ContinuationParameter::beta: break;
  }
  beta_is_a_scene_parameter();
}

Parameters with_parameter(Parameters p, ContinuationParameter q, double value) {
  require_finite(to_string(q), value);
  switch (q) {
    case ContinuationParameter::lambda: p.lambda = value; break;
    case ContinuationParameter::Delta: p.Delta = value; break;
    case ContinuationParameter::Delta0: p.Delta0 = value; break;
    case ContinuationParameter::B: p.B = value; break;
    case ContinuationParameter::C: p.C = value; break;
    case ContinuationParameter::Lambda:
      require(value > 0, "Lambda", value, "a number > 0");
      p.Delta *= (value / p.Lambda()) * (value / p.Lambda());
      break;
    case ContinuationParameter::S: {
      const double S = p.S();
      require(std::isfinite(S), "S", value, "continuable only from a finite S (Delta0 > 0 and C finite)");
      require(value > 0, "S", value, "a number > 0");
      p.C *= value / S;
      break;
    }
    case ContinuationParameter::beta:
      beta_is_a_scene_parameter();
  }
  p.validate();
  return p;
}

double get_parameter(const Scene& s, ContinuationParameter q) {
  return q == ContinuationParameter::beta ? s.beta : get_parameter(s.parameters, q);
}

Scene with_parameter(Scene s, ContinuationParameter q, double value) {
  if (q != ContinuationParameter::beta) {
    s.parameters = with_parameter(s.parameters, q, value);
    return s;
  }
  require(std::isfinite(value) && value >= 0 && value <= M_PI, "beta", value,
          "[0, pi] (0: rest shape out of plane, pi/2: in plane)");
  s.beta = value;
  return s;
}

void require_independent(ContinuationParameter p1, ContinuationParameter p2, const std::string& name) {
  // Lambda is moved through Delta and depends on lambda; S is moved through C and depends on Delta0:
  // setting one of a coupled pair would undo the other.
  using P = ContinuationParameter;
  auto coupled = [](P a, P b) {
    return a == b || (a == P::Lambda && (b == P::Delta || b == P::lambda)) || (a == P::S && (b == P::C || b == P::Delta0));
  };
  if (coupled(p1, p2) || coupled(p2, p1))
    throw InvalidArgument(name, name + " = " + to_string(p2) + " is not independent of the first parameter " + to_string(p1) +
                                    ": choose two of lambda, Delta, Delta0, B, C, beta, or a composite (Lambda, S) with a "
                                    "parameter it does not depend on");
}

InitialState oriented_initial_state(Scene s) {
  for (const auto& [l, d] : s.rest_delta_l)
    if (d > 0)
      throw InvalidArgument("rest_delta_l", "rest_delta_l[" + std::to_string(l) + "] = " + std::to_string(d) +
                                                ": the stress-free shape has l >= 3 content, which only the full model "
                                                "holds; the reduced and modal problems would drop it (use the full "
                                                "level: FullEquilibriumProblem, rbcstab continue --kind full)");
  s.parameters.Delta0 = s.parameters.Delta;
  return initial_state(s);
}

}  // namespace rbcstab
