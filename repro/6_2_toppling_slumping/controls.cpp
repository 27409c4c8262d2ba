// Negative controls of the Sect. 6.2 toppling and slumping rows: the
// mechanism criteria on configurations that remove what they look for
// (locked joints, a rough base, a gentle friction), the stability criterion
// at twice the critical step, and the ratchet diagnosis with the paper's
// update on both sides.
#include <catch2/catch.hpp>

#include <string>

#include "dda/paper_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/6_2_toppling_slumping/toppling_slumping.hpp"

TEST_CASE("6.2 toppling, slumping, premise: FAIL with locked joints, a rough base and a gentle friction",
          "[controls][6.2]") {
  // Each criterion of the 6.2 rows on a configuration that removes what it
  // looks for (3.5 s, the paper's duration; about 5 s of runs).
  const dda::paper::TopplingSlumping ts = dda::paper::toppling_slumping();
  // Joints locked (80 deg): nothing topples, and the joints carry no slip
  // beyond what the same locked model does.
  dda::Scene locked = ts.scene;
  locked.contact.friction_deg = 80.0;
  const topple::Control l = topple::run_control(ts, locked, ts.side, 1, "control: joints locked");
  CHECK_FALSE(topple::topples(l.right, l.right));
  CHECK_FALSE(topple::joints_carry_slip(l.left, l.left));
  // A rough base (80 deg on the sliding base): the left slope cannot slide
  // down it, so it does not slump.
  dda::Scene rough = ts.scene;
  rough.contact.friction_rules = {{dda::paper::kRockGroup, dda::paper::kBoundaryGroup, 80.0}};
  const topple::Control r = topple::run_control(ts, rough, ts.side, 1, "control: rough base");
  INFO("left base slip on a rough base " << r.left.base_slip << " m");
  CHECK_FALSE(topple::slumps(r.left, r.right));
  // Each slope as one block on a base with 20 deg friction (< the 30 deg
  // slope): it slides, and the premise row must see it.
  dda::Scene gentle = topple::one_block_per_slope(ts);
  gentle.contact.friction_rules = {{dda::paper::kRockGroup, dda::paper::kBoundaryGroup, 20.0}};
  const topple::Control g = topple::run_control(ts, gentle, {-1, +1}, 1, "control: base friction 20 deg");
  INFO("one block per slope, base friction 20 deg: left slip " << g.left.base_slip << " m");
  CHECK_FALSE(topple::stays(g));
}

TEST_CASE("6.2 stable run: FAIL at twice the critical step", "[controls][6.2]") {
  // The valley model at dt = 2 x the predicted critical step for 200 steps
  // (or until a guard stops it): the stability row must see it.
  const dda::paper::TopplingSlumping ts = dda::paper::toppling_slumping();
  dda::Scene over = ts.scene;
  over.dt_fraction = 2.0;
  topple::Health h;
  try {
    dda::Simulation sim(over);
    h.sample(sim);
    for (int k = 0; k < 200; ++k) {
      sim.step();
      h.sample(sim);
    }
  } catch (const dda::SimulationError& e) {
    INFO("stopped: " << e.what());
  }
  INFO("dt/dt_crit at most " << h.ratio_max << ", energy rise " << h.rise << " J/m of " << h.e0);
  CHECK_FALSE(topple::runs_stably(h));
}

TEST_CASE("6.2 ratchet diagnosis: FAIL when both runs use the paper's update", "[controls][6.2]") {
  // The diagnosis compares the late slip of the elastic-plastic update with
  // the paper's rule; with the paper's rule on both sides (each slope as one
  // block, 3.5 s) the two are the same and the row must FAIL.
  const dda::paper::TopplingSlumping ts = dda::paper::toppling_slumping();
  const topple::Control c = topple::run_control(ts, topple::one_block_per_slope(ts), {-1, +1}, 1, "control: ratchet");
  const double late = c.left.base_slip - c.left_half.base_slip;
  INFO("late slip, paper rule " << late << " m");
  CHECK_FALSE(topple::ratchet_explains(late, late));
}
