// Negative controls of Paper B's drivers (issue 21, item 2): B-6 two prisms
// and B-7 contact comparison. Each test applies the driver's own criterion
// (from the driver's header) to a deliberately wrong configuration and
// asserts that the check comes out FAIL (and, where cheap, that the paper's
// configuration passes); the driver's row names the test in its `control`
// field through the shared test-name constant. Part of repro_controls_tests
// (the main is in test_controls.cpp).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "dda/cdem/model.hpp"
#include "dda/cdem/scenes.hpp"
#include "repro/B_6_two_prisms/two_prisms.hpp"
#include "repro/common/claims.hpp"

// --- B-6, two prisms -------------------------------------------------------------
namespace {
// The run of the prisms scene with geometry g and options opt (default: the
// paper's scene, with subdivision).
prisms::Result prisms_run(const dda::cdem::CdemOptions& opt = {}, const dda::cdem::PrismGeometry& g = {}) {
  return prisms::simulate(dda::cdem::two_prisms(2, opt, g));
}
dda::cdem::CdemOptions no_subdivision() {
  dda::cdem::CdemOptions o;
  o.subdivision = false;
  return o;
}
// The row `claim` of prisms::rows(r, coarse) must name `test`.
void names_test(const prisms::Result& r, const prisms::Result& coarse, const std::string& claim, const char* test) {
  for (const repro::Claim& c : prisms::rows(r, coarse))
    if (c.claim == claim) {
      CHECK(c.kind == repro::Kind::kCheck);
      CHECK(c.control == repro::control_test(test));
      return;
    }
  FAIL("B-6: no row '" << claim << "'");
}
}  // namespace

// The row's own verdict is FAIL (the printed step does not contain the
// printed touch time); the control shows the criterion passes on a scene
// built to touch in the printed step and fails on others.
TEST_CASE(prisms::kTestPrintedStep, "[controls][B-6]") {
  const prisms::Result paper = prisms_run(), coarse = prisms_run(no_subdivision());
  names_test(paper, coarse, "the touch falls in the step printed by the paper", prisms::kTestPrintedStep);
  CHECK_FALSE(prisms::in_printed_step(paper.touch));  // 1/3 s lies in [0.3330, 0.3335]
  dda::cdem::PrismGeometry g;
  g.gap = 3.0 * 0.33375;  // m: touch at 0.33375 s, the middle of the printed step
  CHECK(prisms::in_printed_step(prisms_run({}, g).touch));
  g.gap = 1.1;  // touch at 0.3667 s
  CHECK_FALSE(prisms::in_printed_step(prisms_run({}, g).touch));
}

TEST_CASE(prisms::kTestRefined, "[controls][B-6]") {
  const prisms::Result paper = prisms_run(), coarse = prisms_run(no_subdivision());
  names_test(paper, coarse, "the contact zone is refined within c dt2 of the contact point (Sect. 5)",
             prisms::kTestRefined);
  CHECK(prisms::refined_within_c_dt2(paper.touch));
  CHECK_FALSE(prisms::refined_within_c_dt2(coarse.touch));  // radius 0, no element refined
  // Both blocks a quarter as stiff: the model refines within its own c dt2,
  // half the paper's radius (0.32 m against 0.64 m).
  dda::cdem::CdemScene s = dda::cdem::two_prisms(2, {}, {});
  for (auto& m : s.materials) m.young /= 4.0;
  CHECK_FALSE(prisms::refined_within_c_dt2(prisms::simulate(s).touch));
}

TEST_CASE(prisms::kTestSeparation, "[controls][B-6]") {
  const prisms::Result paper = prisms_run(), coarse = prisms_run(no_subdivision());
  names_test(paper, coarse, "the clone node separates after the collision", prisms::kTestSeparation);
  CHECK(prisms::separates_at_fig15a(paper));
  // 14 m prisms: the tension wave returns later, the clone separates at
  // 0.3455 s, 5 ms after Fig. 15a (the window is 2 steps, 1 ms).
  dda::cdem::PrismGeometry g;
  g.length = 14.0;
  CHECK_FALSE(prisms::separates_at_fig15a(prisms_run({}, g)));
}

TEST_CASE(prisms::kTestLittleLoss, "[controls][B-6]") {
  const prisms::Result paper = prisms_run(), coarse = prisms_run(no_subdivision());
  names_test(paper, coarse, "a little energy is lost in the collision", prisms::kTestLittleLoss);
  CHECK(prisms::little_loss(paper));
  // Coarse clone nodes: the Eq. 5 loss of the heavy coarse masses, 7.1 % of
  // E0 (above the 5 % bound of 'a little').
  CHECK_FALSE(prisms::little_loss(coarse));
  // Mass damping alpha = 1/s: 63 % lost, nearly all of it outside the
  // impact and remap balance.
  dda::cdem::CdemOptions damped;
  damped.mass_damping = 1.0;
  CHECK_FALSE(prisms::little_loss(prisms_run(damped)));
}

TEST_CASE(prisms::kTestSubdivisionLoss, "[controls][B-6]") {
  const prisms::Result paper = prisms_run(), coarse = prisms_run(no_subdivision());
  names_test(paper, coarse, "subdivision makes the clone's inelastic loss small (Eq. 5: it falls with the "
             "contact-point mass)", prisms::kTestSubdivisionLoss);
  CHECK(prisms::subdivision_reduces_loss(paper, coarse));  // 517 against 18605 J/m
  // The 'subdivided' run with coarse clone nodes too: the same masses, the
  // same loss, nothing smaller.
  CHECK_FALSE(prisms::subdivision_reduces_loss(prisms_run(no_subdivision()), coarse));
}
