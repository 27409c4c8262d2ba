// Negative controls of the geometry drivers' check rows:
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
#include "repro/5_3_small_edges/small_edges.hpp"
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

// --- 3.2.2, Figs. 4b and 5: the rows specific to each figure ------------------------

namespace {
// A grid over pts with inside, d_exit and phi filled from the given functions.
template <class Inside, class DExit, class Phi>
potential_fields::Grid filled_grid(const std::vector<dda::Vec2>& pts, Inside inside, DExit d_exit, Phi phi) {
  potential_fields::Grid g = potential_fields::make_grid(pts);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t k = g.idx(i, j);
      g.inside[k] = inside(g.at(i, j));
      g.d_exit[k] = d_exit(g.at(i, j));
      g.phi[k] = phi(g.at(i, j));
    }
  return g;
}
}  // namespace

TEST_CASE("3.2.2 Fig. 4b equal penetration: FAIL with H set to each edge's length", "[controls][3.2.2]") {
  // A potential with the wrong H: kn d / L_e, L_e the length of the nearest
  // edge (one H per edge instead of one per assembly). The same penetration
  // below the 0.03 m edge then gives a potential about 30 times the one below
  // the 0.98 m edge: the criterion must see the unequal potentials.
  namespace pf = potential_fields;
  const dda::Polygon poly = fig4_polygon();
  CHECK(pf::equal_penetration_row(poly, [&](dda::Vec2 p) { return dda::potential(poly, p, pf::kKn, pf::kH); }).pass);
  auto per_edge_h = [&](dda::Vec2 p) {
    double d = 1e300, len = 1.0;
    for (int i = 0; i < poly.count; ++i) {
      const double di = dda::dot(poly.normal(i), poly.vertex(i) - p);
      if (di < d) {
        d = di;
        len = dda::length(poly.edge(i));
      }
    }
    return d > 0.0 ? pf::kKn * d / len : 0.0;
  };
  const repro::Claim c = pf::equal_penetration_row(poly, per_edge_h);
  CHECK_FALSE(c.pass);
  CHECK(c.control == control_name(pf::kControlPenetration));
}

TEST_CASE("3.2.2 Fig. 4b edge lines = shortest distance: FAIL on the concave Fig. 5 polygon", "[controls][3.2.2]") {
  // Eqs. 13-14 (edge lines) are valid for a convex polygon only. On the
  // concave Fig. 5 polygon the line of an edge passes inside near the reflex
  // vertices, so min_i n_i . (v_i - p) is below the distance to the nearest
  // boundary segment (even negative) there: the criterion must catch it.
  namespace pf = potential_fields;
  const std::vector<dda::Vec2> convex = pf::small_edge_polygon(), concave = pf::concave_polygon();
  CHECK(pf::edge_lines_row(convex, pf::convex_grid(convex)).pass);
  const pf::Grid g = filled_grid(
      concave, [&](dda::Vec2 p) { return pf::inside_simple(concave, p) && pf::boundary_distance(concave, p) > 0.0; },
      [&](dda::Vec2 p) { return pf::edge_line_distance(concave, p); }, [](dda::Vec2) { return 0.0; });
  const repro::Claim c = pf::edge_lines_row(concave, g);
  CHECK_FALSE(c.pass);
  CHECK(c.control == control_name(pf::kControlEdgeLines));
}

TEST_CASE("3.2.2 Fig. 4b largest potential: FAIL with H halved in the field", "[controls][3.2.2]") {
  // The Fig. 4b field evaluated with H / 2 (twice kn/H): its maximum is
  // 2 kn r / H, not the kn r / H the row expects from the inscribed circle.
  // A field offset by one cm is caught too (its maximum is too high by kn
  // 0.01 / H, ten grid steps).
  namespace pf = potential_fields;
  const std::vector<dda::Vec2> pts = pf::small_edge_polygon();
  const dda::Polygon poly = fig4_polygon();
  auto eq12 = [&](dda::Vec2 p) { return dda::potential(poly, p, pf::kKn, pf::kH); };
  CHECK(pf::inscribed_row(poly, pf::convex_grid(pts), eq12).pass);
  auto inside = [&](dda::Vec2 p) { return dda::locate_point(poly, p) == dda::PointLocation::kInside; };
  auto d_exit = [&](dda::Vec2 p) { return dda::exit_distance(poly, p); };
  auto halved = [&](dda::Vec2 p) { return dda::potential(poly, p, pf::kKn, 0.5 * pf::kH); };
  const repro::Claim c = pf::inscribed_row(poly, filled_grid(pts, inside, d_exit, halved), halved);
  CHECK_FALSE(c.pass);
  CHECK(c.control == control_name(pf::kControlInscribed));
  auto offset = [&](dda::Vec2 p) { return eq12(p) + (inside(p) ? 0.01 * pf::kKn / pf::kH : 0.0); };
  CHECK_FALSE(pf::inscribed_row(poly, filled_grid(pts, inside, d_exit, offset), offset).pass);
}

TEST_CASE("3.2.2 Fig. 5 nearest boundary point: FAIL with the edge-line formula as the field", "[controls][3.2.2]") {
  // The Fig. 5 field computed by Eqs. 13-14 (edge lines) instead of the
  // distance to the boundary segments: not the distance to the nearest
  // boundary point near the reflex vertices, which the independent
  // boundary sampling must detect.
  namespace pf = potential_fields;
  const std::vector<dda::Vec2> pts = pf::concave_polygon();
  const pf::Grid good = pf::concave_grid(pts);
  CHECK(pf::nearest_point_row(pts, good).pass);
  pf::Grid g = good;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t k = g.idx(i, j);
      if (g.inside[k]) g.phi[k] = pf::kKn * pf::edge_line_distance(pts, g.at(i, j)) / pf::kH;
    }
  const repro::Claim c = pf::nearest_point_row(pts, g);
  CHECK_FALSE(c.pass);
  CHECK(c.control == control_name(pf::kControlNearest));
}

TEST_CASE("3.2.2 Fig. 5 edge lines fail on the concave polygon: FAIL on the convex Fig. 4b polygon",
          "[controls][3.2.2]") {
  // The row expects the edge-line formula to give d_exit <= 0 somewhere
  // inside the concave polygon. On the convex Fig. 4b polygon it is exact
  // and positive at every interior point, so the check must FAIL there.
  namespace pf = potential_fields;
  const std::vector<dda::Vec2> concave = pf::concave_polygon(), convex = pf::small_edge_polygon();
  CHECK(pf::concave_lines_row(concave, pf::concave_grid(concave)).pass);
  const repro::Claim c = pf::concave_lines_row(convex, pf::convex_grid(convex));
  CHECK_FALSE(c.pass);
  CHECK(c.control == control_name(pf::kControlConcaveLines));
}

// --- 5.3, mirror symmetry of case 1 ---------------------------------------------------

TEST_CASE("5.3 mirror symmetry: FAIL when the square also moves 1 mm/s sideways", "[controls][5.3]") {
  // Case 1 with the upper square given 1 mm/s along x besides its 1 m/s
  // fall: the impact is no longer symmetric about x = 0 (the centroid
  // drifts and the off-centre hit on the 0.01 m edge turns the square, about
  // 1 cm of asymmetry), far above the 1e-9 m the row allows.
  dda::paper::SmallEdgeImpact si = dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnSmallEdge);
  REQUIRE(si.mirror_symmetric);
  CHECK(small_edges::mirror_row("5.3", "control", small_edges::run(si, 1, nullptr, nullptr)).pass);
  si.scene.blocks[static_cast<std::size_t>(si.upper)].velocity.x += 1e-3;
  const repro::Claim c = small_edges::mirror_row("5.3", "control", small_edges::run(si, 1, nullptr, nullptr));
  CHECK_FALSE(c.pass);
  CHECK(c.control == control_name(small_edges::kControlMirror));
}
