// Negative controls of B-6's rows of Paper B Sect. 5 as written (the
// sub-model, SubdivisionMode::kSubModel; prisms::mode_rows): the touch, the
// energy and the momentum. Each test applies the driver's own criterion to
// a deliberately wrong configuration (a wider gap, a step above the
// critical one, the literal transfer of step 5) and asserts FAIL, and to
// the paper's run where it should PASS; the rows name the tests through
// the shared test-name constants.
#include <catch2/catch.hpp>

#include <functional>
#include <string>
#include <vector>

#include "repro/B_6_two_prisms/two_prisms.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/controls.hpp"

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
