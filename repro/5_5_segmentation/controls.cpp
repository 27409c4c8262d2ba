// Negative controls of the Sect. 5.5 segmentation rows: exactness of the
// paper's rule on the Sect. 4-5 runs against SPEC.md's reading of the
// small-edge rule, and the rectangle case with the corner too shallow to
// cross the middle medial segment.
#include <catch2/catch.hpp>

#include <string>

#include "dda/robustness_scenes.hpp"
#include "repro/5_5_segmentation/segmentation.hpp"
#include "repro/common/claims.hpp"

TEST_CASE("5.5 segmentation exact on the Sect. 4-5 runs: FAIL with SPEC.md's reading on the 5.3 impact",
          "[controls][5.5]") {
  // The row's criterion (largest relative force error over the scanned
  // contacts < 1e-8) on the 5.3 case-1 impact, once for the library default
  // and once for SPEC.md's reading of the small-edge rule (the virtual node
  // replaces the vertex rays). That reading drops the vertex rays at the
  // 0.01 m edge, so kinks of phi along the IP edges lie between demarcation
  // points and the trapezoid rule is off: the criterion must see it.
  namespace sg = segmentation;
  const dda::paper::SmallEdgeImpact si = dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnSmallEdge);
  const sg::SceneStats st = sg::scan("control 5.3 case 1", si.scene, 1, 0, nullptr);
  REQUIRE(st.mode[sg::kPaperRule].n > 0);
  CHECK(sg::exact_row({st}).pass);
  const repro::Claim c = sg::exact_row({st}, sg::kReplaceRule);
  CHECK_FALSE(c.pass);
  CHECK(c.control == repro::control_test(sg::kControlExact));
}

TEST_CASE("5.5 rectangle: FAIL when the corner stays above the middle medial segment", "[controls][5.5]") {
  // The row expects the paper's rule to be inexact (force error > 1e-6) for a
  // corner 0.7 m deep, across the rectangle's middle medial segment y = 0.5.
  // 0.3 m deep the IP stays in the band where the top edge is the nearest
  // one (no kink of phi_TP) and the square's kinks lie on its diagonals,
  // which are vertex rays: the rule is exact there, so the check must FAIL.
  namespace sg = segmentation;
  CHECK(sg::rectangle_row(sg::kRectangleDepth, sg::rectangle_case(sg::kRectangleDepth)).pass);
  const sg::Errors shallow = sg::rectangle_case(0.3);
  REQUIRE(shallow.valid);
  const repro::Claim c = sg::rectangle_row(0.3, shallow);
  CHECK_FALSE(c.pass);
  CHECK(c.control == repro::control_test(sg::kControlRectangle));
}
