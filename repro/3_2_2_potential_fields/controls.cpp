// Negative controls of the Sect. 3.2.2 potential-field rows (Figs. 4b and
// 5): the checks shared by both figures on an offset, a shifted and a
// doubled field, and each figure's own rows on a field or polygon changed so
// that the property fails (one H per edge, the concave polygon, H halved,
// the edge-line formula as the field). Each must PASS on the driver's field
// and FAIL on the wrong one.
#include <catch2/catch.hpp>

#include <cstddef>
#include <string>
#include <vector>

#include "repro/3_2_2_potential_fields/potential_fields.hpp"
#include "repro/common/claims.hpp"

namespace {
dda::Polygon fig4_polygon() {
  const std::vector<dda::Vec2> pts = potential_fields::small_edge_polygon();
  return dda::make_polygon(pts.data(), static_cast<int>(pts.size()));
}

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

TEST_CASE("3.2.2 potential field: FAIL on an offset, a shifted and a doubled field", "[controls][3.2.2]") {
  // The Fig. 4b polygon's grid filled with Eq. 12's field and with three
  // wrong ones; add_common_claims gives rows [0] zero on the boundary and
  // positive inside, [1] defined everywhere inside, [2] slope <= kn/H.
  namespace pf = potential_fields;
  const std::vector<dda::Vec2> pts = pf::small_edge_polygon();
  const dda::Polygon poly = dda::make_polygon(pts.data(), static_cast<int>(pts.size()));
  auto rows = [&](auto phi) {
    pf::Grid g = pf::make_grid(pts);
    for (int j = 0; j < g.ny; ++j)
      for (int i = 0; i < g.nx; ++i) {
        const std::size_t k = g.idx(i, j);
        g.inside[k] = dda::locate_point(poly, g.at(i, j)) == dda::PointLocation::kInside;
        g.phi[k] = phi(g.at(i, j));
      }
    std::vector<repro::Claim> c;
    pf::add_common_claims(c, "control", g, pf::boundary_max_abs(pts, phi));
    REQUIRE(c.size() == 3);
    return c;
  };
  const double k = pf::kKn / pf::kH;
  auto eq12 = [&](dda::Vec2 p) { return dda::potential(poly, p, pf::kKn, pf::kH); };
  const auto good = rows(eq12);
  for (const repro::Claim& c : good) CHECK(c.pass);
  // Offset by 1 cm: not zero on the boundary.
  CHECK_FALSE(rows([&](dda::Vec2 p) { return eq12(p) + 0.01 * k; })[0].pass);
  // Shifted 5 cm inward: phi <= 0 in a band inside the boundary.
  CHECK_FALSE(rows([&](dda::Vec2 p) { return k * (dda::exit_distance(poly, p) - 0.05); })[1].pass);
  // Doubled (H / 2 in the field only): slope 2 kn/H.
  CHECK_FALSE(rows([&](dda::Vec2 p) { return 2.0 * eq12(p); })[2].pass);
}

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
  CHECK(c.control == repro::control_test(pf::kControlPenetration));
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
  CHECK(c.control == repro::control_test(pf::kControlEdgeLines));
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
  CHECK(c.control == repro::control_test(pf::kControlInscribed));
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
  CHECK(c.control == repro::control_test(pf::kControlNearest));
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
  CHECK(c.control == repro::control_test(pf::kControlConcaveLines));
}

