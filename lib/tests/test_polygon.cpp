#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dda/joint_sets.hpp"
#include "dda/polygon.hpp"
#include "dda/rock_scenes.hpp"
#include "test_helpers.hpp"

using namespace dda;
using namespace dda::test;

namespace {
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

namespace {
// Green's theorem one edge at a time, in scalar arithmetic: the reference
// whose bits area_moments and update_polygon_geometry must reproduce.
AreaMoments scalar_moments(const Polygon& p) {
  AreaMoments m;
  const Vec2 o = p.v[0];
  double s = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  for (int i = 0; i < p.count; ++i) {
    const Vec2 a = p.vertex(i) - o, b = p.vertex(p.next(i)) - o;
    const double c = cross(a, b);
    s += c;
    sx += c * (a.x + b.x);
    sy += c * (a.y + b.y);
    sxx += c * (a.x * a.x + a.x * b.x + b.x * b.x);
    syy += c * (a.y * a.y + a.y * b.y + b.y * b.y);
    sxy += c * (a.x * b.y + 2.0 * a.x * a.y + 2.0 * b.x * b.y + b.x * a.y);
  }
  s *= 0.5;
  sx /= 6.0;
  sy /= 6.0;
  m.area = s;
  const Vec2 c{sx / s, sy / s};
  m.centroid = o + c;
  m.sxx = sxx / 12.0 - s * c.x * c.x;
  m.syy = syy / 12.0 - s * c.y * c.y;
  m.sxy = sxy / 24.0 - s * c.x * c.y;
  return m;
}
}  // namespace

TEST_CASE("the one-pass geometry matches normals, moments, bounds and edges one at a time", "[polygon]") {
  // Irregular polygons far from the origin (3 to 6 vertices: the unrolled
  // quadrilateral, odd and even counts), one with a zero-length edge: the
  // normals must be the same bits as the unit right perpendicular of each
  // edge (0 for the empty edge), the moments those of the scalar formula,
  // the bounds the scalar min / max fold, the minimum the smallest squared edge.
  const std::vector<std::vector<Vec2>> shapes = {
      {{1e5 + 0.1, 3.3}, {1e5 + 2.7, 2.9}, {1e5 + 3.1, 4.2}},
      {{1e5 + 0.1, 3.3}, {1e5 + 2.7, 2.9}, {1e5 + 3.1, 4.2}, {1e5 + 1.9, 5.55}},
      {{1e5 + 0.1, 3.3}, {1e5 + 2.7, 2.9}, {1e5 + 3.1, 4.2}, {1e5 + 1.9, 5.55}, {1e5 + 0.3, 4.9}},
      {{-7.1, 3.3}, {-4.5, 2.9}, {-4.1, 4.2}, {-5.3, 5.55}, {-6.9, 4.9}, {-7.2, 4.1}},
      {{1e5 + 0.1, 3.3}, {1e5 + 2.7, 2.9}, {1e5 + 2.7, 2.9}, {1e5 + 1.9, 5.55}},
  };
  for (const auto& pts : shapes) {
    Polygon b = make_polygon(pts.data(), static_cast<int>(pts.size()));
    for (int i = 0; i < b.count; ++i) b.n[static_cast<std::size_t>(i)] = {7.0, 7.0};
    const PolygonGeometry g = update_polygon_geometry(b);
    double expect = DBL_MAX;
    for (int i = 0; i < b.count; ++i) {
      const Vec2 n = normalized(perp_right(b.edge(i)));
      CHECK(n.x == b.normal(i).x);
      CHECK(n.y == b.normal(i).y);
      expect = std::min(expect, length_squared(b.edge(i)));
    }
    CHECK(g.min_edge2 == expect);
    const AreaMoments m = scalar_moments(b), am = area_moments(b);
    for (const AreaMoments& x : {g.moments, am}) {
      CHECK(x.area == m.area);
      CHECK(x.centroid == m.centroid);
      CHECK(x.sxx == m.sxx);
      CHECK(x.syy == m.syy);
      CHECK(x.sxy == m.sxy);
    }
    const AreaMoments ac = area_centroid(b);
    CHECK(ac.area == m.area);
    CHECK(ac.centroid == m.centroid);
    // The bounds: the scalar fold from the empty box (bounds() shares the
    // implementation under test).
    Aabb box;
    for (int i = 0; i < b.count; ++i) {
      box.lo = {std::min(box.lo.x, b.vertex(i).x), std::min(box.lo.y, b.vertex(i).y)};
      box.hi = {std::max(box.hi.x, b.vertex(i).x), std::max(box.hi.y, b.vertex(i).y)};
    }
    for (const Aabb& x : {g.box, bounds(b)}) {
      CHECK(x.lo == box.lo);
      CHECK(x.hi == box.hi);
    }
  }
}

// A self-intersecting quadrilateral turns both ways with a total
// turning of 0; when the right turns outweighed (three right, one left) it
// was labelled clockwise, which reversing cannot fix. (Of 100,000 random
// crossed quadrilaterals in [-1, 1]^2, 26,082 were "clockwise" before the
// fix, this one the first; 0 after.)
TEST_CASE("a bow tie is non-convex, not clockwise", "[polygon]") {
  const std::vector<Vec2> bow = {{0.13969429740419326, 0.27046243662747216},
                                 {-0.82109361271069092, 0.11235779824475989},
                                 {0.57930393901296728, -0.55673265201320743},
                                 {-0.16266294128208603, -0.50044415316658108}};
  CHECK(fault_of(bow) == PolygonFault::kNonConvex);
  CHECK(fault_of({bow[3], bow[2], bow[1], bow[0]}) == PolygonFault::kNonConvex);
  CHECK(fault_of({{0, 0}, {1, 1}, {1, 0}, {0, 1}}) == PolygonFault::kNonConvex);
  CHECK(fault_of({{0, 0}, {1, 0}, {0, 1}, {1, 1}}) == PolygonFault::kNonConvex);
  CHECK(fault_of({{0, 0}, {2, 1}, {2, 0}, {0, 1}}) == PolygonFault::kNonConvex);
  // Negative control: the same square in clockwise order is clockwise.
  CHECK(fault_of({{0, 0}, {0, 1}, {1, 1}, {1, 0}}) == PolygonFault::kClockwise);
  // A concave polygon listed clockwise is non-convex too (reversing it does not help).
  CHECK(fault_of({{0, 2}, {2, 2}, {2, 0}, {1, 0.5}, {0, 0}}) == PolygonFault::kNonConvex);
}

// Coordinates of 1e308 were "duplicate vertex (zero-length edge)"
// (the edge lengths overflow to infinity); they have their own reason.
TEST_CASE("coordinates whose area moments overflow are kOverflow", "[polygon]") {
  CHECK(fault_of({{0, 0}, {1e308, 0}, {0, 1e308}}) == PolygonFault::kOverflow);
  CHECK(fault_of({{-1e300, 0}, {1e300, 0}, {0, 1e300}}) == PolygonFault::kOverflow);
  CHECK(validate_polygon(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 2e75}}.data(), 3).vertex == 2);
  CHECK(std::string(describe(PolygonFault::kOverflow)).find("1e75") != std::string::npos);
  // At the limit: valid, and its second moments are finite.
  const std::vector<Vec2> big = {{-kMaxCoordinate, -kMaxCoordinate}, {kMaxCoordinate, -kMaxCoordinate}, {0, kMaxCoordinate}};
  REQUIRE(fault_of(big) == PolygonFault::kNone);
  const AreaMoments m = area_moments(make_polygon(big.data(), 3));
  CHECK(std::isfinite(m.sxx));
  CHECK(std::isfinite(m.syy));
  CHECK(m.area > 0.0);
}

// The header said 'diameter' where the code uses the bounding
// box's larger side; they now agree (the box side).
TEST_CASE("geometric_tolerance scales with the bounding box side", "[polygon]") {
  // A right triangle with legs 1: diameter sqrt(2), box side 1.
  const Vec2 t[3] = {{0, 0}, {1, 0}, {0, 1}};
  const Polygon p = make_polygon(t, 3);
  CHECK(geometric_tolerance(p) == kRoundoffUlps * DBL_EPSILON * (1.0 + 1.0));
  CHECK(geometric_tolerance(p) != kRoundoffUlps * DBL_EPSILON * (1.0 + diameter(p)));
}

// Blocks are limited to kMaxBlockVertices = 16. A block cut from a
// convex region of r edges by k joint sets has at most r + 2 k edges; no
// generated scene comes near the limit, and a piece that would exceed it is
// refused by generate_blocks. The error for a scene file's block says why.
TEST_CASE("generated blocks fit kMaxBlockVertices", "[polygon]") {
  int most = 0;
  const paper::Collapse c = paper::collapse(30.0);
  for (const BlockSpec& b : c.scene.blocks) most = std::max(most, static_cast<int>(b.vertices.size()));
  const paper::TopplingSlumping ts = paper::toppling_slumping();
  for (const BlockSpec& b : ts.scene.blocks) most = std::max(most, static_cast<int>(b.vertices.size()));
  CHECK(most >= 3);
  CHECK(most <= kMaxBlockVertices);
  // Regions of up to 10 edges cut by up to 3 joint sets (r + 2 k <= 16).
  for (int r = 3; r <= 10; ++r)
    for (int k = 1; k <= 3; ++k) {
      std::vector<Vec2> region;
      for (int i = 0; i < r; ++i) region.push_back({10.0 * std::cos(2 * M_PI * i / r), 10.0 * std::sin(2 * M_PI * i / r)});
      std::vector<JointSet> sets;
      for (int s = 0; s < k; ++s) sets.push_back({17.0 + 53.0 * s, 2.0 + 0.7 * s, {0.31 * s, 0.17}});
      const GeneratedBlocks g = generate_blocks(region, sets, 0.0);
      REQUIRE(!g.blocks.empty());
      for (const Polygon& p : g.blocks) {
        CHECK(p.count <= r + 2 * k);
        CHECK(p.count <= kMaxBlockVertices);
      }
    }
  CHECK(std::string(describe(PolygonFault::kTooManyVertices)).find("kMaxBlockVertices") != std::string::npos);
}
