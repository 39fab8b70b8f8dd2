#pragma once
// The physical-map tests' cell and cheap options (physical_map_test.cpp, physical_map_slow_test.cpp).
#include <string>

#include "rbcstab/io/scene_file.hpp"
#include "rbcstab/verdict/physical_map.hpp"

namespace rbcstab::test {

// A cell near the perturbative regime (Delta = 1) whose in-plane motion turns from tumbling to swinging within
// 0.1..1e3 1/s at 25-50 mPa s (Lambda < 1 there: the vesicle limit tank-treads).
inline Scene map_cell(double eta_in = 6e-3) {
  SceneFile sf = parse_scene(
      "name = 'cell'\n[physical]\nshear_rate = 10\nviscosity = '25 mPa s'\nradius = '2.8 um'\n"
      "bending_modulus = '2e-19 J'\nshear_modulus = '6 uN/m'\ninner_viscosity = '" +
      std::to_string(eta_in * 1e3) + " mPa s'\n[parameters]\nDelta = 1\nDelta0 = 0.5\n");
  return sf.scene;
}

inline PhysicalMapOptions fast_map(double eta_lo, double eta_hi, int n) {
  PhysicalMapOptions o;
  o.min_viscosity = eta_lo;
  o.max_viscosity = eta_hi;
  o.viscosities = n;
  o.min_rate = 0.1;
  o.max_rate = 1e3;
  o.samples_per_decade = 3;
  o.rtol = 1e-4;
  o.onset = false;
  o.threads = 2;
  // The identities tested hold for any classifier settings: a shorter regime window keeps the tests fast.
  o.predictor.transient = 200;
  o.predictor.window = 400;
  return o;
}

}  // namespace rbcstab::test
