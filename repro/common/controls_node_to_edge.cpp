// Negative controls of B-7's node-to-edge penalty baseline P
// (repro/B_7_contact_comparison/penalty_baseline.hpp):
// each test applies the row's own criterion to the paper's configuration
// (PASS) and to a deliberately wrong one (FAIL). On the prisms (P runs there
// take milliseconds). Part of repro_controls_tests (main in test_controls.cpp).
#include <catch2/catch.hpp>

#include <string>

#include "repro/B_7_contact_comparison/penalty_baseline.hpp"

namespace {
compare::SceneDef prisms_def() {
  for (const compare::SceneDef& d : compare::scene_defs())
    if (d.name == "prisms") return d;
  FAIL("no B-7 prisms scene");
  return {};
}
}  // namespace

TEST_CASE(compare::kTestPenaltyTouch, "[controls][B-7][P]") {
  compare::SceneDef d = prisms_def();
  CHECK(compare::penalty_touch_ok(compare::penalty_sweep(d, nullptr, true), d.t_touch_exact));
  // The reference of a 0.9 m gap (0.3 s), the scene's is 1 m: P is 33 ms
  // (67 steps) late against it.
  d.t_touch_exact = 0.9 / d.v0;
  CHECK_FALSE(compare::penalty_touch_ok(compare::penalty_sweep(d, nullptr, true), d.t_touch_exact));
  // The reference of a 1.1 m gap: P would touch before it.
  d.t_touch_exact = 1.1 / d.v0;
  CHECK_FALSE(compare::penalty_touch_ok(compare::penalty_sweep(d, nullptr, true), d.t_touch_exact));
}

TEST_CASE(compare::kTestPenaltyMomentum, "[controls][B-7][P]") {
  compare::SceneDef d = prisms_def();
  CHECK(compare::penalty_momentum_ok(compare::penalty_sweep(d, nullptr, true)));
  const auto make = d.cdem_scene;
  d.cdem_scene = [make](bool sub) {
    dda::cdem::CdemScene s = make(sub);
    s.blocks[1].fixed = true;  // the wall takes the momentum: block i bounces back
    return s;
  };
  CHECK_FALSE(compare::penalty_momentum_ok(compare::penalty_sweep(d, nullptr, true)));
}

TEST_CASE(compare::kTestPenaltyStability, "[controls][B-7][P]") {
  const compare::SceneDef d = prisms_def();
  const compare::StabilityProbe p = compare::probe_stability(d, compare::kStiffKnFactor, 0.1);
  CAPTURE(p.dt_pred, p.dt_mesh, p.dt_stable, p.dt_unstable, p.failure);
  CHECK(compare::stability_prediction_ok(p, p.dt_pred));
  // The mesh's critical step alone (7.4e-4 s) ignores the spring of kn =
  // 100 E: the prisms blow up at 6e-5 s, far below it.
  CHECK_FALSE(compare::stability_prediction_ok(p, p.dt_mesh));
}
