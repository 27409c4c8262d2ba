#include <catch2/catch.hpp>

#include <cmath>

#include "dda/potential.hpp"
#include "test_helpers.hpp"

using namespace dda;
using namespace dda::test;

TEST_CASE("exit distance and potential of a rectangle", "[potential]") {
  const Polygon r = rect(0, 0, 4, 2);
  CHECK(exit_distance(r, {1, 1}) == Approx(1.0));
  CHECK(exit_distance(r, {0.25, 1}) == Approx(0.25));
  CHECK(potential(r, {0.25, 1}, 10.0, 2.0) == Approx(1.25));
  CHECK(potential(r, {-1, 1}, 10.0, 2.0) == 0.0);
  const Vec2 g = potential_gradient(r, {0.25, 1}, 10.0, 2.0);
  CHECK(g.x == Approx(5.0));  // pointing inward from the left edge
  CHECK(g.y == Approx(0.0).margin(1e-15));
}

TEST_CASE("inscribed circle of a rectangle, triangle and square", "[potential]") {
  CHECK(inscribed_circle(rect(0, 0, 4, 2)).radius == Approx(1.0));
  const Vec2 t[3] = {{0, 0}, {3, 0}, {0, 4}};  // 3-4-5: r = (a + b - c) / 2 = 1
  const InscribedCircle c = inscribed_circle(make_polygon(t, 3));
  CHECK(c.radius == Approx(1.0));
  CHECK(c.centre.x == Approx(1.0));
  CHECK(c.centre.y == Approx(1.0));
  CHECK(inscribed_circle(rect(5, 5, 1, 1)).radius == Approx(0.5));
}

TEST_CASE("bisector rays and the virtual node of a small edge", "[potential]") {
  Ray rays[kMaxVertices];
  const Polygon sq = rect(0, 0, 1, 1);
  REQUIRE(bisector_rays(sq, 1e-3, rays) == 4);
  CHECK(rays[0].dir.x == Approx(std::sqrt(0.5)));
  CHECK(rays[0].dir.y == Approx(std::sqrt(0.5)));
  // A square with its top-right corner cut by a 0.01 edge at 45 degrees.
  const double c = 0.01 / std::sqrt(2.0);
  const Vec2 p[5] = {{0, 0}, {1, 0}, {1, 1 - c}, {1 - c, 1}, {0, 1}};
  const Polygon cut = make_polygon(p, 5);
  const int n = bisector_rays(cut, 0.05, rays);
  REQUIRE(n == 4);
  // The virtual node lies on the diagonal, its ray points to the centre.
  CHECK(rays[0].origin.x == Approx(rays[0].origin.y));
  CHECK(rays[0].dir.x == Approx(-std::sqrt(0.5)));
  CHECK(rays[0].dir.y == Approx(-std::sqrt(0.5)));
  // It passes through the centre (0.5, 0.5), ahead of its origin.
  CHECK(cross(Vec2{0.5, 0.5} - rays[0].origin, rays[0].dir) == Approx(0.0).margin(1e-12));
  CHECK(dot(Vec2{0.5, 0.5} - rays[0].origin, rays[0].dir) > 0.0);
}

TEST_CASE("a small edge's virtual node adds to or replaces the vertex rays", "[potential]") {
  const double c = 0.01 / std::sqrt(2.0);
  const Vec2 p[5] = {{0, 0}, {1, 0}, {1, 1 - c}, {1 - c, 1}, {0, 1}};
  const Polygon cut = make_polygon(p, 5);
  Ray rays[2 * kMaxVertices];
  CHECK(bisector_rays(cut, 0.05, SmallEdgeRays::kVirtualAndVertex, rays) == 6);     // 5 vertices + 1 node
  CHECK(bisector_rays(cut, 0.05, SmallEdgeRays::kVirtualReplacesVertex, rays) == 4);  // 3 vertices + 1 node
  CHECK(bisector_rays(cut, 0.001, SmallEdgeRays::kVirtualAndVertex, rays) == 5);    // no small edge
}

TEST_CASE("each bisector ray is where its two edge lines are equally far, from d0 on", "[potential]") {
  // The contact integration finds ray crossings from the distances to the
  // ray's two lines (Ray::lines), not from origin and dir: the
  // two descriptions must be the same ray. Polygons with small edges (so
  // virtual nodes occur), both small-edge modes.
  const double c = 0.01 / std::sqrt(2.0);
  const Vec2 cut[5] = {{0, 0}, {1, 0}, {1, 1 - c}, {1 - c, 1}, {0, 1}};
  const Vec2 tri[3] = {{2, 1}, {5, 1.5}, {3, 4}};
  const Vec2 chamfered[6] = {{10, -3}, {12, -3}, {12, -2.1}, {11.9, -2}, {10.05, -2}, {10, -2.05}};
  const Polygon polys[3] = {make_polygon(cut, 5), make_polygon(tri, 3), make_polygon(chamfered, 6)};
  auto line_distance = [](const Polygon& p, int i, Vec2 x) { return dot(p.normal(i), p.vertex(i) - x); };
  int virtual_rays = 0;
  for (const Polygon& poly : polys)
    for (SmallEdgeRays mode : {SmallEdgeRays::kVirtualAndVertex, SmallEdgeRays::kVirtualReplacesVertex}) {
      Ray rays[2 * kMaxVertices];
      Bisector lines[2 * kMaxVertices];
      const int n = bisector_rays(poly, 0.35, mode, rays);
      REQUIRE(bisectors(poly, 0.35, mode, lines) == n);  // what a simulation keeps: the same, in order
      for (int r = 0; r < n; ++r) {
        CHECK(lines[r].line_a == rays[r].lines.line_a);
        CHECK(lines[r].line_b == rays[r].lines.line_b);
        CHECK(lines[r].d0 == rays[r].lines.d0);
        const Bisector& ray = rays[r].lines;
        REQUIRE(ray.line_a >= 0);
        REQUIRE(ray.line_b >= 0);
        REQUIRE(ray.line_a != ray.line_b);
        if (ray.d0 > 0.0) ++virtual_rays;
        for (double s : {0.0, 0.05, 0.2, 0.4}) {
          const Vec2 x = rays[r].origin + s * rays[r].dir;
          const double da = line_distance(poly, ray.line_a, x), db = line_distance(poly, ray.line_b, x);
          CHECK(da == Approx(db).margin(1e-12));
          if (s == 0.0) CHECK(da == Approx(ray.d0).margin(1e-12));
          else CHECK(da > ray.d0);  // the distance grows along the ray: d >= d0 is the ray's side
        }
      }
    }
  CHECK(virtual_rays == 6);  // three small edges, each in both modes
}

// A triangle a few units of the coordinate spacing wide (at 1e6 the
// spacing is 1.16e-10 m) has no centre with a positive exit distance: every
// candidate rounds onto the grid. inscribed_circle returned r = 0 at (0, 0),
// 1.4e6 m away; now r = 0 at a point of the polygon (the error callers test).
TEST_CASE("inscribed circle below the coordinate spacing is at a point of the polygon", "[potential]") {
  const double x = 1e6, u = std::nextafter(x, 2e6) - x;  // the spacing at 1e6
  const Vec2 t[3] = {{x, x}, {x + 2 * u, x}, {x, x + 2 * u}};
  const Polygon p = make_polygon(t, 3);
  REQUIRE(validate_polygon(t, 3).ok());
  const InscribedCircle c = inscribed_circle(p);
  CHECK(c.radius >= 0.0);
  CHECK(locate_point(p, c.centre, 0.0) != PointLocation::kOutside);
  CHECK(c.radius == exit_distance(p, c.centre) * (c.radius > 0.0 ? 1.0 : 0.0));
  // Negative control: the same triangle scaled up has a positive radius at its incentre.
  const Vec2 big[3] = {{x, x}, {x + 2, x}, {x, x + 2}};
  CHECK(inscribed_circle(make_polygon(big, 3)).radius == Approx(2.0 - std::sqrt(2.0)).epsilon(1e-9));
}
