// Beyond Paper A Sect. 5 (extreme_geometry.cpp says what it measures): the
// cases, one attempt at a dt, and the "clean" criterion, here so that the
// negative controls (controls.cpp beside this file) apply the same one.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "dda/contact.hpp"
#include "dda/scene.hpp"
#include "dda/simulation.hpp"
#include "repro/common/claims.hpp"

namespace extreme {

// A scene plus what to watch in it.
struct Case {
  std::string family;     // "5.1", "5.2", "5.3"
  std::string label;      // e.g. "B height 1e-3 m, unified H"
  double parameter = 0.0; // the swept size (m or deg)
  dda::Scene scene;
  int a = 0, b = 1;       // the contact pair
  int pushed = 1;         // block whose normal force must point up (+y)
  bool apart_at_end = true;  // must the pair be apart at the end?
  double floor_y = -1e300;   // 5.1: A's lowest point must stay above this
  double thin_height = 0.0;  // 5.1: B's height (the block that may be pierced), m
  // Symmetry error of the current state; empty if the scene has none.
  std::function<double(const dda::Simulation&)> asymmetry;
};

struct Outcome {
  bool finished = false, clean = false;
  bool flip = false, pierced = false, energy_bad = false, asymmetric = false, still_touching = false;
  std::string verdict;  // "clean" or the reason
  double dt = 0.0, dt_crit = 0.0;
  double dt_strain = 0.0;  // stability limit of the blocks' own strain modes alone, s
  double energy_error = 0.0, energy_growth = 0.0;
  double asymmetry = -1.0;  // largest, m (up to the stop for a run the solver stopped); -1: not applicable
  double thickness = 0.0, depth = 0.0;
  double min_push = 0.0;   // most negative normal force on the pushed block along y, N
  double below = 0.0;      // 5.1: how far A's base went below B's bottom, m (0 if never)
  double max_up = 0.0;     // largest upward velocity of the pushed block after the first contact, m/s
  double first_release_asymmetry = -1.0;  // asymmetry when the first contact ends, m (-1: never / n/a)
  double seconds = 0.0;
  long steps = 0;
};

// One run of case c at dt (motion_guard false: the step-motion guard off),
// judged by the criterion of the rows: clean if it finishes, shows no
// flip-through (the pushed block's normal force never pulls it in; for 5.1
// it does not end below B), is not pierced, is apart at the end where it
// must be, has an energy error < 1 % and, where the scene is symmetric, an
// asymmetry < 1e-9 m.
Outcome attempt(const Case& c, double dt, bool motion_guard,
                dda::Integration integration = dda::Integration::kPaperBisector);

// The 5.1, 5.2 and 5.3 cases of the sweep (paper sizes first).
std::vector<Case> make_cases();

// Summary of one outcome for the report row; pm: 3 significant digits.
std::string describe(const Outcome& o);
std::string pm(double x);

// The negative control of the "clean" criterion (controls.cpp beside this file).
inline constexpr const char* kCleanControl =
    "repro_controls: 5.4 clean: FAIL on a damped, an asymmetric and a pierced run";

// ---- diagnosis of a run that is not clean (diagnosis.cpp) -------------------

// Why a run that is not clean at the paper's dt fails, derived from the
// diagnoses: d1 = stable step (<= 0.5 dt_crit) with the step-motion guard
// off, d2 = d1 with the exact integration, d3 = d1 with dt / 10. Every
// statement carries the numbers it rests on; `brief` is the same in a few
// words (the figure's table).
struct Cause {
  std::string text, brief;
};
Cause cause(const Case& c, const Outcome& o, const Outcome& d1, const Outcome& d2, const Outcome& d3);

// The option beside a FAIL at the paper's settings, as its own row (the
// paper's method stays the row above it):
//  - a failure a smaller step removes (d1 or d3 clean): that step with every
//    guard on, beyond the paper's fixed dt;
//  - a 5.1 failure no step removes (the penalty of Eq. 12 at the paper's kn
//    cannot stop A within B's half thickness: the guard's message): the
//    stiff-contact option, beyond the paper's kn (diagnosis.cpp); a run too
//    long for this suite is costed, not run (a measurement row).
// None for the rest (a failure of neither kind has no option to show).
// `total` accumulates the simulated seconds.
std::optional<repro::Claim> option_row(const Case& c, const Outcome& d1, const Outcome& d3, double& total);

}  // namespace extreme
