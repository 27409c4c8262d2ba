// Extreme cases: one report row each, run at the paper's dt (1e-4 s) and,
// where the solver stops there, again with dt = 0.5 x the predicted
// critical step (Scene::dt_fraction).
//
// Sect. 4.1's material and contact (rho 2000, E 1 GPa, nu 0.25, kn 10 MPa,
// H unified, frictionless, deformable, no gravity), collisions along x:
//   mass ratio 1e4: a 1 m square of density 2e7 at 1 m/s hits one of 2000
//     at rest, and the reverse. Expected (1D elastic collision of rigid
//     bodies): v_A' = (M - m)/(M + m) v, v_B' = 2 M/(M + m) v;
//   impact speed 1, 10, 100 m/s: the two squares of Sect. 4.1. Expected:
//     exchange at 1 and 10 m/s; at 100 m/s the overlap needed to stop the
//     blocks (kn L d^2 / H = m v^2 / 4 gives d = 0.71 m) exceeds half a
//     block: without the penetration guard they pass through each other;
//     with it (the default) the run stops at first contact;
//   size ratio 1000: a 0.01 m square at 1 m/s hits a free 10 m square.
//     Expected: it rebounds at ~1 m/s; its own strain modes give dt_crit
//     ~7e-6 s, so the paper's dt must be stopped by a guard;
//   sliver of aspect ratio 100 (1 m x 0.01 m): hit on its long side by a
//     1 m square at 1 m/s, and flying end-on (short edge first) into a 1 m
//     square at rest. Expected: dt_crit ~7e-6 s (its thin strain mode);
//   penetration deeper than half a block: the two squares at 1 m/s with a
//     soft kn = 1e3 Pa (d = 0.71 m). Detection (measurable, no solver
//     support needed): the intersection polygon contains the centroid of
//     either block; beyond it the shortest-exit potential of that block
//     points toward its far side over part of the overlap. Expected: the
//     penetration guard stops the run before the blocks cross. Also recorded:
//     the normal force on CP pointing toward TP's centroid (the net force
//     pulls instead of pushes), and softening: the overlap grows while
//     the normal force falls (negative contact stiffness).
// Each row: class (stable, energy growth > 1 %, flip-through, blow-up as in
// S2), dt/dt_crit at the start and its maximum, momentum and energy errors
// (relative; energy after the last contact), the velocities against the
// expected ones, the deepest overlap (thickness of the intersection polygon
// over the smaller block's inscribed diameter), the first time of deep
// penetration and of a wrong-way force, and the solver's message if it
// stopped.
// 5. Guards: a run at 1.5 x dt_crit must stop with a message naming the
// step, the time, the block, the pair, what was exceeded and dt/dt_crit;
// the rows written before the stop are committed and all finite (the
// guard_stop program does the same as a command and checks the exit status
// in ctest).
//
// Output: data/extreme_cases/table.csv, data/extreme_cases/guard_series.csv,
// claims/S3_extreme_cases.csv.
#include <string>
#include <vector>

#include "repro/S3_extreme_cases/extreme_cases.hpp"
#include "repro/common/common.hpp"
#include "repro/common/driver.hpp"
#include "repro/common/table.hpp"

using namespace s3;

namespace {

// One row of table.csv: a case run at one dt setting.
struct Row {
  const Extreme& e;
  std::string setting;
  const Outcome& o;
};
using Column = repro::Column<Row>;
Column outcome(const char* name, double Outcome::*field) {
  return {name, [field](const Row& r) { return r.o.*field; }};
}
// A value of a run that ended normally (empty after a guard stop).
Column finished(const char* name, double Outcome::*field) {
  return {name, [field](const Row& r) { return repro::cell_if(r.o.message.empty(), r.o.*field); }};
}
// A time, -1 if it never happened.
Column when(const char* name, double Outcome::*field) {
  return {name, [field](const Row& r) { return r.o.*field >= 0.0 ? r.o.*field : -1.0; }};
}
const std::vector<Column> kColumns = {
    {"case", [](const Row& r) { return r.e.name; }},
    {"parameter", [](const Row& r) { return r.e.parameter; }},
    {"dt_setting", [](const Row& r) { return r.setting; }},
    outcome("dt", &Outcome::dt),
    outcome("dt_over_crit_start", &Outcome::ratio0),
    outcome("dt_over_crit_max", &Outcome::ratio_max),
    {"class", [](const Row& r) { return r.o.class_name(); }},
    outcome("momentum_error", &Outcome::momentum_error),
    finished("energy_error", &Outcome::energy_error),
    finished("vx_A", &Outcome::va),
    finished("vx_B", &Outcome::vb),
    {"vx_A_expected", [](const Row& r) { return r.e.va_expected; }},
    {"vx_B_expected", [](const Row& r) { return r.e.vb_expected; }},
    finished("velocity_error", &Outcome::velocity_error),
    outcome("deepest_overlap", &Outcome::overlap),
    when("t_deep_penetration", &Outcome::t_deep),
    when("t_softening", &Outcome::t_soft),
    when("t_wrong_way_force", &Outcome::t_wrong),
    when("t_centroids_swapped", &Outcome::t_swap),
    {"message", [](const Row& r) { return r.o.message; }}};

// What a row's run measured, in words.
std::string measured(const Extreme& e, const Outcome& o) {
  std::string m = std::string(o.class_name()) + " at dt = " + format_short(o.dt, 3) + " s (dt/dt_crit " +
                  format_short(o.ratio0, 3) + " at start, max " + format_short(o.ratio_max, 3) + ")";
  if (o.message.empty())
    m += "; v_A = " + format_short(o.va, 5) + " (expected " + format_short(e.va_expected, 5) + "), v_B = " +
         format_short(o.vb, 5) + " (expected " + format_short(e.vb_expected, 5) + ") m/s; momentum error " +
         format_short(o.momentum_error, 3) + ", energy error " + format_short(o.energy_error, 3) +
         "; deepest overlap " + format_short(o.overlap, 3) + " of the smaller block";
  else
    m += "; stopped: " + o.message;
  if (o.t_deep >= 0.0) m += "; deep penetration detected at t = " + format_short(o.t_deep, 4) + " s";
  if (o.t_soft >= 0.0) m += "; force falls while the overlap grows from t = " + format_short(o.t_soft, 4) + " s";
  if (o.t_wrong >= 0.0) m += "; wrong-way force at t = " + format_short(o.t_wrong, 4) + " s";
  if (o.t_swap >= 0.0) m += "; centroids swapped at t = " + format_short(o.t_swap, 4) + " s";
  return m;
}

// 1-4. Every case at the paper's dt and, where the solver stops there or
// dt exceeds dt_crit, at 0.5 x the predicted dt_crit: table.csv, one row each.
void case_rows(const std::string& dir, const repro::Progress& progress, std::vector<repro::Claim>& claims) {
  repro::TableWriter<Row> table(
      dir + "/table.csv", kColumns,
      {"Extreme cases (Sect. 4.1 material, kn 10 MPa unless stated). Energy error after the run, relative to the "
       "initial kinetic energy; velocity error relative to the impact speed; deepest overlap = thickness of the "
       "intersection polygon / the smaller block's inscribed diameter; times -1: never; softening: the overlap "
       "grows while the normal force falls"});
  for (const Extreme& e : cases()) {
    std::vector<std::pair<std::string, Outcome>> runs{{"paper dt 1e-4 s", run(e, 0.0)}};
    if (runs.back().second.cls == RunClass::kBlowUp || runs.back().second.ratio0 > 1.0)
      runs.push_back({"0.5 x predicted dt_crit", run(e, 0.5)});
    for (const auto& [setting, o] : runs) {
      table.row({e, setting, o});
      // Expectation per case: s3::row_verdict.
      const auto [pass, tolerance] = row_verdict(e, o);
      claims.push_back({"S3 / " + e.name, e.parameter + " (" + setting + ")", "extreme case (not in the paper)",
                        measured(e, o), tolerance, pass});
      claims.back().control = kRowControl;
    }
    progress(e.name + ", " + e.parameter + ": done");
  }
  table.commit();
}

// 5. Guards: a too-large dt is stopped with a full message; the rows
// written before the stop stay valid (guard_series.csv).
repro::Claim guard_row(const std::string& dir) {
  const dda::Scene s = guard_scene(3.0);
  dda::Simulation sim(s);
  const Series series =
      guarded_series(sim, s.duration, dir + "/guard_series.csv",
                     "two squares, kn 1e10 Pa, dt = 3 x predicted dt_crit: the rows before the guard stop");
  repro::Claim row{"S3 / guards", "a run at 3 x dt_crit stops with a message naming step, time, block, pair, "
                                  "what was exceeded and dt/dt_crit; the rows written before it are kept",
                   "not in the papers: fail loudly, never write NaN results as data",
                   (series.message.empty() ? std::string("no stop") : "message: " + series.message) + "; " +
                       std::to_string(series.rows) + " finite rows kept",
                   "all six items in the message, >= 1 row kept",
                   guard_stop_complete(series.message, static_cast<long>(series.rows))};
  row.control = repro::control_test(kControlGuardStop);
  return row;
}

}  // namespace

int main(int argc, char** argv) {
  return repro::driver_main(
      argc, argv,
      {"extreme_cases", "S3 extreme cases", "Extreme cases at the paper's dt and at 0.5 x the predicted critical step."},
      {}, [](const repro::Driver& d) {
        const std::string dir = d.out + "/data/extreme_cases";
        std::vector<repro::Claim> claims;
        case_rows(dir, d.progress, claims);
        claims.push_back(guard_row(dir));
        repro::default_scope(claims, repro::Scope::kSuite);  // the suite's guards, every row
        repro::write_claims(repro::claims_path(d.out, "S3_extreme_cases"), claims);
        d.progress("done");
        return 0;
      });
}
