// Negative controls of B-8, two elastic bars against 1D wave theory: each
// test applies the driver's own criterion (from bar_waves.hpp) to the
// driver's configuration, where it must PASS, and to a deliberately wrong
// one, where it must FAIL; the driver's rows name these tests through the
// shared test-name constants.
#include <catch2/catch.hpp>

#include "repro/B_8_bar_waves/bar_waves.hpp"

namespace {
constexpr int kFinestNy = 16;  // the driver's finest mesh, where its CDEM rows are judged
// The driver's finest B0 run (clone node, no subdivision), computed once (2 s).
const bars::Run& finest_b0() {
  static const bars::Run r = bars::run_cdem(bars::Setup{}, kFinestNy, 0.0, false);
  return r;
}
}  // namespace

TEST_CASE(bars::kTestDuration, "[controls][B-8]") {
  const bars::Setup paper;
  REQUIRE(finest_b0().ok());
  CHECK(bars::duration_ok(finest_b0(), paper));  // +1.1 % of 2 L / c
  // Bars half as long: the wave returns after L / c, half the reference.
  bars::Setup half = paper;
  half.length *= 0.5;
  const bars::Run r = bars::run_cdem(half, kFinestNy, 0.0, false);
  REQUIRE(r.ok());
  CHECK_FALSE(bars::duration_ok(r, paper));
  CHECK(bars::duration_ok(r, half));  // and it passes against its own 2 L / c
}

TEST_CASE(bars::kTestStress, "[controls][B-8]") {
  const bars::Setup paper;
  CHECK(bars::stress_ok(finest_b0(), paper));  // -1.9 %
  // Both bars four times as stiff: rho c doubles, so does the stress.
  bars::Setup stiff = paper;
  stiff.material.young *= 4.0;
  const bars::Run r = bars::run_cdem(stiff, kFinestNy, 0.0, false);
  REQUIRE(r.ok());
  CHECK_FALSE(bars::stress_ok(r, paper));
}

TEST_CASE(bars::kTestPlateau, "[controls][B-8]") {
  const bars::Setup paper;
  CHECK(bars::plateau_ok(finest_b0(), paper));
  // The plateau is right on a coarse mesh too (ny 4): the stiff bars' plateau
  // is twice the paper material's.
  CHECK(bars::plateau_ok(bars::run_cdem(paper, 4, 0.0, false), paper));
  bars::Setup stiff = paper;
  stiff.material.young *= 4.0;
  const bars::Run r = bars::run_cdem(stiff, 4, 0.0, false);
  REQUIRE(r.ok());
  CHECK_FALSE(bars::plateau_ok(r, paper));
}

TEST_CASE(bars::kTestExchange, "[controls][B-8]") {
  const bars::Setup paper;
  CHECK(bars::exchange_ok(finest_b0(), paper));  // 0.8 %
  // The target twice as dense (the striker unchanged): unequal bars do not
  // exchange their velocities (rigid: target 2 m / (m + 2 m) v = 0.67 v).
  bars::Setup dense = paper;
  dense.target_density_factor = 2.0;
  const bars::Run r = bars::run_cdem(dense, kFinestNy, 0.0, false);
  REQUIRE(r.ok());
  CHECK_FALSE(bars::exchange_ok(r, paper));
  // Paper A's rigid-like exchange fails the same way.
  CHECK(bars::exchange_ok(bars::run_dda(paper, 1e-4, 0.01 * paper.material.young), paper));
  CHECK_FALSE(bars::exchange_ok(bars::run_dda(dense, 1e-4, 0.01 * paper.material.young), paper));
}

TEST_CASE(bars::kTestEnergy, "[controls][B-8]") {
  const bars::Setup paper;
  const bars::Run ok = bars::run_cdem(paper, 2, 0.0, false);
  CHECK(bars::energy_never_grows({ok}));
  // dt 5 % above the coarse mesh's critical step (the scene check switched
  // off): the explicit integration is unstable and the energy grows from
  // round-off until an element inverts.
  const double crit = dda::cdem::Model(bars::cdem_scene(paper, 2, 1e-6, false)).critical_dt();
  const bars::Run bad = bars::run_cdem(paper, 2, 1.05 * crit, false, nullptr, false);
  INFO("growth " << bad.energy_growth << ", stopped: " << bad.stopped);
  CHECK(bad.energy_growth > 1e-3);
  CHECK_FALSE(bars::energy_never_grows({ok, bad}));
}
