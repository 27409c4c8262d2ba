// S3 penetration map (the suite's own study, not in the paper): where two
// blocks would pass through each other, the penetration guard stops the run.
//
// Two 1 m squares of Sect. 4.1's material (rho 2000 kg/m^3, E 1 GPa, nu 0.25,
// deformable, frictionless, no gravity, H unified = 1 m): A moves at speed v
// onto B at rest (B's face at x = 0, 0.2 m higher than A), head on (along x)
// or obliquely (30 deg off the face normal). Three maps:
//   head on, v against kn at the paper's dt (1e-4 s);
//   oblique, v against kn at dt = 1e-4 s;
//   head on, v against dt at a soft kn (1e5 Pa, where fast impacts pass
//   through without the guard).
// Every cell runs twice: guards on (the defaults) and with the penetration
// guard off (guards.max_penetration = max_approach_energy = 0). A cell is
//   bounced       the blocks separated, A still left of B;
//   guard stop    the penetration guard stopped the run;
//   other stop    another guard (step motion, energy growth or balance);
//   passed        the centroids' order along x swapped (blocks crossed);
//   stuck         still overlapping at the end of the run;
//   missed        never touched (a broken scene: must not occur).
// Expected: with the guard on no cell passes through or ends stuck; every
// cell that bounces with the guard on ends bit for bit as without it; the
// unguarded runs pass through where the approach energy exceeds what the
// pair can store (E_max ~ kn / 2 J/m for these squares): the map's own
// negative control, the same criterion applied to them must FAIL.
//
// Output: data/penetration_map/cells.csv, claims/S3_penetration_map.csv.
#include <cmath>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/S3_extreme_cases/penetration_cells.hpp"
#include "repro/common/common.hpp"
#include "repro/common/driver.hpp"
#include "repro/common/table.hpp"

namespace {
using repro::format_short;
using namespace s3map;

// One row of cells.csv: a cell run with the guards on and off.
struct Row {
  const Setup& c;
  const Result &on, &off;
  bool identical;
};
const std::vector<repro::Column<Row>> kColumns = {
    {"map", [](const Row& r) { return r.c.map; }},
    {"speed", [](const Row& r) { return r.c.speed; }},
    {"kn", [](const Row& r) { return r.c.kn; }},
    {"dt", [](const Row& r) { return r.c.dt; }},
    {"dt_over_crit", [](const Row& r) { return r.on.ratio; }},
    {"guarded", [](const Row& r) { return name(r.on.cls); }},
    {"unguarded", [](const Row& r) { return name(r.off.cls); }},
    {"identical", [](const Row& r) { return r.identical; }},
    {"message", [](const Row& r) { return r.on.message; }}};

// The three maps' cells.
std::vector<Setup> map_cells() {
  std::vector<Setup> cells;
  for (bool oblique : {false, true})
    for (double kn : kKns)
      for (double v : kSpeeds) cells.push_back({oblique ? "oblique, v-kn" : "head on, v-kn", oblique, v, kn, kPaperDt});
  for (double dt : kDts)
    for (double v : kSpeeds) cells.push_back({"head on, v-dt", false, v, kSoftKn, dt});
  return cells;
}

// What the rows count over the cells.
struct Tally {
  int cells = 0, through_on = 0, through_off = 0, stuck_on = 0, stops = 0, stops_actionable = 0, bounces = 0,
      bounces_identical = 0, false_stops = 0, other_stops = 0;
  std::string first_through, first_false;
};

// Every cell twice (guards on and off), a row of cells.csv each, counted.
Tally run_map(const std::vector<Setup>& cells, const std::string& path) {
  repro::TableWriter<Row> table(path, kColumns,
                                {"Two 1 m squares (Sect. 4.1 material), A at speed v onto B at rest, head on or 30 "
                                 "deg oblique; each cell with the guards on (guarded) and the penetration guard off "
                                 "(unguarded); identical: a guarded bounce ends bit for bit as the unguarded run"});
  Tally t;
  t.cells = static_cast<int>(cells.size());
  for (const Setup& c : cells) {
    const Result on = run(scene(c, true)), off = run(scene(c, false));
    const bool identical = on.cls == Cell::kBounced && off.cls == Cell::kBounced && on.final_state == off.final_state;
    const std::string where = c.map + " at v = " + format_short(c.speed) + " m/s, kn = " + format_short(c.kn) +
                              " Pa, dt = " + format_short(c.dt) + " s";
    t.through_on += on.cls == Cell::kPassed;
    t.stuck_on += on.cls == Cell::kStuck || on.cls == Cell::kMissed;
    t.through_off += off.cls == Cell::kPassed;
    if (on.cls == Cell::kPassed && t.first_through.empty()) t.first_through = where;
    if (on.cls == Cell::kGuardStop) {
      ++t.stops;
      t.stops_actionable += actionable(on.message);
      if (off.cls == Cell::kBounced) {
        ++t.false_stops;
        if (t.first_false.empty()) t.first_false = where;
      }
    }
    t.other_stops += on.cls == Cell::kOtherStop;
    if (on.cls == Cell::kBounced) {
      ++t.bounces;
      t.bounces_identical += identical;
    }
    table.row({c, on, off, identical});
  }
  table.commit();
  return t;
}

// The map's rows.
std::vector<repro::Claim> claim_rows(const Tally& t) {
  const std::string n = std::to_string(t.cells);
  const std::string sec = "S3 / penetration map";
  // The criterion of the first row applied to the unguarded runs is the
  // map's negative control: it must come out FAIL there.
  const bool pass_on = t.through_on == 0 && t.stuck_on == 0;
  const bool pass_off = t.through_off == 0;
  std::vector<repro::Claim> claims;
  claims.push_back({sec, "with the guards on (the default), no impact passes through or ends stuck overlapping",
                    "the suite: a run that leaves the method's domain stops, never a normal end",
                    std::to_string(t.through_on) + " of " + n + " cells passed through, " +
                        std::to_string(t.stuck_on) + " stuck or missed" +
                        (t.first_through.empty() ? "" : " (first: " + t.first_through + ")") +
                        "; negative control, the same criterion without the penetration guard: " +
                        std::to_string(t.through_off) + " cells passed through -> " + (pass_off ? "PASS" : "FAIL"),
                    "0 passed, 0 stuck; and FAIL on the unguarded runs", pass_on && !pass_off});
  claims.back().control = "in the same run: the criterion on the unguarded runs must FAIL (make verdicts)";
  claims.push_back({sec, "the guard does not touch a bounce: every guarded bounce ends bit for bit as without it",
                    "the suite: a guard observes, it does not change the trajectory",
                    std::to_string(t.bounces_identical) + " of " + std::to_string(t.bounces) + " bounces identical",
                    "all, and at least one bounce", bounces_untouched(t.bounces, t.bounces_identical)});
  claims.back().control = repro::control_test(kControlUntouched);
  claims.push_back({sec, "every penetration-guard stop names step, time, pair, the bound, dt/dt_crit and what to change",
                    "the suite: a message a user can act on",
                    std::to_string(t.stops_actionable) + " of " + std::to_string(t.stops) + " stop messages complete",
                    "all, and at least one stop", s3map::stops_actionable(t.stops, t.stops_actionable)});
  claims.back().control = repro::control_test(kControlActionable);
  claims.push_back({sec, "cells the guard stops although the unguarded run bounces (the guard's margin)",
                    "measurement: the guard stops at half the depth of no return",
                    std::to_string(t.false_stops) + " of " + std::to_string(t.stops) + " guard stops" +
                        (t.first_false.empty() ? "" : " (first: " + t.first_false + ")") + "; " +
                        std::to_string(t.other_stops) + " cells stopped by another guard",
                    "measurement, no verdict", false, repro::Kind::kMeasurement});
  repro::default_scope(claims, repro::Scope::kSuite);  // the suite's guards, every row
  return claims;
}

}  // namespace

int main(int argc, char** argv) {
  return repro::driver_main(
      argc, argv,
      {"penetration_map", "S3 penetration map", "Penetration map: impact speed against kn and dt, guard on and off."},
      {}, [](const repro::Driver& d) {
        const Tally t = run_map(map_cells(), d.out + "/data/penetration_map/cells.csv");
        d.progress(std::to_string(t.cells) + " cells done");
        repro::write_claims(repro::claims_path(d.out, "S3_penetration_map"), claim_rows(t));
        d.progress("done");
        return 0;
      });
}
