#pragma once
// Specs of the scene-continuation tests (scene_continuation.hpp): the modal scene's ellipsoidal branch
// in C and Fig. 2's in-plane orbit in Delta, as `rbcstab continue` runs them in the CLI tests; and the
// check that a call is refused naming a parameter.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "continuation/fig2_fixture.hpp"
#include "continuation/invalid_argument_fixture.hpp"
#include "continuation/modal_fixtures.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/scene_curve.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"
#include "rbcstab/core/error.hpp"

namespace rbcstab::test {

inline BranchSpec spec_of(const Scene& scene, ProblemKind kind, ContinuationParameter q, double lo, double hi,
                          Direction d) {
  BranchSpec s;
  s.scene = scene;
  s.kind = kind;
  s.parameter = q;
  s.engine.p_min = lo;
  s.engine.p_max = hi;
  s.engine.direction = d;
  return s;
}

inline CurveSpec curve_of(CurveKind type, ContinuationParameter q2, double lo, double hi) {
  CurveSpec c;
  c.type = type;
  c.parameter2 = q2;
  c.p2_min = lo;
  c.p2_max = hi;
  return c;
}

// The ellipsoidal branch of modal equilibria in C from 0.08 down to C_min: BPs where Upsilon_l(sigma) = 0
// (the first, l = 3, at C = 0.036169).
inline BranchSpec modal_spec(int L = 6, double C_min = 0.015) {
  return spec_of(modal_fixtures::scene(0.08, L), ProblemKind::modal, ContinuationParameter::C, C_min, 0.08,
                 Direction::backward);
}

// Fig. 2's in-plane orbit from Delta = 0.3 to 0.45 (4 segments): one swinging -> tumbling transition.
inline BranchSpec orbit_spec() {
  BranchSpec s =
      spec_of(fig2_in_plane(0.3), ProblemKind::orbit, ContinuationParameter::Delta, 0.3, 0.45, Direction::forward);
  s.orbit.segments = 4;
  return s;
}

}  // namespace rbcstab::test
