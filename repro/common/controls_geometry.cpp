// Negative controls of the geometry drivers' check rows (issue 21, item 2):
// 3.2.2 previous potential (Fig. 4a), 3.2.2 potential fields (Figs. 4b, 5),
// 5.3 mirror symmetry and 5.5 segmentation. Each test applies the driver's
// own criterion (from the driver's header / library) to a deliberately wrong
// configuration and asserts that the check comes out FAIL; the driver's row
// names the test in its `control` field. Part of repro_controls_tests (the
// main is in test_controls.cpp).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "dda/robustness_scenes.hpp"
#include "repro/3_2_2_potential_fields/potential_fields.hpp"
#include "repro/3_2_2_previous_potential/previous_potential.hpp"
#include "repro/5_5_segmentation/segmentation.hpp"
#include "repro/common/claims.hpp"

namespace {
std::string control_name(const char* test) { return std::string("repro_controls: ") + test; }
}  // namespace

// --- 5.5, segmentation ------------------------------------------------------------

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
  CHECK(c.control == control_name(sg::kControlExact));
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
  CHECK(c.control == control_name(sg::kControlRectangle));
}

// --- 3.2.2, Fig. 4a: the previous sub-polygon potential (reconstruction) ----------

namespace {
dda::Polygon fig4_polygon() {
  const std::vector<dda::Vec2> pts = potential_fields::small_edge_polygon();
  return dda::make_polygon(pts.data(), static_cast<int>(pts.size()));
}
}  // namespace

TEST_CASE("3.2.2 Fig. 4a undefined part: FAIL on a regular hexagon (no small edge)", "[controls][3.2.2]") {
  // The row's criterion (more than 10 % of the interior in no sub-polygon)
  // applied to the regular hexagon: with no small edge its offset depth d* is
  // the inscribed radius, the sub-polygons tile it and nothing is undefined,
  // so a "large undefined part" there would mean the scan counts wrongly.
  namespace pp = previous_potential;
  const dda::Polygon fig = fig4_polygon();
  const pp::SubPolygons sp = pp::sub_polygons(fig);
  CHECK(pp::undefined_row(pp::scan_field(fig, sp, nullptr), sp.depth, dda::inscribed_circle(fig).radius).pass);
  const dda::Polygon hex = pp::regular_hexagon();
  const pp::SubPolygons sh = pp::sub_polygons(hex);
  const pp::FieldScan f = pp::scan_field(hex, sh, nullptr);
  REQUIRE(f.inside > 0);
  const repro::Claim c = pp::undefined_row(f, sh.depth, dda::inscribed_circle(hex).radius);
  CHECK_FALSE(c.pass);
  CHECK(c.control == control_name(pp::kControlUndefined));
}

TEST_CASE("3.2.2 Fig. 4a hexagon control: FAIL when the hexagon is replaced by the Fig. 4a polygon",
          "[controls][3.2.2]") {
  // The row's criterion (d* / inscribed radius = 1 within 1e-9) on the
  // Fig. 4a polygon instead of the hexagon: its 0.03 m edge's bisectors meet
  // a few cm inside, far short of the 0.47 m inscribed radius.
  namespace pp = previous_potential;
  CHECK(pp::hexagon_row(pp::depth_ratio(pp::regular_hexagon())).pass);
  const repro::Claim c = pp::hexagon_row(pp::depth_ratio(fig4_polygon()));
  CHECK_FALSE(c.pass);
  CHECK(c.control == control_name(pp::kControlHexagon));
}

TEST_CASE("3.2.2 Fig. 4a previous = shortest exit: FAIL with sub-polygons offset to the inscribed radius",
          "[controls][3.2.2]") {
  // The sub-polygons of the Fig. 4a polygon cut at the inscribed radius
  // instead of d*: beyond d* the bisectors at the small edges' ends have
  // crossed, so a sub-polygon then covers points nearer to another edge and
  // its kn d_i / H is larger than the shortest-exit potential there.
  namespace pp = previous_potential;
  const dda::Polygon fig = fig4_polygon();
  CHECK(pp::mismatch_row(pp::scan_field(fig, pp::sub_polygons(fig), nullptr)).pass);
  const pp::SubPolygons deep = pp::sub_polygons(fig, dda::inscribed_circle(fig).radius);
  const repro::Claim c = pp::mismatch_row(pp::scan_field(fig, deep, nullptr));
  CHECK_FALSE(c.pass);
  CHECK(c.control == control_name(pp::kControlMismatch));
}

TEST_CASE("3.2.2 / 5.3 impact beyond d*: FAIL when kn is 100 times too stiff", "[controls][3.2.2][5.3]") {
  // The 5.3 case-1 impact with kn 100 times the paper's: the penetration
  // shrinks (deepest IP vertex about 4 mm instead of 20 mm), well short of
  // the lower block's d* = 18 mm, so no contact step reaches the undefined
  // part and the check must FAIL.
  namespace pp = previous_potential;
  dda::paper::SmallEdgeImpact si = dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnSmallEdge);
  CHECK(pp::impact_row(pp::impact_depth(si)).pass);
  si.scene.contact.kn *= 100.0;
  const pp::Impact r = pp::impact_depth(si);
  REQUIRE(r.contact_steps > 0);
  const repro::Claim c = pp::impact_row(r);
  CHECK_FALSE(c.pass);
  CHECK(c.control == control_name(pp::kControlImpact));
}
