// Negative controls of the claim rows (issue 21, item 2): every check that
// names a control here ("repro_controls: <test name>") is run with the
// driver's own criterion on a deliberately wrong configuration that the claim
// depends on, and must come out FAIL. A criterion that passes anyway checks
// nothing, and this test fails.
#define CATCH_CONFIG_MAIN
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "repro/4_1_two_squares/two_squares.hpp"
#include "repro/4_2_symmetric_stack/symmetric_stack.hpp"
#include "repro/4_3_incline/incline.hpp"
#include "repro/5_1_bouncing_block/bouncing_block.hpp"
#include "repro/common/claims.hpp"

namespace {

// The row with key `key`; fails the test if there is none or it is not a check.
const repro::Claim& row(const std::vector<repro::Claim>& rows, const std::string& key) {
  for (const repro::Claim& c : rows)
    if (c.key == key) {
      REQUIRE(c.kind == repro::Kind::kCheck);
      return c;
    }
  FAIL("no row with key " << key);
  return rows.front();
}

// The control named in the row must be this test case (so that the report's
// count of controlled checks names real tests).
void names_control(const repro::Claim& c, const std::string& test) {
  CHECK(c.control == "repro_controls: " + test);
}

}  // namespace

// --- Sect. 4.1, two squares --------------------------------------------------
TEST_CASE("4.1 velocity exchange: FAIL when B is twice as heavy", "[controls][4.1]") {
  dda::Scene s = dda::paper::two_squares();
  s.materials.push_back(s.materials[0]);
  s.materials[1].density *= 2.0;  // unequal masses: velocities are not exchanged
  s.blocks[1].material = 1;
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

// --- Sect. 4.2, symmetric stack --------------------------------------------------
TEST_CASE("4.2 symmetry: FAIL when the impactor drifts sideways", "[controls][4.2]") {
  dda::paper::SymmetricStack st = dda::paper::symmetric_stack();
  // Symmetric at t = 0, but the impactor drifts sideways at 2.5 % of its
  // 2 m/s fall: the asymmetry must come from the motion, not the start.
  constexpr double kSideSpeed = 0.05;  // m/s
  st.scene.blocks.back().velocity.x = kSideSpeed;
  const repro::Claim c = symmetric_stack::row(symmetric_stack::run(st, nullptr, nullptr));
  CHECK_FALSE(c.pass);
  CHECK(c.control == "repro_controls: 4.2 symmetry: FAIL when the impactor drifts sideways");
}

// --- Sect. 4.3, incline ----------------------------------------------------------
TEST_CASE("4.3 Eq. 30 with friction: FAIL with friction off", "[controls][4.3]") {
  for (double phi : {10.0, 20.0}) {
    dda::paper::Incline in = dda::paper::incline(phi);
    in.scene.contact.kt = 0.0;  // friction off: B slides as on a frictionless plane
    const repro::Claim c = incline::eq30_row(phi, incline::run(in, nullptr, phi, dda::FrictionUpdate::kPaper));
    CHECK_FALSE(c.pass);
    CHECK(c.control == "repro_controls: 4.3 Eq. 30 with friction: FAIL with friction off");
  }
}

TEST_CASE("4.3 Eq. 30 without friction: FAIL with friction on", "[controls][4.3]") {
  // The phi = 0 row judged on a run with the 10 deg friction of the next case.
  const repro::Claim c =
      incline::eq30_row(0.0, incline::run(dda::paper::incline(10.0), nullptr, 0.0, dda::FrictionUpdate::kPaper));
  CHECK_FALSE(c.pass);
  CHECK(c.control == "repro_controls: 4.3 Eq. 30 without friction: FAIL with friction on");
}

// --- Sect. 5.1, bouncing block ----------------------------------------------------
TEST_CASE("5.1 H comparison: FAIL with the H rules swapped", "[controls][5.1]") {
  // The wrong H rule: the runs judged as 'unified H' use the inscribed radius
  // and the other way round.
  using dda::HRule;
  const double diff_inscribed = bouncing_block::max_difference(bouncing_block::run(0.1, HRule::kInscribedRadius, "c1"),
                                                               bouncing_block::run(1.0, HRule::kInscribedRadius, "c2"));
  const double diff_unified = bouncing_block::max_difference(bouncing_block::run(0.1, HRule::kMinMaxEdge, "c1"),
                                                             bouncing_block::run(1.0, HRule::kMinMaxEdge, "c2"));
  const repro::Claim swapped = bouncing_block::comparison_row(diff_inscribed, diff_unified);
  CHECK_FALSE(swapped.pass);
  CHECK(swapped.control == "repro_controls: 5.1 H comparison: FAIL with the H rules swapped");
}
