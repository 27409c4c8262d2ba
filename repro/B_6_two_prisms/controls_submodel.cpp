// Negative controls of the rows of Paper B Sect. 5 as written (the
// sub-model, SubdivisionMode::kSubModel): B-6's comparison rows
// (prisms::mode_rows) and B-9's sub-model cells (impact::submodel_rows).
// Each test applies the driver's own criterion to a deliberately wrong
// configuration and asserts FAIL (and to a good one where it should PASS);
// the rows name the tests through the shared test-name constants. Part of
// repro_controls_tests (the main is in test_controls.cpp).
#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

#include "repro/B_6_two_prisms/two_prisms.hpp"
#include "repro/B_9_impact_study/impact_study.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/controls_rows.hpp"

namespace {

using dda::cdem::SubdivisionMode;

const prisms::ModeRun& sub_run() {
  static const prisms::ModeRun r = prisms::run_mode(SubdivisionMode::kSubModel, prisms::kPaperDivisions, prisms::kPaperDt);
  return r;
}
const prisms::ModeRun& inplace_run() {
  static const prisms::ModeRun r = prisms::run_mode(SubdivisionMode::kInPlace, prisms::kPaperDivisions, prisms::kPaperDt);
  return r;
}

// The sub-model prisms with options changed by `edit`.
prisms::Result sub_prisms(const std::function<void(dda::cdem::CdemScene&)>& edit) {
  dda::cdem::CdemOptions o;
  o.subdivision_mode = SubdivisionMode::kSubModel;
  dda::cdem::CdemScene s = dda::cdem::two_prisms(prisms::kPaperDivisions, o);
  edit(s);
  return prisms::simulate(s);
}

// The B-6 mode row `claim` must be a check naming `test`.
void b6_names_test(const std::string& claim_start, const char* test) {
  controls::row_names_test(
      prisms::mode_rows(sub_run(), inplace_run(), inplace_run().r),
      [&claim_start](const repro::Claim& c) { return c.claim.rfind(claim_start, 0) == 0; }, test,
      "B-6 starting '" + claim_start + "'");
}

using impact::Cell;
using impact::CellResult;

// The good sub-model cell (30 deg, 5 m/s, mu 0.3) and its finished run.
const Cell kGoodSubCell{30.0, 5.0, 0.3, true, false, true};
const CellResult& good_sub_cell() {
  static const CellResult r = impact::run_cell(kGoodSubCell);
  return r;
}

// The good sub-model cell run on its scene changed by `edit`, at step dt.
CellResult good_sub_cell_with(const std::function<void(dda::cdem::CdemScene&)>& edit, double dt = impact::kDt) {
  dda::cdem::CdemScene s = impact::scene_of(kGoodSubCell, dt);
  edit(s);
  return impact::run_cell(kGoodSubCell, dt, &s);
}

void b9_names_test(const std::string& key, const char* test) {
  controls::key_names_test(impact::submodel_rows({good_sub_cell()}, {}), key, test);
}

}  // namespace

TEST_CASE(prisms::kTestSubTouch, "[controls][B-6][submodel]") {
  b6_names_test("Sect. 5's sub-model (our reading): the touch", prisms::kTestSubTouch);
  CHECK(prisms::touch_time_exact(sub_run().r.touch));
  const prisms::Result wide = sub_prisms([](dda::cdem::CdemScene& s) {
    for (dda::Vec2& p : s.blocks[1].outline) p.x += 0.1;
  });
  INFO("touch at " << wide.touch.time << " s");
  CHECK_FALSE(prisms::touch_time_exact(wide.touch));
}

TEST_CASE(prisms::kTestSubEnergy, "[controls][B-6][submodel]") {
  b6_names_test("Sect. 5's sub-model (our reading): the energy", prisms::kTestSubEnergy);
  CHECK(prisms::energy_never_grows(sub_run().r.accounts));
  std::vector<dda::cdem::CdemEnergyAccount> grown = sub_run().r.accounts;
  grown.back().kinetic = 1.01 * grown.back().initial;  // a row 1 % above E0
  CHECK_FALSE(prisms::energy_never_grows(grown));
  // A real sub-model run at 1.5 times the coarse critical step (the
  // stability check off): the explicit integration grows or stops.
  const double dt = 1.5 * dda::cdem::Model(dda::cdem::two_prisms(prisms::kPaperDivisions)).critical_dt();
  bool failed = false;
  try {
    const prisms::Result r = sub_prisms([&](dda::cdem::CdemScene& s) {
      s.dt = dt;
      s.options.check_stability = false;
    });
    INFO("max E/E0 " << prisms::max_energy_ratio(r.accounts));
    failed = !prisms::energy_never_grows(r.accounts);
  } catch (const dda::SimulationError& e) {
    INFO("stopped: " << e.what());
    failed = true;  // a stopped run has no energy series that stays bounded
  }
  CHECK(failed);
}

TEST_CASE(prisms::kTestSubMomentum, "[controls][B-6][submodel]") {
  b6_names_test("Sect. 5's sub-model (our reading): momentum", prisms::kTestSubMomentum);
  // The default (k = 6): every sub-node's element force returned, momentum
  // to round-off; k = 1: each sub-model is its parent element (no free
  // sub-node), the returned forces are the element's own.
  const prisms::Result k1 = sub_prisms([](dda::cdem::CdemScene& s) {
    s.options.min_subdivision = 1;
    s.options.max_subdivision = 1;
  });
  // The literal reading of step 5 (the forces on the prescribed sub-nodes
  // only): the free sub-nodes' inertia is returned, momentum is lost.
  const prisms::Result literal = sub_prisms(
      [](dda::cdem::CdemScene& s) { s.options.submodel_transfer = dda::cdem::SubModelTransfer::kPrescribedNodes; });
  INFO("max |p - p0| / p0: default (k = " << sub_run().k << ") " << sub_run().r.worst_momentum << ", k = 1 "
                                          << k1.worst_momentum << ", literal " << literal.worst_momentum);
  CHECK(sub_run().k == 6);
  CHECK(prisms::momentum_conserved(sub_run().r));
  CHECK(prisms::momentum_conserved(k1));
  CHECK_FALSE(prisms::momentum_conserved(literal));
}

TEST_CASE(impact::kTestSubPassThrough, "[controls][B-9][submodel]") {
  b9_names_test("submodel-no-pass-through", impact::kTestSubPassThrough);
  REQUIRE(good_sub_cell().ok);
  CHECK(impact::no_pass_through(good_sub_cell()));
  const Cell c{0.0, 1.0, 0.0, true, false, true};
  dda::cdem::CdemScene s = impact::scene_of(c);
  const double depth = 2.0 * s.options.tolerance;
  s.blocks[0].outline = impact::square(-impact::kSide + depth, -0.5 * impact::kSide);
  const CellResult r = impact::run_cell(c, impact::kDt, &s);
  INFO("outcome " << r.outcome);
  CHECK_FALSE(impact::no_pass_through(r));
}

TEST_CASE(impact::kTestSubEnergy, "[controls][B-9][submodel]") {
  b9_names_test("submodel-kinetic-energy", impact::kTestSubEnergy);
  CHECK(impact::energy_never_grows(good_sub_cell()));
  const double dt = 1.5 * dda::cdem::Model(impact::scene_of(kGoodSubCell)).critical_dt();
  const CellResult r = good_sub_cell_with([](dda::cdem::CdemScene& s) { s.options.check_stability = false; }, dt);
  INFO("outcome " << r.outcome << ", max KE/KE0 - 1 = " << r.ke_growth);
  CHECK_FALSE(impact::energy_never_grows(r));
}

TEST_CASE(impact::kTestSubSeparation, "[controls][B-9][submodel]") {
  b9_names_test("submodel-separation", impact::kTestSubSeparation);
  CHECK(impact::separates(good_sub_cell()));
  const CellResult r = good_sub_cell_with([](dda::cdem::CdemScene& s) {
    s.options.strength.tensile = 1e12;
    s.options.strength.cohesion = 1e12;
  });
  INFO("outcome " << r.outcome);
  CHECK_FALSE(impact::separates(r));
}

TEST_CASE(impact::kTestSubTouchLoss, "[controls][B-9][submodel]") {
  b9_names_test("submodel-touch-loss-eq5", impact::kTestSubTouchLoss);
  CellResult r = good_sub_cell();
  CHECK(impact::touch_loss_within_eq5(r));
  r.touch_loss = 1.1 * r.touch_loss_eq5_group;  // 10 % above the group's Eq. 5
  CHECK_FALSE(impact::touch_loss_within_eq5(r));
}

TEST_CASE(impact::kTestSubTotalLoss, "[controls][B-9][submodel]") {
  b9_names_test("submodel-total-loss-eq5", impact::kTestSubTotalLoss);
  CHECK(impact::total_loss_within_block_eq5(good_sub_cell()));
  const CellResult r = good_sub_cell_with([](dda::cdem::CdemScene& s) { s.options.mass_damping = 2000.0; });
  INFO("outcome " << r.outcome << ", loss / block Eq. 5 = " << r.total_loss / r.block_eq5);
  CHECK_FALSE(impact::total_loss_within_block_eq5(r));
}
