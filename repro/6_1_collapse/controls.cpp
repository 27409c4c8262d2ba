// Negative controls of the Sect. 6.1 collapse rows: each applies the
// driver's own criterion (collapse.hpp) to a deliberately wrong
// configuration the claim depends on and asserts FAIL.
//
// Cost: the full 7.5 s collapse takes minutes, so the runs here are short:
// both cases to kShort = 1.5 s (run once, shared by the tests), where case 1
// already leads by more than one joint spacing (front 30.0 vs 26.5 m, mean
// drop 4.9 vs 3.7 m, runout mass 19 vs 16 %), so the criteria do pass on the
// right configuration and the controls show they fail on the wrong one; and
// runs of a few hundred steps for the generator and the stability rows.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "repro/6_1_collapse/collapse.hpp"

namespace {
using namespace collapse61;

constexpr double kShort = 1.5;  // s

// The row's control (a constant of collapse.hpp, set by the driver) must be
// the running test case.
void names_this_test(const char* control_name) {
  CHECK(control(control_name) == "repro_controls: " + Catch::getResultCapture().getCurrentTestName());
}

// Both cases to kShort, with the paper's friction angles (run once).
const std::vector<CaseResult>& short_runs() {
  static const std::vector<CaseResult> runs = [] {
    std::vector<CaseResult> r;
    for (int k = 1; k <= 2; ++k)
      r.push_back(run_case(k, scene(kFrictions[k - 1], kShort, dda::RotationUpdate::kPaperLinear), 1, ""));
    return r;
  }();
  return runs;
}

// A few steps of the column `col` (no output): the generator row's measures.
CaseResult few_steps(const dda::paper::Collapse& col) { return run_case(1, col, 1, ""); }

}  // namespace

TEST_CASE("6.1 generator: FAIL without the sliver filter and with the joint spacings a third", "[controls][6.1]") {
  names_this_test(kControlGenerator);
  const double steps = 0.02;  // s: 200 steps, the start and the first live-contact samples
  // The driver's column passes (the check is not failing everything).
  CHECK(generator_ok(few_steps(scene(kFrictions[0], steps, dda::RotationUpdate::kPaperLinear))));
  const dda::paper::Collapse paper = scene(kFrictions[0], steps, dda::RotationUpdate::kPaperLinear);
  // No sliver filter (min_area 0): the slivers the joints cut at the
  // column's edges stay, and the smallest of them sets a critical step far
  // below the paper's dt 1e-4 s: the row's "below the stability limit"
  // must see it.
  const CaseResult all = few_steps(recut(paper, paper.joint_sets, 0.0));
  INFO("no sliver filter: " << all.blocks << " blocks, dt/dt_crit " << all.dt_ratio0 << " at start, at most "
                            << all.dt_ratio_max);
  CHECK_FALSE(generator_ok(all));
  // Spacings a third of the paper's (0.5 and 0.83 m): smaller blocks, a
  // shorter critical step, and the slivers dropped at 0.5 m^2 are a larger
  // share of the region.
  std::vector<dda::JointSet> dense = paper.joint_sets;
  for (dda::JointSet& s : dense) s.spacing /= 3.0;
  const CaseResult small = few_steps(recut(paper, dense, paper.min_area));
  INFO("spacings a third: " << small.blocks << " blocks, " << small.dropped_area << " m^2 dropped, dt/dt_crit "
                            << small.dt_ratio0 << " at start, at most " << small.dt_ratio_max);
  CHECK_FALSE(generator_ok(small));
}

TEST_CASE("6.1 stable run: FAIL with dt twice the critical step", "[controls][6.1]") {
  names_this_test(kControlStable);
  dda::paper::Collapse col = scene(kFrictions[0], 0.2, dda::RotationUpdate::kPaperLinear);
  // The paper's dt passes over the same 0.2 s (the check is not failing everything).
  CHECK(energy_budget(run_case(1, col, 1, "")).pass);
  // dt from 0.55 to 2 times the a-priori critical step: velocity Verlet is
  // unstable above the critical step, the contact springs' energy grows by
  // a factor each step, and the row ("without a stability guard tripping;
  // energy only dissipates") must fail: here by the step-motion guard's stop
  // (measured: after 23 steps) ...
  col.scene.dt = 2.0 * dda::Simulation(col.scene).predicted_critical_step();
  const CaseResult guarded = run_case(1, col, 1, "");
  INFO("guards on: stopped '" << guarded.stopped << "' after " << guarded.steps << " steps");
  CHECK_FALSE(guarded.stopped.empty());
  CHECK_FALSE(energy_budget(guarded).pass);
  // ... and with every guard a scene can switch off switched off: a block
  // turns inside out (the solver's area check, which cannot be switched
  // off, stops the run after 27 steps); the run does not reach its end.
  col.scene.guards.max_step_motion = 1e9;
  col.scene.guards.max_balance_error = 0.0;
  col.scene.guards.energy_check_every = 0;
  col.scene.guards.max_penetration = 0.0;
  col.scene.guards.max_approach_energy = 0.0;
  const CaseResult unguarded = run_case(1, col, 1, "");
  INFO("guards off: stopped '" << unguarded.stopped << "' after " << unguarded.steps << " steps");
  CHECK_FALSE(unguarded.stopped.empty());
  CHECK_FALSE(energy_budget(unguarded).pass);
  // The energy branch of the criterion: both unstable runs stop within a
  // few steps, before the first sample (every 0.05 s), so they never reach
  // it, and neither does any dt (the instability is sharp: dt 1.35 x the
  // predicted step runs 0.2 s cleanly, 1.4 x stops after about 110 steps,
  // both with the switchable guards off). So, synthetic: the
  // 1.5 s run of case 1 with energy gained between two samples, 2 % of the
  // potential energy it releases (what an unstable contact pumping energy
  // into the rock would show), must fail too.
  CaseResult pumped = short_runs()[0];
  const EnergyBudget clean = energy_budget(pumped);
  CHECK(clean.pass);
  for (std::size_t i = pumped.series.size() / 2; i < pumped.series.size(); ++i)
    pumped.series[i].total = pumped.series.front().total + 0.02 * clean.released;
  CHECK_FALSE(energy_budget(pumped).pass);
}

TEST_CASE("6.1 faster collapse: FAIL with the friction swapped between the cases", "[controls][6.1]") {
  names_this_test(kControlFaster);
  const std::vector<CaseResult>& runs = short_runs();
  const Sample& p15 = runs[0].at(faster_time(kShort));
  const Sample& p30 = runs[1].at(faster_time(kShort));
  INFO("at " << p15.t << " s: mean drop " << p15.mean_drop << " vs " << p30.mean_drop << " m, front " << p15.front_x
             << " vs " << p30.front_x << " m");
  // The paper's assignment (case 1 at 15 deg) passes at 1.5 s already ...
  CHECK(collapses_faster(p15, p30));
  // ... and with the friction angles swapped between the cases (case 1 at
  // 30 deg, case 2 at 15 deg) the claimed faster case is the slower one: the
  // criterion must fail.
  CHECK_FALSE(collapses_faster(p30, p15));
  // Equal friction (both cases the 15 deg run): no lead at all, must fail.
  CHECK_FALSE(collapses_faster(p15, p15));
}

TEST_CASE("6.1 runout: FAIL with the friction swapped between the cases", "[controls][6.1]") {
  names_this_test(kControlRunout);
  const std::vector<CaseResult>& runs = short_runs();
  const Sample& e15 = runs[0].at(kShort);
  const Sample& e30 = runs[1].at(kShort);
  INFO("at " << e15.t << " s: front " << e15.front_x << " vs " << e30.front_x << " m, runout mass "
             << e15.runout_mass << " vs " << e30.runout_mass);
  CHECK(runs_out_further(e15, e30));
  // Case 1 at 30 deg, case 2 at 15 deg: case 1 runs out less far, with less mass.
  CHECK_FALSE(runs_out_further(e30, e15));
  // The same front but no more runout mass: a lead of the front alone (one
  // block ahead) is not a larger runout mass.
  Sample ahead_only = e30;
  ahead_only.front_x = e15.front_x + 10.0;
  CHECK_FALSE(runs_out_further(ahead_only, e30));
}

TEST_CASE("6.1 renumbering: FAIL when the cases' order flips in one numbering", "[controls][6.1]") {
  names_this_test(kControlRenumbered);
  const std::vector<CaseResult>& runs = short_runs();
  const Sample& e15 = runs[0].series.back();
  const Sample& e30 = runs[1].series.back();
  // All three numberings with the paper's assignment: holds at 1.5 s.
  const Ends same = {{{e15, e30}, {e15, e30}, {e15, e30}}};
  CHECK(ordering_survives(same));
  // The y numbering's end states swapped between the cases: the ordering
  // flips under a renumbering (what a chaotic run can do), and the row must
  // fail even though the generator numbering still holds.
  const Ends flipped = {{{e15, e30}, {e15, e30}, {e30, e15}}};
  CHECK(runs_out_further(flipped[0][0], flipped[0][1]));
  CHECK_FALSE(ordering_survives(flipped));
  // A real renumbered rerun (blocks by centroid x) with the friction swapped.
  const Sample x30 = rerun_renumbered(1, scene(kFrictions[1], kShort, dda::RotationUpdate::kPaperLinear), 1, 0);
  const Ends rerun = {{{e15, e30}, {x30, e30}, {e15, e30}}};
  INFO("x-numbered rerun of case 1 at 30 deg: front " << x30.front_x << " m, runout mass " << x30.runout_mass);
  CHECK_FALSE(ordering_survives(rerun));
}
