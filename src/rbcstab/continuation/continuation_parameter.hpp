#pragma once
// The physical parameters a branch can be continued in: the rows of the parameter table
// (model/parameter_table.hpp) marked for continuation. They are the five material and shape numbers, the
// composites Lambda, S of the reduced system (Eq. Lambda_S), and the orientation beta of the stress-free
// (and initial) shape, which lives in the Scene.
#include <span>
#include <string>
#include <vector>

#include "rbcstab/model/parameter_table.hpp"
#include "rbcstab/model/parameters.hpp"
#include "rbcstab/model/scene.hpp"

namespace rbcstab {

using ContinuationParameter = SceneParameter;  // one of the rows usable_as(q, ParameterUse::continuation)
// "lambda", "Delta", "Delta0", "B", "C", "Lambda", "S", "beta"; throws InvalidArgument("parameter", ...).
ContinuationParameter continuation_parameter_from_string(const std::string& name);
const std::vector<std::string>& continuation_parameter_names();
// The same as one comma-separated list (help texts).
std::string continuation_parameter_list();

// "" when q moves the model `level` (the parameter table's levels); else a note that a branch in q at that level
// repeats one state, naming the levels q does move (B leaves the reduced level alone: it takes Upsilon_2 itself as
// its multiplier).
std::string unmoved_level_note(ContinuationParameter q, ModelLevel level);

// The material parameters only: beta throws InvalidArgument("parameter", ...) (use the Scene overloads).
double get_parameter(const Parameters& p, ContinuationParameter q);
// p with q set to value, validated (throws InvalidArgument naming q outside its domain).
// Lambda is moved through Delta (Lambda ~ sqrt(Delta) at fixed lambda, S unchanged) and S through C
// (S ~ C at fixed Delta0, Lambda unchanged), so each composite moves alone.
Parameters with_parameter(Parameters p, ContinuationParameter q, double value);

// Every parameter, beta included: what the problems and adapters use (get_parameter(const Scene&, q) is the
// table's). The value must lie in q's continuation domain (beta: [0, pi], 0: rest shape out of plane, pi/2:
// in plane, pi - beta is the mirror image), else InvalidArgument naming q; then the material parameters are
// validated (Lambda moves Delta, which must stay in its domain).
Scene with_parameter(Scene s, ContinuationParameter q, double value);

// The scene's initial state built with Delta0 = Delta > 0. The continuation problems take only the rest
// shape's orientation from it (its size is kappa = 1/(Lambda S) from the parameters), so a branch
// started at Delta0 = 0 keeps the orientation when continued in Delta0. Throws
// InvalidArgument("rest_delta_l") for a stress-free shape with l >= 3 content: those problems (reduced,
// modal) cannot hold it, and silently dropping it would continue a different cell.
InitialState oriented_initial_state(Scene s);

// dF/dq at (t, y) of the scene's system F (make_scene_system(scene): its level and L, which must be concrete), by
// central differences of the systems built at q +- h (h = cbrt(eps)|q|: relative error ~ eps^(2/3)), or a
// second-order one-sided difference where q - h or q + h leaves q's domain. Throws InvalidArgument("y", ...) if
// y is not of the system's dimension.
void rhs_parameter_derivative(const Scene& scene, ContinuationParameter q, double t, std::span<const double> y,
                              std::span<double> dfdq);

// Throws InvalidArgument(name, ...) unless p2 can be set independently of p1 (not equal, not Lambda with
// Delta or lambda, not S with C or Delta0: independent() of the table): the pairs of a two-parameter curve.
void require_independent(ContinuationParameter p1, ContinuationParameter p2, const std::string& name);

}  // namespace rbcstab
