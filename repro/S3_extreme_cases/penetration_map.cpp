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
#include "repro/S_common/stability.hpp"
#include "repro/common/common.hpp"

namespace {
using dda::Vec2;
using repro::format_short;

constexpr double kGap = 0.02;                      // A's face to B's at t = 0, m
constexpr double kOffset = 0.2;                    // B's centre above A's, m: not a symmetric hit
constexpr double kOblique = 0.5235987755982988;    // 30 deg off the face normal, rad
constexpr double kPaperDt = 1e-4;                  // Sect. 4.1's time step, s
constexpr double kSoftKn = 1e5;                    // Pa: the v-dt map's penalty, 1 % of Sect. 4.1's
const std::vector<double> kSpeeds{0.5, 1, 2, 4, 8, 16, 32, 64};  // m/s
const std::vector<double> kKns{1e4, 1e5, 1e6, 1e7, 1e8};         // Pa
const std::vector<double> kDts{1e-5, 3e-5, 1e-4, 3e-4, 1e-3};    // s

enum class Cell { kBounced, kGuardStop, kOtherStop, kPassed, kStuck, kMissed };
const char* name(Cell c) {
  switch (c) {
    case Cell::kBounced: return "bounced";
    case Cell::kGuardStop: return "guard stop";
    case Cell::kOtherStop: return "other stop";
    case Cell::kPassed: return "passed";
    case Cell::kStuck: return "stuck";
    case Cell::kMissed: return "missed";
  }
  return "?";
}

struct Setup {
  std::string map;
  bool oblique = false;
  double speed = 0.0, kn = 0.0, dt = 0.0;
};

std::vector<Vec2> square(Vec2 c) {
  return {c + Vec2{-0.5, -0.5}, c + Vec2{0.5, -0.5}, c + Vec2{0.5, 0.5}, c + Vec2{-0.5, 0.5}};
}

dda::Scene scene(const Setup& c, bool guarded) {
  dda::Scene s = dda::paper::two_squares();
  s.contact.kn = c.kn;
  s.dt = c.dt;
  s.blocks[0].vertices = square({-0.5 - kGap, 0.0});
  s.blocks[1].vertices = square({0.5, kOffset});
  s.blocks[0].velocity = c.oblique ? c.speed * Vec2{std::cos(kOblique), std::sin(kOblique)} : Vec2{c.speed, 0.0};
  if (!guarded) s.guards.max_penetration = s.guards.max_approach_energy = 0.0;
  // Long enough to cross the gap and both blocks (2 m) or to finish a
  // bounce: 4 x the half period pi sqrt(m_eff / k) of the pair's spring
  // k = 2 kn (face contact, H = 1 m), m_eff = 1000 kg/m.
  s.duration = (kGap + 2.5) / c.speed + 4.0 * 3.14159 * std::sqrt(1000.0 / (2.0 * c.kn));
  return s;
}

struct Result {
  Cell cls = Cell::kBounced;
  double ratio = 0.0;  // dt / predicted dt_crit at the start
  std::string message;
  std::vector<double> final_state;  // vertex coordinates at the end (bounces only)
};

Result run(const Setup& c, bool guarded) {
  Result r;
  dda::Simulation sim(scene(c, guarded));
  r.ratio = sim.dt() / sim.predicted_critical_step();
  const auto steps = static_cast<long>(std::ceil(sim.scene().duration / sim.dt()));
  bool touched = false;
  try {
    for (long k = 0; k < steps; ++k) {
      sim.step();
      if (!sim.contacts().empty()) touched = true;
      else if (touched) break;  // the contact is over: bounced or through
    }
  } catch (const dda::SimulationError& e) {
    r.message = e.what();
    const bool penetration = r.message.find("max_penetration") != std::string::npos ||
                             r.message.find("max_approach_energy") != std::string::npos;
    r.cls = penetration ? Cell::kGuardStop : Cell::kOtherStop;
  }
  const bool crossed = sim.centroid(0).x > sim.centroid(1).x;
  if (r.message.empty())
    r.cls = crossed ? Cell::kPassed : !touched ? Cell::kMissed : !sim.contacts().empty() ? Cell::kStuck : Cell::kBounced;
  else if (crossed) r.cls = Cell::kPassed;  // a stop after the blocks crossed is too late
  if (r.cls == Cell::kBounced) r.final_state = repro::stab::vertex_state(sim);
  return r;
}

bool has(const std::string& text, const char* part) { return text.find(part) != std::string::npos; }

// The guard's message names what a user needs to act on: where (step,
// time, pair), the bound (a depth bound, or the energy the pair can store),
// dt/dt_crit and what to change (kn).
bool actionable(const std::string& m) {
  for (const char* part : {"step ", "(t = ", "pair (", "dt/dt_crit", "contact.kn"})
    if (!has(m, part)) return false;
  return has(m, "(bound ") || has(m, "the pair can store");
}

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
    const Result on = run(c, true), off = run(c, false);
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
                    "all, and at least one bounce", bounces > 0 && bounces_identical == bounces});
  claims.push_back({sec, "every penetration-guard stop names step, time, pair, the bound, dt/dt_crit and what to change",
                    "the suite: a message a user can act on",
                    std::to_string(stops_actionable) + " of " + std::to_string(stops) + " stop messages complete",
                    "all, and at least one stop", stops > 0 && stops_actionable == stops});
  claims.push_back({sec, "cells the guard stops although the unguarded run bounces (the guard's margin)",
                    "measurement: the guard stops at half the depth of no return",
                    std::to_string(false_stops) + " of " + std::to_string(stops) + " guard stops" +
                        (first_false.empty() ? "" : " (first: " + first_false + ")") + "; " +
                        std::to_string(other_stops) + " cells stopped by another guard",
                    "measurement, no verdict", false, repro::Kind::kMeasurement});
  repro::write_claims(repro::claims_path(out, "S3_penetration_map"), claims);
  progress("done");
  return 0;
}
