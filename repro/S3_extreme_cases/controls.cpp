// Negative controls of the S3 extreme-case rows: the row criterion with the
// penetration guard off and against the wrong expected velocities, the
// guard stop below the critical step and on a bare message, and the
// penetration map's bounce and message rows.
#include <catch2/catch.hpp>

#include <string>
#include <utility>

#include "dda/simulation.hpp"
#include "repro/S3_extreme_cases/extreme_cases.hpp"
#include "repro/S3_extreme_cases/penetration_cells.hpp"
#include "repro/common/controls.hpp"

TEST_CASE("S3 rows: FAIL with the penetration guard off and with the wrong expected velocities", "[controls][S3]") {
  auto find = [](const std::string& name, const std::string& parameter) {
    return controls::find(
        s3::cases(), [&](const s3::Extreme& e) { return e.name == name && e.parameter == parameter; },
        "S3 case " + name + " / " + parameter);
  };
  // 100 m/s: with the guards the run stops before the blocks cross (PASS);
  // without the penetration and approach-energy checks they pass through.
  s3::Extreme fast = find("impact speed", "100 m/s");
  CHECK(s3::row_verdict(fast, s3::run(fast, 0.0)).first);
  fast.scene.guards.max_penetration = 0.0;
  fast.scene.guards.max_approach_energy = 0.0;
  const s3::Outcome through = s3::run(fast, 0.0);
  INFO("guard off: " << through.class_name() << ", centroids swapped at " << through.t_swap << " s");
  CHECK_FALSE(s3::row_verdict(fast, through).first);
  // 1 m/s: the velocities are exchanged (PASS); against the answer of a
  // perfectly inelastic collision (both at v / 2) the same run must FAIL.
  s3::Extreme slow = find("impact speed", "1 m/s");
  CHECK(s3::row_verdict(slow, s3::run(slow, 0.0)).first);
  slow.va_expected = slow.vb_expected = 0.5 * slow.v0;
  CHECK_FALSE(s3::row_verdict(slow, s3::run(slow, 0.0)).first);
}

TEST_CASE("S3 guard stop: FAIL below the critical step and on a bare message", "[controls][S3]") {
  // The row's run at 3 x dt_crit passes; at half the critical step nothing
  // stops the run (no message), and a message without the step, block and
  // pair (a bare exception text) does not name what a user needs.
  auto run = [](double fraction) {
    dda::Simulation sim(s3::guard_scene(fraction));
    long rows = 0;
    try {
      while (sim.time() < sim.scene().duration) {
        sim.step();
        ++rows;
      }
    } catch (const dda::SimulationError& e) {
      return std::make_pair(std::string(e.what()), rows);
    }
    return std::make_pair(std::string(), rows);
  };
  const auto over = run(3.0);
  INFO(over.first);
  CHECK(s3::guard_stop_complete(over.first, over.second));
  const auto under = run(0.5);
  CHECK(under.first.empty());
  CHECK_FALSE(s3::guard_stop_complete(under.first, under.second));
  CHECK_FALSE(s3::guard_stop_complete("energy budget off by 0.5, more than guards.max_balance_error", over.second));
}

TEST_CASE("S3 map bounces: FAIL against a run with kn changed by 1e-9", "[controls][S3]") {
  // A guard that touched the trajectory at all, here as a contact stiffness
  // off by one part in 1e9, must show in the bit-for-bit comparison: the
  // bounce counts as changed and the row FAILs. The guard itself passes.
  const s3map::Setup c{"head on, v-kn", false, 1.0, 1e7, s3map::kPaperDt};
  const s3map::Result on = s3map::run(s3map::scene(c, true)), off = s3map::run(s3map::scene(c, false));
  REQUIRE(on.cls == s3map::Cell::kBounced);
  REQUIRE(off.cls == s3map::Cell::kBounced);
  CHECK(s3map::bounces_untouched(1, on.final_state == off.final_state ? 1 : 0));
  dda::Scene touched = s3map::scene(c, true);
  touched.contact.kn *= 1.0 + 1e-9;
  const s3map::Result changed = s3map::run(touched);
  REQUIRE(changed.cls == s3map::Cell::kBounced);
  CHECK_FALSE(s3map::bounces_untouched(1, changed.final_state == off.final_state ? 1 : 0));
}

TEST_CASE("S3 map messages: FAIL on a map without stops and on another guard's message", "[controls][S3]") {
  // A map where the guard never stops a run shows nothing; the message of a
  // different guard (the energy budget of the S3 guard row's run at 3 x
  // dt_crit) does not give the penetration bound and what to change.
  const s3map::Setup fast{"head on, v-dt", false, 64.0, s3map::kSoftKn, s3map::kPaperDt};
  const s3map::Result stop = s3map::run(s3map::scene(fast, true));
  REQUIRE(stop.cls == s3map::Cell::kGuardStop);
  INFO(stop.message);
  CHECK(s3map::stops_actionable(1, s3map::actionable(stop.message) ? 1 : 0));
  CHECK_FALSE(s3map::stops_actionable(0, 0));
  std::string other;
  try {
    dda::Simulation sim(s3::guard_scene(3.0));
    while (sim.time() < sim.scene().duration) sim.step();
  } catch (const dda::SimulationError& e) {
    other = e.what();
  }
  INFO(other);
  REQUIRE_FALSE(other.empty());
  CHECK_FALSE(s3map::stops_actionable(1, s3map::actionable(other) ? 1 : 0));
}
