// The rows of B-7's baseline P (node-to-edge penalty on the CST blocks, see
// penalty_baseline.hpp): touch time and momentum (checks, with negative
// controls in controls.cpp beside this file), the predicted
// critical step against the measured stability limit (a check), energy and
// cost (measurements).
#include "repro/B_7_contact_comparison/penalty_baseline.hpp"

#include <algorithm>

namespace compare {

std::vector<repro::Claim> penalty_rows(const SceneDef& def, const std::vector<Result>& p,
                                       const std::vector<Result>& a, const std::vector<Result>& b,
                                       const std::vector<Result>& b0, const std::vector<StabilityProbe>& probes) {
  std::vector<repro::Claim> rows;
  const std::string sec = "B-7 " + def.name;
  const Result &p0 = p.front(), &a0 = a.front(), &bb = b.front(), &bc = b0.front();
  std::string touch;
  for (const Result& r : p)
    touch += (touch.empty() ? "" : ", ") + format_short(r.touch_err, 3) + " s at dt " + format_short(r.dt);
  rows.push_back({sec, "touch time: P (node-to-edge penalty) is late by up to one step, like A",
                  "reference gap / speed = " + format_short(def.t_touch_exact, 8) + " s",
                  "P: first step end with a node behind an edge; error " + touch +
                      ". B, B0 exact (the row above); A late by up to one step. B BETTER than P",
                  "0 <= t_P - t_exact <= dt at every dt", penalty_touch_ok(p, def.t_touch_exact)});
  rows.back().control = repro::control_test(kTestPenaltyTouch);
  rows.push_back({sec, "momentum: P's equal and opposite node-edge forces conserve it", "conservation law",
                  "max |p - p0| / p0 over the dt sweep: P " + format_short(worst_of(p, &Result::mom_err), 3) +
                      " (A " + format_short(worst_of(a, &Result::mom_err), 3) + ", B " +
                      format_short(worst_of(b, &Result::mom_err), 3) + "). TIE",
                  "< 1e-12 for every P run", penalty_momentum_ok(p)});
  rows.back().control = repro::control_test(kTestPenaltyMomentum);
  std::string energy;
  for (const Result& r : p)
    energy += (energy.empty() ? "" : ", ") + format_short(r.energy_err_end, 3) + " (max " +
              format_short(r.energy_err_max, 3) + ") at dt " + format_short(r.dt);
  rows.push_back(repro::measurement(
      sec, "energy of P (elastic penalty springs, undamped) over the dt sweep", "an elastic collision keeps the energy",
      "E_end / E0 - 1 (max |E / E0 - 1| during the run, springs' energy included): P " + energy +
          "; at the base dt A " + format_short(a0.energy_err_end, 3) + ", B " + format_short(bb.energy_err_end, 3) +
          ", B0 " + format_short(bc.energy_err_end, 3) + ". P's post-impact v_j " + format_short(p0.v_j, 6) +
          " m/s (v0 " + format_short(def.v0) + "), contact " + format_short(p0.contact_end - p0.contact_start, 4) +
          " s (A " + format_short(a0.contact_end - a0.contact_start, 4) + " s, B " +
          format_short(bb.contact_end - bb.contact_start, 4) + " s)",
      "no verdict: P's energy error is the explicit step's (falls with dt); B's loss is the method's (clone impact)"));
  for (const StabilityProbe& s : probes) {
    const bool base = s.kn_factor == 1.0;
    repro::Claim c{sec,
                   std::string("stable dt of P: the mesh's critical step with the penalty spring predicts it") +
                       (base ? " (kn = E/100)" : " (stiff kn)"),
                   "explicit step: dt < 2 / omega_max; up to 3 springs per node add 6 kn max(1/m) to omega^2 (our bound)",
                   "kn " + format_short(s.kn, 3) + " Pa: predicted " + format_short(s.dt_pred, 4) +
                       " s (mesh alone " + format_short(s.dt_mesh, 4) + " s); measured (ladder of dt / dt_pred, run "
                       "to the touch + 0.1 s): stable up to " + format_short(s.dt_stable, 4) + " s, unstable at " +
                       format_short(s.dt_unstable, 4) + " s (" + s.failure.substr(0, 120) + "). The base dt " +
                       format_short(def.dts.front()) + " s is " + format_short(def.dts.front() / s.dt_pred, 3) +
                       " x the predicted step. B, B0 need dt below the mesh's step only",
                   "stable at dt_pred; unstable at or below " + format_short(kStabilityMargin) + " x dt_pred",
                   stability_prediction_ok(s, s.dt_pred)};
    c.key = base ? "p-stable-dt" : "p-stable-dt-stiff-kn";
    c.control = repro::control_test(kTestPenaltyStability);
    rows.push_back(c);
  }
  std::string cost;
  for (const Result& r : p)
    cost += (cost.empty() ? "" : ", ") + format_short(r.wall / def.duration, 3) + " at dt " + format_short(r.dt);
  rows.push_back(repro::measurement(
      sec, "cost of P: wall time per simulated second over the dt sweep", "work-precision",
      "P " + cost + " s/s; at the base dt A " + format_short(a0.wall / def.duration, 3) + ", B " +
          format_short(bb.wall / def.duration, 3) + ", B0 " + format_short(bc.wall / def.duration, 3) +
          " s/s (mean of repeated runs; this machine, shared)",
      "no verdict: run times depend on the machine and its load"));
  rows.back().key = "p-cost";
  return rows;
}

PenaltyRuns run_penalty_baseline(const std::vector<SceneDef>& scenes, std::vector<Result>& results,
                                 std::map<std::string, History>& histories, const repro::Progress& progress) {
  PenaltyRuns runs;
  for (const SceneDef& def : scenes) {
    const std::vector<Result> sweep = penalty_sweep(def, &histories[def.name + "/P"]);
    for (const Result& r : sweep)
      progress(def.name + " P dt " + format_short(r.dt) + ": " + format_short(r.wall, 3) + " s, v_j " +
               format_short(r.v_j, 6) + ", dE " + format_short(r.energy_err_end, 3));
    results.insert(results.end(), sweep.begin(), sweep.end());
    for (double factor : {1.0, kStiffKnFactor}) {
      const StabilityProbe s = probe_stability(def, factor, 0.1);
      progress(def.name + " P stability, kn x " + format_short(factor) + ": predicted " + format_short(s.dt_pred, 4) +
               " s, stable " + format_short(s.dt_stable, 4) + " s, unstable " + format_short(s.dt_unstable, 4) +
               " s (" + format_short(s.wall, 3) + " s)");
      runs.probes[def.name].push_back(s);
    }
  }
  return runs;
}

void add_penalty_rows(const std::vector<SceneDef>& scenes, const std::vector<Result>& results, const PenaltyRuns& runs,
                      std::vector<repro::Claim>& claims) {
  for (const SceneDef& def : scenes) {
    auto pick = [&](const std::string& model) {
      std::vector<Result> v;
      for (const Result& r : results)
        if (r.scene == def.name && r.model == model) v.push_back(r);
      return v;
    };
    const std::vector<repro::Claim> rows =
        penalty_rows(def, pick("P"), pick("A"), pick("B"), pick("B0"), runs.probes.at(def.name));
    claims.insert(claims.end(), rows.begin(), rows.end());
  }
}

}  // namespace compare
