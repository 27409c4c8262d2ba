// S2, part 1 (stability_maps.cpp): the resting contacts whose stability
// limit the solver's critical steps are checked against, the empirical limit
// by bisection, and the rows' criteria, here so that the negative controls
// (controls.cpp beside it) apply the same ones.
#pragma once
#include <string>

#include "dda/scene.hpp"
#include "dda/simulation.hpp"

namespace s2 {

struct RestCase {
  std::string name;
  dda::Scene scene;
};

// A 1 m square A (two_high: on a free 2 m x 1 m block on) a fixed 4 m x 0.1 m
// block, each at its static penetration, every mode seeded by 1e-9 m/s and
// 1e-9 rad/s. H: unified (min-max edge) or inscribed radius.
RestCase resting(double kn, bool inscribed, bool strains, bool two_high);

// Whether the resting contact is unstable at dt over `steps` steps: the
// mechanical energy grows tenfold, a guard stops the run, or a contact of the
// rest state opens.
bool unstable(dda::Scene s, double dt, int steps);

// The empirical stability limit: bisection on dt between 0.3 and 3 times
// `guess` (kBisections halvings of the log interval, kBisectionSteps steps
// per trial).
inline constexpr int kBisections = 14;
inline constexpr int kBisectionSteps = 20000;
double empirical_limit(const dda::Scene& s, double guess);

// A simpler per-block estimate, for comparison: per free block k = kn L_max
// 2 / H_i, omega^2 = max(k/m + k r^2 / I, strain modes).
double old_prior(const dda::Simulation& sim);

// Row "the linearised dt_crit is the empirical stability limit": the largest
// |empirical / linearised - 1| over the cases stays below this (14 halvings
// of the factor-10 interval resolve the limit to ~0.1 %, the linearisation
// by central differences to round-off).
inline constexpr double kEmpiricalTolerance = 0.02;
inline bool linearised_is_empirical(double worst_relative_gap) { return worst_relative_gap < kEmpiricalTolerance; }
// Row "the solver's critical steps never exceed the linearised limit":
// the largest current / linearised and predicted / linearised ratios.
inline bool solver_steps_are_safe(double worst_current_ratio, double worst_predicted_ratio) {
  return worst_current_ratio <= 1.0 && worst_predicted_ratio <= 1.0;
}
inline constexpr const char* kControlEmpirical =
    "S2 dt_crit: FAIL when the linearised limit is taken at 4 times the contact's kn";
inline constexpr const char* kControlSafe = "S2 dt_crit: FAIL for critical steps taken at a sixteenth of the contact's kn";

}  // namespace s2
