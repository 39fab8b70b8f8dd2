#pragma once
// The in-plane scene whose orbit start used to be wrong: lambda = 15.5, Delta = 0.05754, Delta0 = 1e-6,
// C = 0.0412, B = 2 (Lambda = 1.19991, S = 199.99), rest shape in the flow plane, no l >= 3 content. Two
// periodic orbits lie 6e-3 apart: an attracting one (complex multipliers |mu| = 0.97659) and a
// repelling one (|mu| = 1.02397); the attracting one contracts so slowly that Newton from the state
// relaxed for T = 200 (32 periods) converged to the repelling one.
#include <cmath>

#include "continuation/scene_spec_fixture.hpp"
#include "rbcstab/continuation/branch_spec.hpp"
#include "rbcstab/continuation/scene_kinds.hpp"

namespace rbcstab::test {

inline Scene wrong_start_scene() {
  Scene s;
  s.name = "wrong_start";
  s.parameters.lambda = 15.5;
  s.parameters.Delta = 0.05754;
  s.parameters.Delta0 = 1e-6;
  s.parameters.C = 0.04120;
  s.parameters.B = 2;
  s.beta = M_PI / 2;
  s.delta = 0;
  s.L = 2;
  s.model = ModelLevel::reduced;
  return s;
}

// `rbcstab continue --kind orbit --parameter Lambda --min 1.1 --max 1.3` on that scene.
inline BranchSpec wrong_start_spec() {
  return spec_of(wrong_start_scene(), ProblemKind::orbit, ContinuationParameter::Lambda, 1.1, 1.3, Direction::both);
}

}  // namespace rbcstab::test
