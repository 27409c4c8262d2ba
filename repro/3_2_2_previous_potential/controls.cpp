// Negative controls of the Sect. 3.2.2 Fig. 4a rows (the previous
// sub-polygon potential, a reconstruction): the undefined part, the hexagon
// control, previous = shortest exit and the 5.3 impact beyond d*, each
// judged by the driver's own criterion on a polygon, offset or stiffness
// changed so that the property fails.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "dda/robustness_scenes.hpp"
#include "repro/3_2_2_potential_fields/potential_fields.hpp"
#include "repro/3_2_2_previous_potential/previous_potential.hpp"
#include "repro/common/claims.hpp"

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
  CHECK(c.control == repro::control_test(pp::kControlUndefined));
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
  CHECK(c.control == repro::control_test(pp::kControlHexagon));
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
  CHECK(c.control == repro::control_test(pp::kControlMismatch));
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
  CHECK(c.control == repro::control_test(pp::kControlImpact));
}
