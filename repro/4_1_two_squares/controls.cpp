// Negative controls of the Sect. 4.1 two-squares rows: velocity exchange,
// momentum and energy, each judged by the driver's own rows on a scene
// changed so that the property fails (unequal masses, B fixed, mass damping).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "repro/4_1_two_squares/two_squares.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/controls.hpp"

using controls::names_control;
using controls::row;

TEST_CASE("4.1 velocity exchange: FAIL when B is twice as heavy", "[controls][4.1]") {
  dda::Scene s = dda::paper::two_squares();
  controls::make_j_denser(s, 2.0);  // unequal masses: velocities are not exchanged
  const auto rows = two_squares::claims(two_squares::run(s, nullptr));
  CHECK_FALSE(row(rows, two_squares::kKeyAStops).pass);
  names_control(row(rows, two_squares::kKeyAStops), "4.1 velocity exchange: FAIL when B is twice as heavy");
  CHECK_FALSE(row(rows, two_squares::kKeyBLeaves).pass);
  names_control(row(rows, two_squares::kKeyBLeaves), "4.1 velocity exchange: FAIL when B is twice as heavy");
}

TEST_CASE("4.1 momentum: FAIL when B is fixed", "[controls][4.1]") {
  dda::Scene s = dda::paper::two_squares();
  s.blocks[1].fixed = true;  // a wall: A bounces back, momentum is not conserved
  const auto rows = two_squares::claims(two_squares::run(s, nullptr));
  CHECK_FALSE(row(rows, two_squares::kKeyMomentum).pass);
  names_control(row(rows, two_squares::kKeyMomentum), "4.1 momentum: FAIL when B is fixed");
}

TEST_CASE("4.1 energy: FAIL with mass damping", "[controls][4.1]") {
  dda::Scene s = dda::paper::two_squares();
  s.damping.mass = 1.0;  // 1/s: A loses most of its kinetic energy within the 1 s run
  const auto rows = two_squares::claims(two_squares::run(s, nullptr));
  CHECK_FALSE(row(rows, two_squares::kKeyEnergy).pass);
  names_control(row(rows, two_squares::kKeyEnergy), "4.1 energy: FAIL with mass damping");
}
