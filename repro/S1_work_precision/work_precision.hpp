// S1 work precision (see work_precision.cpp for what it measures): the
// scenes with a reference (cases.cpp: the paper's, cases_ours.cpp: ours; their
// parts in case_kit.hpp), the dt sweep (sweep.cpp) and the
// claim rows with their criteria (claims.cpp). The criteria are functions
// here so that the negative controls (controls.cpp beside it) apply
// the same ones to a deliberately wrong configuration.
#pragma once
#include <algorithm>
#include <cmath>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "dda/scene.hpp"
#include "dda/simulation.hpp"
#include "repro/S_common/stability.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/common.hpp"
#include "repro/common/table.hpp"

namespace s1 {

// ---- one scene, one option ----------------------------------------------

// Observes a monitored run: begin() after construction, step() after every
// step, end() returns the errors of the analytic measures (in the order of
// Case::measures).
struct Observer {
  std::function<void(const dda::Simulation&)> begin = [](const dda::Simulation&) {};
  std::function<void(const dda::Simulation&)> step = [](const dda::Simulation&) {};
  std::function<std::vector<double>(const dda::Simulation&)> end;
};

struct Measure {
  std::string name;       // e.g. "energy"
  std::string reference;  // e.g. "exact conservation"
  double floor = 1e-13;   // round-off level: errors below it are not fitted
};

struct Case {
  std::string scene, option;  // "4.1 two squares", "paper, H unified"
  dda::Scene sc;
  double paper_dt = 0.0;
  std::vector<double> dts;  // ascending
  double sample_every = 0.0;  // s, a multiple of every dt
  std::vector<Measure> measures;
  std::function<Observer()> observer;
  // Trajectory measures against a run at dts[0] / 16: one per window end
  // (s); empty: none. Names "trajectory" / "trajectory to t = ..".
  std::vector<double> trajectory_windows;
  std::vector<std::string> trajectory_names;
};

struct RunOut {
  bool ok = true;
  std::string message;
  double ratio0 = 0.0, ratio_max = 0.0;
  std::vector<double> errors;                // analytic measures
  std::vector<std::vector<double>> samples;  // vertex states at sample times
  std::vector<double> sample_times;
};

// One monitored run at dt (observe = false: the reference run, trajectory
// samples only); a SimulationError ends it with ok = false.
RunOut monitored_run(const Case& c, double dt, bool observe = true);
// Median wall and CPU time of unmonitored runs of the scene at dt: one run
// to size the median, then 3 of them (5 or 9 for runs shorter than 0.2 or
// 0.05 s), at most max_repeats.
repro::stab::Timing timed_run(const dda::Scene& sc, double dt, int max_repeats = 9);

// ---- scenes (cases.cpp, cases_ours.cpp) -------------------------------------
std::vector<Case> all_cases();
std::vector<Case> free_rotation_cases();  // [0] the paper's rotation, [1] exact (not the paper's)

// The resting block (our scene): rigid A (1 m square) on a fixed 4 m x 1 m
// block B, A released `sunk` deep; its static and deepest penetrations.
struct Resting {
  dda::Scene sc;
  double h_a = 0.0, h_b = 0.0, weight = 0.0, length = 1.0;
  double static_pen() const {  // f(delta) = W
    const double s = 1.0 / h_a + 1.0 / h_b, kn = sc.contact.kn;
    return 0.5 * h_a * (length * s - std::sqrt(length * length * s * s - 4.0 * weight / (kn * h_a)));
  }
  double max_pen() const {  // int_0^delta f = W delta
    const double s = 1.0 / h_a + 1.0 / h_b, kn = sc.contact.kn;
    return 1.5 * h_a * (0.5 * length * s - std::sqrt(0.25 * length * length * s * s - 4.0 * weight / (3.0 * kn * h_a)));
  }
};

Resting resting_block(dda::HRule h, double sunk);
// A's depth below B's top (y = 0), m.
double penetration(const dda::Simulation& sim);

// ---- sweep (sweep.cpp) -----------------------------------------------------

struct CurveSummary {
  std::string scene, option, measure, reference;
  repro::stab::Order order;      // over the 4 smallest dt above round-off
  repro::stab::Order order_all;  // over every dt that ran (robust to one lucky cancellation)
  double error_at_paper = -1.0, wall_at_paper = -1.0, cpu_at_paper = -1.0, ratio_at_paper = 0.0;
  double largest_stable_ratio = 0.0;  // dt/dt_crit (predicted) of the largest dt that ran through
  double max_error = 0.0;             // over every dt that ran through
  std::string first_failure;          // message of the smallest dt that stopped
};

// The data files' columns (tables.cpp): runs.csv, one row per measure of a
// case at one dt; orders.csv, one row per curve.
struct RunRow {
  const Case& c;
  const std::string& measure;
  double dt;
  const RunOut& r;
  const repro::stab::Timing& t;
  double error, local;  // local: the order from the previous dt (NaN: none)
};
extern const std::vector<repro::Column<RunRow>> kRunColumns;
extern const std::vector<repro::Column<CurveSummary>> kOrderColumns;

// Converged trajectories by "scene | option" (reference-run samples).
using References = std::vector<std::pair<std::string, std::vector<std::vector<double>>>>;

// How the sweep spends its time. The errors and every claim row depend on
// neither: only the wall_s/cpu_s columns (and the times quoted in rows' text).
struct SweepOptions {
  int max_repeats = 9;  // timed runs per dt at most (timed_run)
  // Cases run at once, each on its own thread (results kept in case order).
  // With more than one, the timed runs share the machine's cores.
  int jobs = 1;
};

// Runs every case at every dt, writes dir/runs.csv and dir/orders.csv, and
// returns one summary per (case, measure); fills `references`.
std::vector<CurveSummary> sweep(const std::vector<Case>& cases, const std::string& dir, References& references,
                                const repro::Progress& progress, const SweepOptions& options = {});

// ---- criteria and claims (claims.cpp) --------------------------------------

// An observed order within tol of the expected one.
bool order_met(const repro::stab::Order& order, double expected, double tol);
// Every error over the sweep below the round-off level.
bool roundoff_met(double max_error, double level);
// The fitted errors within a factor 1.5 (a model error dt does not reduce).
bool plateau_met(const repro::stab::Order& order);
// phi = 20 deg: the Eq. 30 error (relative, at the paper's dt) is the
// model's, not dt's: as a distance (x kInclineDistance) it is more than
// 100 x the trajectory error at the same dt.
inline constexpr double kInclineDistance = 0.9;  // m, about the slide at t = 1 s
inline bool model_error_dominates(double eq30_rel_error, double trajectory_error) {
  return eq30_rel_error * kInclineDistance > 100.0 * trajectory_error;
}
// Within 1 % of Eq. 30 at every dt that ran.
inline bool within_eq30(double max_rel_error) { return max_rel_error < 0.01; }
// The resting block placed at `sunk` (the static penetration of the rows)
// stays there: the largest |delta - sunk| over the run, m.
double resting_deviation(dda::HRule h, double sunk);
inline bool stays_at(double deviation, double static_pen) { return deviation < 1e-6 * static_pen; }

// The energy budget (Energy::balance_error) of a run with friction: the
// largest |kinetic + gravity + strain + contact + friction springs +
// dissipated - initial| over the run, relative to the largest energy turned
// over (kinetic + strain + contact + friction springs + dissipated).
// count_dissipated false leaves the dissipated work out (a control).
struct Budget {
  bool count_dissipated = true;
  double worst = 0.0, turned_over = 0.0;
  void step(const dda::Simulation& sim) {
    const dda::Energy e = sim.energy();
    const double off = e.balance_error() - (count_dissipated ? 0.0 : e.dissipated);
    worst = std::max(worst, std::fabs(off));
    turned_over = std::max(turned_over, e.kinetic + e.strain + e.contact + e.friction_spring + e.dissipated);
  }
  double error() const { return turned_over > 0.0 ? worst / turned_over : 0.0; }
};
// The budget rows: below 1e-3 of the energy turned over at every dt that ran.
inline bool budget_closes(double max_error) { return max_error < 1e-3; }

// The negative controls (controls.cpp) named by the rows.
inline const char* const kControlOrder2 = "repro_controls: S1 order 2: FAIL on a first-order configuration";
inline const char* const kControlOrder1 = "repro_controls: S1 order 1: FAIL on a second-order configuration";
inline const char* const kControlRoundoff = "repro_controls: S1 round-off: FAIL on a first-order configuration";
inline const char* const kControlPlateau = "repro_controls: S1 plateau: FAIL on a converging curve";
inline const char* const kControlModelError = "S1 model error: FAIL with the friction start-up option";
inline const char* const kControlEq30 = "S1 Eq. 30 at every dt: FAIL with the paper's start";
inline const char* const kControlStatic = "S1 static penetration: FAIL at the other H rule's penetration";
inline const char* const kControlBudget = "S1 energy budget: FAIL without the dissipated sliding work";

std::vector<repro::Claim> claim_rows(const std::vector<CurveSummary>& curves, const References& references);

}  // namespace s1
