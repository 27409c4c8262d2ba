#include <catch2/catch.hpp>

#include <cmath>

#include "dda/overlap.hpp"

using namespace dda;

namespace {
Polygon rect(double x0, double y0, double w, double h) {
  const Vec2 p[4] = {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
  return make_polygon(p, 4);
}
}  // namespace

TEST_CASE("entrance block of two squares is the 2x2 square around a0 - b offset", "[overlap]") {
  const Polygon a = rect(0, 0, 1, 1), b = rect(3, 0, 1, 1);
  const EntranceBlock e = entrance_block(a, b, {0.5, 0.5});
  // B - A = [2,4] x [-1,1]; plus a0.
  CHECK(e.poly.count == 4);
  CHECK(area(e.poly) == Approx(4.0));
  const Aabb bb = bounds(e.poly);
  CHECK(bb.lo.x == Approx(2.5));
  CHECK(bb.hi.x == Approx(4.5));
  CHECK(bb.lo.y == Approx(-0.5));
  CHECK(bb.hi.y == Approx(1.5));
}

TEST_CASE("overlap states: apart, touching, overlapping", "[overlap]") {
  const Polygon a = rect(0, 0, 1, 1);
  CHECK(overlap_state(a, rect(2, 0, 1, 1)) == OverlapState::kSeparate);
  CHECK(overlap_state(a, rect(1, 0, 1, 1)) == OverlapState::kTouching);
  CHECK(overlap_state(a, rect(1, 1, 1, 1)) == OverlapState::kTouching);  // corner only
  CHECK(overlap_state(a, rect(0.99, 0.2, 1, 1)) == OverlapState::kOverlapping);
  CHECK(overlap_state(a, a) == OverlapState::kOverlapping);
  CHECK(overlap_state(a, rect(0.25, 0.25, 0.5, 0.5)) == OverlapState::kOverlapping);
}

TEST_CASE("intersection polygon of overlapping rectangles", "[overlap]") {
  const Polygon a = rect(0, 0, 1, 1), b = rect(0.9, 0.5, 1, 1);
  const Polygon ip = intersection_polygon(a, b);
  CHECK(ip.count == 4);
  CHECK(area(ip) == Approx(0.1 * 0.5));
  const Polygon ip2 = intersection_polygon(b, a);
  CHECK(area(ip2) == Approx(area(ip)));
  // Shared edge line and shared vertices: no duplicates, no zero-length edges.
  const Polygon c = rect(0, 0, 1, 0.5);
  const Polygon ip3 = intersection_polygon(a, c);
  CHECK(ip3.count == 4);
  CHECK(min_edge_length(ip3) > 0.1);
  CHECK(intersection_polygon(a, rect(1, 0, 1, 1)).count == 0);
}
