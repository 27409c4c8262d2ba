#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

#include "dda/polygon.hpp"

using namespace dda;

namespace {
Polygon rect(double x0, double y0, double w, double h) {
  const Vec2 p[4] = {{x0, y0}, {x0 + w, y0}, {x0 + w, y0 + h}, {x0, y0 + h}};
  return make_polygon(p, 4);
}
PolygonFault fault_of(std::vector<Vec2> p) { return validate_polygon(p.data(), static_cast<int>(p.size())).fault; }
}  // namespace

TEST_CASE("rectangle moments equal the closed forms", "[polygon]") {
  const double w = 3.0, h = 2.0;
  const AreaMoments m = area_moments(rect(1e6, -5.0, w, h));
  CHECK(m.area == Approx(w * h).epsilon(1e-14));
  CHECK(m.centroid.x == Approx(1e6 + w / 2).epsilon(1e-15));
  CHECK(m.centroid.y == Approx(-5.0 + h / 2).epsilon(1e-15));
  CHECK(m.sxx == Approx(h * w * w * w / 12).epsilon(1e-10));
  CHECK(m.syy == Approx(w * h * h * h / 12).epsilon(1e-10));
  CHECK(std::fabs(m.sxy) < 1e-9);
}

TEST_CASE("right triangle moments equal the closed forms", "[polygon]") {
  // Legs a (x) and b (y): Sxx = a^3 b / 36, Syy = a b^3 / 36, Sxy = -a^2 b^2 / 72.
  const double a = 2.0, b = 3.0;
  const Vec2 p[3] = {{0, 0}, {a, 0}, {0, b}};
  const AreaMoments m = area_moments(make_polygon(p, 3));
  CHECK(m.area == Approx(a * b / 2));
  CHECK(m.centroid.x == Approx(a / 3));
  CHECK(m.centroid.y == Approx(b / 3));
  CHECK(m.sxx == Approx(a * a * a * b / 36));
  CHECK(m.syy == Approx(a * b * b * b / 36));
  CHECK(m.sxy == Approx(-a * a * b * b / 72));
}

TEST_CASE("validation names each fault", "[polygon]") {
  CHECK(fault_of({{0, 0}, {1, 0}, {0, 1}}) == PolygonFault::kNone);
  CHECK(fault_of({{0, 0}, {1, 0}}) == PolygonFault::kTooFewVertices);
  CHECK(fault_of({{0, 0}, {0, 1}, {1, 0}}) == PolygonFault::kClockwise);
  CHECK(fault_of({{0, 0}, {NAN, 0}, {0, 1}}) == PolygonFault::kNonFinite);
  CHECK(fault_of({{0, 0}, {1, 0}, {1, 0}, {0, 1}}) == PolygonFault::kDuplicateVertex);
  CHECK(fault_of({{0, 0}, {0.5, 0}, {1, 0}, {0, 1}}) == PolygonFault::kCollinear);
  CHECK(fault_of({{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}}) == PolygonFault::kNonConvex);
  // A pentagram turns left at every vertex but winds twice.
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) {
    const double t = 2.0 * M_PI * (2 * k) / 5.0;
    star.push_back({std::cos(t), std::sin(t)});
  }
  CHECK(fault_of(star) == PolygonFault::kNonConvex);
  std::vector<Vec2> many;
  for (int k = 0; k < 17; ++k) many.push_back({std::cos(2 * M_PI * k / 17), std::sin(2 * M_PI * k / 17)});
  CHECK(fault_of(many) == PolygonFault::kTooManyVertices);
  // A 0.5-degree angle and a 1e-6 edge are valid.
  const double t = 0.5 * M_PI / 180.0;
  CHECK(fault_of({{0, 0}, {1, 0}, {std::cos(t), std::sin(t)}}) == PolygonFault::kNone);
  CHECK(fault_of({{0, 0}, {1, 0}, {1, 1}, {1 - 1e-6, 1 + 1e-6}, {0, 1}}) == PolygonFault::kNone);
}

TEST_CASE("point location has three answers", "[polygon]") {
  const Polygon r = rect(0, 0, 1, 1);
  CHECK(locate_point(r, {0.5, 0.5}) == PointLocation::kInside);
  CHECK(locate_point(r, {1.0, 0.5}) == PointLocation::kOnBoundary);
  CHECK(locate_point(r, {1.0, 1.0}) == PointLocation::kOnBoundary);
  CHECK(locate_point(r, {1.0 + 1e-9, 0.5}) == PointLocation::kOutside);
  CHECK(locate_point(r, {1.0 - 1e-9, 0.5}) == PointLocation::kInside);
}

TEST_CASE("splitting a polygon by a line conserves area", "[polygon]") {
  const Polygon r = rect(0, 0, 2, 1);
  Polygon lo, hi;
  split_polygon(r, {1.0, 0.0}, normalized({1.0, 0.3}), lo, hi);
  CHECK(lo.count >= 3);
  CHECK(hi.count >= 3);
  CHECK(area(lo) + area(hi) == Approx(2.0).epsilon(1e-14));
  // Through a vertex along a diagonal: two triangles, no duplicate vertex.
  split_polygon(r, {0, 0}, normalized(perp_right({2.0, 1.0})), lo, hi);
  CHECK(lo.count == 3);
  CHECK(hi.count == 3);
  // A line missing the polygon leaves one side empty.
  split_polygon(r, {5, 0}, {1, 0}, lo, hi);
  CHECK(lo.count == 4);
  CHECK(hi.count == 0);
}

TEST_CASE("the one-pass normals and smallest edge match normalized(perp_right(edge)) and length_squared", "[polygon]") {
  // Irregular pentagon far from the origin: the normals must be the same
  // bits as the unit right perpendicular of each edge, the minimum the
  // smallest squared edge length.
  const Vec2 p[5] = {{1e5 + 0.1, 3.3}, {1e5 + 2.7, 2.9}, {1e5 + 3.1, 4.2}, {1e5 + 1.9, 5.55}, {1e5 + 0.3, 4.9}};
  Polygon b = make_polygon(p, 5);
  const double min2 = update_normals_min_edge2(b);
  double expect = DBL_MAX;
  for (int i = 0; i < 5; ++i) {
    const Vec2 n = normalized(perp_right(b.edge(i)));
    CHECK(n.x == b.normal(i).x);
    CHECK(n.y == b.normal(i).y);
    expect = std::min(expect, length_squared(b.edge(i)));
  }
  CHECK(min2 == expect);
}
