#pragma once
// The boundary on a plane with a ln B axis, exactly: one reduced solution per value u of the other axis (the
// in-plane asymptotic criterion's periodic orbit, or the finite-horizon criterion's transient). The reduced flow
// holds no B (verdict/asymptotic.hpp, analysis/predictors.hpp), so at fixed u every quantity of the criterion is
// affine in B: <sigma_R>(B) (orbit_sigma_average_at_B; <sigma_R>_T through transient_at_B, since
// G_l(T) = T Upsilon_l(<sigma_R>_T)) and sigma_l^c(B/C), hence
// e_l(B) = <sigma_R> - sigma_l^c = a_l + m_l B with a_l = e_l(0) = sigma_2^c(0) - sigma_l^c(0) = Pi_l - 6 > 0.
// Mode l grows (mu_l > 0, i.e. e_l < 0) iff m_l < 0 and B > B_l* = 1/r_l, r_l = -m_l/a_l: the unstable set at u is
// the half-line B > B*(u) = 1/max_l r_l (none where every r_l <= 0), and the boundary is the graph
// ln B = -ln max_l r_l(u), its mode the argmax, which is the argmax of sigma_l^c at B* (the verdict's active
// mode) since e_l(B*) >= 0 = e_active there. The tracer samples u (adaptively, to the step cap), and locates
// edge exits (the verdict's margin on the edge) and corners (r_l = r_l') by Brent's method on u.
#include <optional>
#include <string>

#include "rbcstab/model/scene.hpp"
#include "rbcstab/sweep/diagram.hpp"
#include "rbcstab/sweep/trace.hpp"

namespace rbcstab::detail {

// The plane and options allow it: the finite-horizon criterion, or the asymptotic criterion by periodic orbits
// (orbit.enabled) on a base scene in plane; one axis ln B and the other one that does not move B (independent():
// not alpha or shear_rate), no fixed alpha, and TraceMethod::automatic.
bool closed_form_in_B_applies(const Scene& base, const DiagramSpec& plane, const TraceOptions& options);

struct InBTrace {
  std::optional<TraceResult> result;  // empty: a sampled value's orbit or transient was not usable (why): the
                                      // caller falls back
  std::string why;
  std::size_t evaluations = 0;  // orbit solves or transients, also when empty
};
// Requires closed_form_in_B_applies. `criterion` is carried into each curve.
InBTrace trace_in_B(const Scene& base, const DiagramSpec& plane, const TraceOptions& options,
                    const std::string& criterion);

}  // namespace rbcstab::detail
