// Stability maps and a check of the critical time step.
//
// 1. dt_crit check. The solver's critical_time_step() (current contacts)
//    and predicted_critical_step() (a priori) are compared with an
//    independent value: 2 / omega_max of the linearised system (stiffness by
//    central differences of the library's contact force, DDA mass matrices;
//    repro/S_common), and with the empirical limit found by bisection on dt
//    for a block resting at its static penetration, nudged by 1e-9 m/s and
//    1e-9 rad/s so that every mode is excited (unstable: the
//    mechanical energy grows 10-fold over 20000 steps, a resting contact
//    opens, or a guard stops the run). Expected: empirical = linearised;
//    the solver's values at or below it (a bound). The "old" column is a simpler per-block estimate
//    (kn L 2 / H_i on k/m + k r^2/I, max with the strain modes).
// 2. Stability maps: kn 1e6 .. 1e12 Pa (half decades) x dt 1e-6 .. 1e-2 s
//    (quarter decades), Table 4/5 material (rho 2000, E 1 GPa, nu 0.25),
//    deformable blocks, frictionless. Shortened runs, the collision window
//    only: (a) Sect. 4.1's two squares, A at 1 m/s, starting 1 mm apart;
//    (b) Sect. 5.1's bouncing block, case 1 (B 0.1 m high), A starting 1 mm
//    above B at the 3.13 m/s it reaches after its 0.5 m fall, gravity on,
//    with the unified H and with the inscribed-radius H. Run length: 2 ms +
//    4 contact half-periods pi/omega (omega from the flat contact on the
//    relative mass), at most 0.4 s (written per run). Each run is
//    classified (s2::map_run, maps.hpp): blow-up (the state diverges: a
//    non-finite state, an area collapse, or the step-motion guard after the
//    energy grew; a stop by the energy-budget guard alone is an accuracy
//    stop, so the cell is rerun with that guard off and classified by that
//    run), flip-through (the penetration guard, the step-motion guard before
//    the energy grew, or the centroids ending in the wrong order), energy
//    growth > 1 % of the impact energy at the end, else stable. Expected:
//    stable below min(contact limit ~ kn^-1/2, strain limit 7e-4 s); the
//    solver's prediction at or below the empirical boundary; above it,
//    short contacts (a few steps) can end in growth without blowing up.
//
// Output: data/stability_maps/dt_crit_check.csv, map_<name>.csv,
// boundary_<name>.csv; claims/S2_stability_maps.csv.
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/S2_stability_maps/maps.hpp"
#include "repro/S2_stability_maps/resting.hpp"
#include "repro/S_common/stability.hpp"
#include "repro/common/common.hpp"

namespace {
using dda::Vec2;
using repro::format_short;
using repro::stab::RunClass;
using namespace s2;

std::string num(double x) { return repro::format_full(x); }

// dt_crit lines for one kn: the solver's prediction, the old estimate, and
// the linearised system at the peak contact force of a resolved run.
struct Lines {
  double predicted = 0.0, old = 0.0, linearized = 0.0, current_min = 0.0;
};

Lines lines_for(const MapScene& m, double kn) {
  Lines l;
  dda::Scene s = m.scene;
  s.contact.kn = kn;
  dda::Simulation probe(s);
  l.predicted = probe.predicted_critical_step();
  l.old = old_prior(probe);
  s.dt = 0.05 * l.predicted;
  s.duration = window(m, kn, s.dt);
  dda::Simulation sim(s);
  double fmax = 0.0;
  long peak = -1;
  l.current_min = std::numeric_limits<double>::infinity();
  try {
    while (sim.time() < s.duration - 0.5 * s.dt) {
      sim.step();
      double f = 0.0;
      for (const dda::ContactInfo& c : sim.contacts()) f += dda::length(c.normal_force);
      if (f > fmax) {
        fmax = f;
        peak = sim.step_count();
      }
      if (!sim.contacts().empty()) l.current_min = std::min(l.current_min, sim.critical_time_step());
    }
  } catch (const dda::SimulationError&) {
    // A soft kn lets the blocks pass through each other even at 0.05 of the
    // predicted step (the penetration guard stops the run): the lines use the
    // largest force reached before the stop.
  }
  dda::Simulation at(s);
  while (at.step_count() < peak) at.step();
  l.linearized = repro::stab::linearized_critical_step(at).dt_crit;
  return l;
}

}  // namespace

int main(int argc, char** argv) {
  repro::check_command_line(argc, argv, "Stability maps and a check of the critical time step.");
  const std::string out = repro::out_dir(argc, argv);
  const repro::Progress progress("S2 stability maps");
  const std::string dir = out + "/data/stability_maps";
  std::vector<repro::Claim> claims;

  // ---- 1. dt_crit check ------------------------------------------------------
  {
    repro::CsvWriter csv(dir + "/dt_crit_check.csv",
                         {"case", "kn", "linearized", "empirical", "solver_current", "solver_predicted",
                          "old_estimate", "empirical_over_linearized", "current_over_linearized",
                          "predicted_over_linearized", "old_over_linearized"},
                         {"dt_crit (s) of a resting contact: linearised 2/omega_max (independent), empirical "
                          "(bisection, 14 halvings of the log interval, 20000 steps), solver's current and "
                          "a-priori estimates, and the per-block estimate 2 kn L_max / H"});
    std::vector<RestCase> cases;
    for (double kn : {1e6, 1e7, 1e8, 1e9}) cases.push_back(resting(kn, false, false, false));
    for (double kn : {1e6, 1e7, 1e8, 1e9}) cases.push_back(resting(kn, true, false, false));
    for (double kn : {1e8, 1e9}) cases.push_back(resting(kn, false, false, true));
    for (double kn : {1e7, 1e8, 1e9}) cases.push_back(resting(kn, false, true, false));
    for (double kn : {1e7, 1e8}) cases.push_back(resting(kn, true, true, false));
    double worst_emp = 0.0, worst_cur = 0.0, worst_pred = 0.0, worst_old = 0.0, best_cur = 1e300;
    for (const RestCase& rc : cases) {
      dda::Simulation sim(rc.scene);
      const double lin = repro::stab::linearized_critical_step(sim).dt_crit;
      const double emp = empirical_limit(rc.scene, lin);
      const double cur = sim.critical_time_step(), pred = sim.predicted_critical_step(), old = old_prior(sim);
      csv.row(std::vector<std::string>{rc.name, num(rc.scene.contact.kn), num(lin), num(emp), num(cur), num(pred),
                                       num(old), num(emp / lin), num(cur / lin), num(pred / lin), num(old / lin)});
      worst_emp = std::max(worst_emp, std::fabs(emp / lin - 1.0));
      worst_cur = std::max(worst_cur, cur / lin);
      best_cur = std::min(best_cur, cur / lin);
      worst_pred = std::max(worst_pred, pred / lin);
      worst_old = std::max(worst_old, old / lin);
    }
    csv.commit();
    claims.push_back({"S2 / dt_crit", "the linearised dt_crit (independent check) is the empirical stability limit "
                                      "of a resting contact",
                      "velocity Verlet: stable iff dt < 2 / omega_max",
                      "largest |empirical / linearised - 1| over " + std::to_string(cases.size()) +
                          " cases (kn 1e6..1e9, rigid and deformable, unified and inscribed H, one and two free "
                          "blocks) = " + format_short(worst_emp, 3),
                      "< " + format_short(kEmpiricalTolerance), linearised_is_empirical(worst_emp)});
    claims.back().control = repro::control_test(kControlEmpirical);
    claims.push_back({"S2 / dt_crit", "the solver's critical time step never exceeds the linearised limit",
                      "a critical step must be safe",
                      "current / linearised in [" + format_short(best_cur, 3) + ", " + format_short(worst_cur, 3) +
                          "]; predicted / linearised <= " + format_short(worst_pred, 3) +
                          "; the per-block estimate 2 kn L_max / H reached " + format_short(worst_old, 3),
                      "current and predicted <= 1.0", solver_steps_are_safe(worst_cur, worst_pred)});
    claims.back().control = repro::control_test(kControlSafe);
    progress("dt_crit check done");
  }

  // ---- 2. maps ----------------------------------------------------------------
  std::vector<double> kns, dts;
  for (int i = 0; i <= 12; ++i) kns.push_back(std::pow(10.0, 6.0 + 0.5 * i));
  for (int i = 0; i <= 16; ++i) dts.push_back(std::pow(10.0, -6.0 + 0.25 * i));
  for (const MapScene& m : {two_squares_map(), bouncing_map(dda::HRule::kMinMaxEdge),
                            bouncing_map(dda::HRule::kInscribedRadius)}) {
    repro::CsvWriter map(dir + "/map_" + m.name + ".csv",
                         {"kn", "dt", "class", "window_s", "dt_over_predicted", "max_dt_over_current",
                          "energy_change", "max_energy_growth", "message"},
                         {m.title + ": one run per (kn, dt); energy relative to the impact energy"});
    repro::CsvWriter bnd(dir + "/boundary_" + m.name + ".csv",
                         {"kn", "predicted", "old_estimate", "linearized_at_peak", "current_min",
                          "largest_stable_below_first_failure", "smallest_not_stable", "smallest_blowup"},
                         {m.title + ": dt_crit lines (s) and the empirical boundary per kn"});
    // Per class, below (dt <= predicted) and above the prediction.
    int below[4] = {0, 0, 0, 0}, above[4] = {0, 0, 0, 0}, old_blowups_below = 0, failures_below = 0;
    // The largest kn at which every cell with dt <= predicted passes
    // through (0: none): where the scene's own kn sits against it.
    double all_through_kn = 0.0;
    double min_blowup_ratio = 1e300, max_blowup_ratio = 0.0;  // first blow-up dt / predicted, over kn
    double growth_ratio = 1e300;  // smallest dt/predicted of an 'energy growth' run
    std::vector<double> flip_below;  // kn with a flip-through at dt <= predicted
    for (double kn : kns) {
      const Lines l = lines_for(m, kn);
      int cells_below = 0, through_below = 0;
      double first_bad = std::numeric_limits<double>::infinity(), first_blowup = first_bad, last_good = 0.0;
      for (double dt : dts) {
        const MapRun r = map_run(m, kn, dt);
        map.row(std::vector<std::string>{num(kn), num(dt), repro::stab::class_name(r.cls), num(r.window),
                                         num(r.ratio0), num(r.ratio_max), num(r.energy_change), num(r.max_growth),
                                         r.message});
        const int c = static_cast<int>(r.cls);
        ++(dt <= l.predicted ? below : above)[c];
        if (fails_at_or_below(r, dt, l.predicted)) ++failures_below;
        if (dt <= l.predicted) {
          ++cells_below;
          through_below += r.cls == RunClass::kFlipThrough;
        }
        if (r.cls == RunClass::kBlowUp) {
          first_blowup = std::min(first_blowup, dt);
          if (dt <= l.old) ++old_blowups_below;
        }
        if (r.cls == RunClass::kEnergyGrowth) growth_ratio = std::min(growth_ratio, dt / l.predicted);
        if (r.cls == RunClass::kFlipThrough && dt <= l.predicted && (flip_below.empty() || flip_below.back() != kn))
          flip_below.push_back(kn);
        if (r.cls != RunClass::kStable) first_bad = std::min(first_bad, dt);
      }
      if (cells_below > 0 && through_below == cells_below) all_through_kn = std::max(all_through_kn, kn);
      for (double dt : dts)
        if (dt < first_bad) last_good = dt;
      bnd.row({kn, l.predicted, l.old, l.linearized, l.current_min, last_good,
               std::isfinite(first_bad) ? first_bad : 0.0, std::isfinite(first_blowup) ? first_blowup : 0.0});
      if (std::isfinite(first_blowup)) {
        min_blowup_ratio = std::min(min_blowup_ratio, first_blowup / l.predicted);
        max_blowup_ratio = std::max(max_blowup_ratio, first_blowup / l.predicted);
      }
    }
    map.commit();
    bnd.commit();
    auto counts = [](const int* n) {
      return std::to_string(n[0]) + " stable, " + std::to_string(n[1]) + " energy growth, " + std::to_string(n[2]) +
             " flip-through, " + std::to_string(n[3]) + " blow-up";
    };
    std::string flip_note;
    for (double kn : flip_below) flip_note += (flip_note.empty() ? "" : ", ") + format_short(kn);
    const std::string summary = "at dt <= predicted: " + counts(below) + "; above: " + counts(above);
    const double paper_kn = m.scene.contact.kn;
    const std::string threshold =
        all_through_kn > 0.0
            ? "every dt <= predicted passes through at kn <= " + format_short(all_through_kn, 4) +
                  " Pa: the paper's kn " + format_short(paper_kn, 3) + " Pa is " +
                  format_short(paper_kn / all_through_kn, 3) + " times that"
            : "no kn of the map passes through at every dt (the paper's kn " + format_short(paper_kn, 3) + " Pa)";
    claims.push_back({"S2 / map", m.title + ": no blow-up and no pass-through at dt <= the predicted dt_crit",
                      "not in the papers: stability of stiff cases against the predicted critical step",
                      threshold + "; " + summary + "; first blow-up at " + format_short(min_blowup_ratio, 3) + " to " +
                          format_short(max_blowup_ratio, 3) + " x predicted over kn; per-block estimate 2 kn L_max / H: " +
                          std::to_string(old_blowups_below) + " blow-ups at or below it",
                      "0 blow-ups and 0 flip-throughs at dt <= predicted", failures_below == 0});
    claims.back().key = "map-" + m.name + "-no-failure-below-predicted";
    claims.back().control = repro::control_test(kControlFailBelow);
    repro::explain_fail(claims.back(),
                        below[static_cast<int>(RunClass::kBlowUp)] > 0 ? repro::Root::kUnexplained
                                                                        : repro::Root::kThinBlock,
                        below[static_cast<int>(RunClass::kBlowUp)] > 0
                            ? "the solver's a-priori critical step is not a bound for this scene: a run blows up "
                              "below it; not explained"
                            : std::to_string(below[static_cast<int>(RunClass::kFlipThrough)]) +
                                  " cells at dt <= predicted pass through: below some kn the penalty cannot stop the "
                                  "block within the thin block's half thickness at any dt; " + threshold);
    claims.push_back({"S2 / map", m.title + ": energy created by under-resolved impacts below the prediction",
                      "not discussed in the paper",
                      "smallest dt / predicted of an 'energy growth > 1 %' run: " + format_short(growth_ratio, 3) +
                          (flip_note.empty() ? std::string("")
                                             : "; flip-through at dt <= predicted (penetration deeper than half "
                                               "the thin block, not a time-step effect) for kn = " + flip_note + " Pa"),
                      "information: an accuracy limit (few steps per contact), not a stability limit", false, repro::Kind::kMeasurement});
    progress(m.title + ": " + summary);
  }
  repro::default_scope(claims, repro::Scope::kSuite);  // the suite's own stability study, every row
  repro::write_claims(repro::claims_path(out, "S2_stability_maps"), claims);
  progress("done");
  return 0;
}
