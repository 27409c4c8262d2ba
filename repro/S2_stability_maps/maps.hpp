// S2 stability maps (stability_maps.cpp says what they show): the scenes,
// the run of one (kn, dt) cell and its class, here so that the negative
// controls (controls.cpp beside it) apply the same classification.
#pragma once
#include <string>
#include <vector>

#include "dda/scene.hpp"
#include "repro/S_common/stability.hpp"
#include "repro/common/shapes.hpp"

namespace s2 {

inline constexpr double kG = 9.81;  // m/s^2

using repro::rect;

// One map: a two-block collision and what its classification needs.
struct MapScene {
  std::string name, title;
  dda::Scene scene;
  int a = 0, b = 1;              // approach: b's centroid - a's centroid > 0 while in order
  dda::Vec2 axis{1.0, 0.0};      // approach axis
  double rel_mass = 0.0;         // mass of the relative mode, kg
  double impact_energy = 0.0;    // J
  double contact_length = 1.0, h_sum_inv = 0.0;  // flat contact: L, 1/H_a + 1/H_b
};

// Sect. 4.1's two squares, A at 1 m/s, starting 1 mm apart (unified H).
MapScene two_squares_map();
// Sect. 5.1's bouncing block, case 1 (B 0.1 m high), A 1 mm above B at the
// 3.13 m/s of its 0.5 m fall, gravity on, with the H rule h.
MapScene bouncing_map(dda::HRule h);

// Run length: 2 ms (the 1 mm gap) + 4 contact half-periods pi/omega, at most
// 0.4 s, and never fewer than 10 steps.
double window(const MapScene& m, double kn, double dt);

struct MapRun {
  repro::stab::RunClass cls = repro::stab::RunClass::kStable;
  double window = 0.0, energy_change = 0.0, max_growth = 0.0;
  double ratio0 = 0.0, ratio_max = 0.0;  // dt / predicted, max dt / current
  std::string message;
};

// One cell, classified:
//  - blow-up: the state diverges: the solver stops on a non-finite state or
//    an area collapse, or the step-motion guard stops a run whose energy had
//    grown. A stop by the energy-budget guard alone is an accuracy stop
//    (Verlet's energy error near its limit is large but bounded): the cell
//    is run again with that guard off and classified by that run, the
//    guard's message kept in `message`;
//  - flip-through: the penetration guard stops it (a soft kn passes through
//    at any dt), the step-motion guard stops it before the energy grew, or
//    the centroids end in the wrong order along the axis;
//  - energy growth: total energy at the end above the start by more than
//    1 % of the impact energy;
//  - else stable.
// balance_guard false: the energy-budget guard off from the start.
MapRun map_run(const MapScene& m, double kn, double dt, bool balance_guard = true);

// A cell with dt <= bound that map_run calls a blow-up; its negative control.
inline constexpr const char* kControlBlowUp = "S2 no blow-up: FAIL against a bound 4 times too large";
inline bool blowup_at_or_below(const MapRun& r, double dt, double bound) {
  return r.cls == repro::stab::RunClass::kBlowUp && dt <= bound;
}
// The row "no blow-up and no pass-through at dt <= the predicted dt_crit"
// counts the cells with dt <= bound that map_run calls a blow-up or a
// flip-through: a pass-through is a failure of the method on that case
// whatever the time step; its negative control.
inline constexpr const char* kControlFailBelow =
    "S2 no blow-up or pass-through: FAIL against a bound 4 times too large and at a kn that passes through";
inline bool fails_at_or_below(const MapRun& r, double dt, double bound) {
  return dt <= bound && (r.cls == repro::stab::RunClass::kBlowUp || r.cls == repro::stab::RunClass::kFlipThrough);
}

}  // namespace s2
