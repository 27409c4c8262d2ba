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

namespace {
using repro::format_short;
using namespace s3map;
}  // namespace

int main(int argc, char** argv) {
  repro::check_command_line(argc, argv, "Penetration map: impact speed against kn and dt, guard on and off.");
  const std::string out = repro::out_dir(argc, argv);
  const repro::Progress progress("S3 penetration map");
  std::vector<Setup> cells;
  for (bool oblique : {false, true})
    for (double kn : kKns)
      for (double v : kSpeeds) cells.push_back({oblique ? "oblique, v-kn" : "head on, v-kn", oblique, v, kn, kPaperDt});
  for (double dt : kDts)
    for (double v : kSpeeds) cells.push_back({"head on, v-dt", false, v, kSoftKn, dt});

  repro::CsvWriter table(out + "/data/penetration_map/cells.csv",
                         {"map", "speed", "kn", "dt", "dt_over_crit", "guarded", "unguarded", "identical", "message"},
                         {"Two 1 m squares (Sect. 4.1 material), A at speed v onto B at rest, head on or 30 deg "
                          "oblique; each cell with the guards on (guarded) and the penetration guard off "
                          "(unguarded); identical: a guarded bounce ends bit for bit as the unguarded run"});
  int through_on = 0, through_off = 0, stuck_on = 0, stops = 0, stops_actionable = 0, bounces = 0,
      bounces_identical = 0, false_stops = 0, other_stops = 0;
  std::string first_through, first_false;
  for (const Setup& c : cells) {
    const Result on = run(scene(c, true)), off = run(scene(c, false));
    const bool identical = on.cls == Cell::kBounced && off.cls == Cell::kBounced && on.final_state == off.final_state;
    const std::string where = c.map + " at v = " + format_short(c.speed) + " m/s, kn = " + format_short(c.kn) +
                              " Pa, dt = " + format_short(c.dt) + " s";
    through_on += on.cls == Cell::kPassed;
    stuck_on += on.cls == Cell::kStuck || on.cls == Cell::kMissed;
    through_off += off.cls == Cell::kPassed;
    if (on.cls == Cell::kPassed && first_through.empty()) first_through = where;
    if (on.cls == Cell::kGuardStop) {
      ++stops;
      stops_actionable += actionable(on.message);
      if (off.cls == Cell::kBounced) {
        ++false_stops;
        if (first_false.empty()) first_false = where;
      }
    }
    other_stops += on.cls == Cell::kOtherStop;
    if (on.cls == Cell::kBounced) {
      ++bounces;
      bounces_identical += identical;
    }
    table.row(std::vector<std::string>{c.map, repro::format_full(c.speed), repro::format_full(c.kn),
                                       repro::format_full(c.dt), repro::format_full(on.ratio), name(on.cls),
                                       name(off.cls), identical ? "1" : "0", on.message});
  }
  table.commit();
  progress(std::to_string(cells.size()) + " cells done");

  const std::string n = std::to_string(cells.size());
  const std::string sec = "S3 / penetration map";
  // The criterion of the first row applied to the unguarded runs is the
  // map's negative control: it must come out FAIL there.
  const bool pass_on = through_on == 0 && stuck_on == 0;
  const bool pass_off = through_off == 0;
  std::vector<repro::Claim> claims;
  claims.push_back({sec, "with the guards on (the default), no impact passes through or ends stuck overlapping",
                    "the suite: a run that leaves the method's domain stops, never a normal end",
                    std::to_string(through_on) + " of " + n + " cells passed through, " + std::to_string(stuck_on) +
                        " stuck or missed" + (first_through.empty() ? "" : " (first: " + first_through + ")") +
                        "; negative control, the same criterion without the penetration guard: " +
                        std::to_string(through_off) + " cells passed through -> " + (pass_off ? "PASS" : "FAIL"),
                    "0 passed, 0 stuck; and FAIL on the unguarded runs", pass_on && !pass_off});
  claims.back().control = "in the same run: the criterion on the unguarded runs must FAIL (make verdicts)";
  claims.push_back({sec, "the guard does not touch a bounce: every guarded bounce ends bit for bit as without it",
                    "the suite: a guard observes, it does not change the trajectory",
                    std::to_string(bounces_identical) + " of " + std::to_string(bounces) + " bounces identical",
                    "all, and at least one bounce", bounces_untouched(bounces, bounces_identical)});
  claims.back().control = repro::control_test(kControlUntouched);
  claims.push_back({sec, "every penetration-guard stop names step, time, pair, the bound, dt/dt_crit and what to change",
                    "the suite: a message a user can act on",
                    std::to_string(stops_actionable) + " of " + std::to_string(stops) + " stop messages complete",
                    "all, and at least one stop", s3map::stops_actionable(stops, stops_actionable)});
  claims.back().control = repro::control_test(kControlActionable);
  claims.push_back({sec, "cells the guard stops although the unguarded run bounces (the guard's margin)",
                    "measurement: the guard stops at half the depth of no return",
                    std::to_string(false_stops) + " of " + std::to_string(stops) + " guard stops" +
                        (first_false.empty() ? "" : " (first: " + first_false + ")") + "; " +
                        std::to_string(other_stops) + " cells stopped by another guard",
                    "measurement, no verdict", false, repro::Kind::kMeasurement});
  repro::default_scope(claims, repro::Scope::kSuite);  // the suite's guards, every row
  repro::write_claims(repro::claims_path(out, "S3_penetration_map"), claims);
  progress("done");
  return 0;
}
