// Negative controls of the Sect. 6.1 collapse rows (repro/6_1_collapse): each
// applies the driver's own criterion (repro/6_1_collapse/collapse.hpp) to a
// deliberately wrong configuration the claim depends on and asserts FAIL.
// Part of repro_controls_tests (test_controls.cpp has the main).
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
