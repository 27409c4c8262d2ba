#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "dda/overlap.hpp"
#include "test_helpers.hpp"

using namespace dda;
using namespace dda::test;

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

namespace {
// Distance from q to the convex polygon p (0 inside): to its nearest edge.
double distance_to(const Polygon& p, Vec2 q) {
  if (locate_point(p, q, 0.0) != PointLocation::kOutside) return 0.0;
  double d = DBL_MAX;
  for (int i = 0; i < p.count; ++i) {
    const Vec2 a = p.vertex(i), e = p.edge(i);
    const double t = std::clamp(dot(q - a, e) / dot(e, e), 0.0, 1.0);
    d = std::min(d, distance(q, a + t * e));
  }
  return d;
}
}  // namespace

// A needle (corner of theta = 1e-4 rad) as the contact, its tip
// inside a diamond whose corner lies d = 0.4 tol / sin(theta / 2) (~8000
// tol) beyond the tip on the needle's axis: within 0.4 tol of both of the
// needle's edge lines, so the clipper kept that corner as an IP vertex,
// 8000 tol from the needle. The bevel at the needle's tip cuts it: every IP
// vertex is within kIpVertexReach tol of both inputs.
TEST_CASE("IP vertices stay near a needle's tip (bevel)", "[overlap]") {
  const double theta = 1e-4, h = std::tan(theta / 2);
  const Vec2 needle_v[3] = {{0, 0}, {1, -h}, {1, h}};
  const Polygon needle = make_polygon(needle_v, 3);
  auto diamond = [](double d) {
    const Vec2 v[4] = {{-d, 0}, {-d + 1, -1}, {-d + 2, 0}, {-d + 1, 1}};
    return make_polygon(v, 4);
  };
  const double d = 0.4 * pair_tolerance(needle, diamond(0.0)) / std::sin(theta / 2);
  const Polygon target = diamond(d);
  const double tol = pair_tolerance(needle, target);  // within a few ulps of the first
  // Negative control: the diamond's corner is within tol of both needle lines, far from the needle.
  CHECK(std::fabs(dot(needle.normal(0), target.vertex(0) - needle.vertex(0))) < tol);
  CHECK(std::fabs(dot(needle.normal(2), target.vertex(0) - needle.vertex(2))) < tol);
  CHECK(distance_to(needle, target.vertex(0)) > 1000.0 * tol);
  Polygon ip;
  REQUIRE(overlap_and_intersection(needle, target, tol, ip, nullptr) == OverlapState::kOverlapping);
  REQUIRE(ip.count >= 3);
  for (int i = 0; i < ip.count; ++i) {
    CHECK(distance_to(needle, ip.vertex(i)) <= kIpVertexReach * tol);
    CHECK(distance_to(target, ip.vertex(i)) <= kIpVertexReach * tol);
  }
  CHECK(area(ip) == Approx(0.5 * 2 * h).epsilon(1e-6));  // the whole needle is inside the diamond
}

// A needle (1e-6 rad) with its tip 0.5 deep in a square, both at
// an offset of 1e9. Along every axis the overlap is far deeper than tol
// (1.4e-5), but the exact intersection is a sliver at most 5e-7 wide: the
// clipper leaves no polygon. The verdict was kOverlapping with an empty IP;
// it is now kTouching (no IP, no force), from the same computation.
TEST_CASE("a sliver thinner than tol is touching, never overlapping without an IP", "[overlap]") {
  const double theta = 1e-6, h = std::tan(theta / 2), c = 1e9;
  const Vec2 needle_v[3] = {{c - 0.5, c + 0.5}, {c + 0.5, c + 0.5 - h}, {c + 0.5, c + 0.5 + h}};
  const Polygon needle = make_polygon(needle_v, 3);
  const Polygon square = rect(c - 1.0, c, 1.0, 1.0);
  const double tol = pair_tolerance(needle, square);
  for (int order = 0; order < 2; ++order) {
    const Polygon& cp = order == 0 ? needle : square;
    const Polygon& tp = order == 0 ? square : needle;
    Polygon ip;
    const OverlapState s = overlap_and_intersection(cp, tp, tol, ip, nullptr);
    CHECK(s != OverlapState::kSeparate);
    CHECK((s == OverlapState::kOverlapping) == (ip.count >= 3));
    CHECK(overlap_state(cp, tp, tol) == s);
    CHECK(intersection_polygon(cp, tp, tol).count == ip.count);
  }
}

TEST_CASE("the block geometry update's support lines and sharp corners are support_lines' and sharp_corners' bits",
          "[overlap]") {
  // A simulation builds each block's support lines and sharp corners in the
  // edge-normal pass of its geometry update; a restored one builds them
  // from the stored normals with support_lines and sharp_corners. Both must
  // give the same bits, for every count a block may have and corners on
  // both sides of the bevel angle, and the geometry must be the plain
  // update's.
  int with_sharp = 0, without_sharp = 0;
  for (int n = 3; n <= kMaxBlockVertices; ++n) {
    for (int s = 0; s < 8; ++s) {
      // An n-gon on an ellipse, flatter with s: the flat ones have corners
      // far below 30 degrees at their ends.
      const double squash = std::pow(0.35, s);
      std::vector<Vec2> v;
      for (int k = 0; k < n; ++k) {
        const double a = 0.3 * s + 2.0 * 3.141592653589793 * k / n;
        v.push_back({3.0 + 2.0 * std::cos(a), -1.0 + 2.0 * squash * std::sin(a)});
      }
      Polygon plain = make_polygon(v.data(), n);
      Polygon fused = plain;
      const PolygonGeometry g0 = update_polygon_geometry(plain);
      const std::size_t pairs = static_cast<std::size_t>(support_line_pairs(n));
      std::vector<SupportLines::Pair> lines(pairs + 1), expect(pairs);
      lines.back().off[0] = 12345.0;  // a sentinel the update must leave alone
      std::uint32_t sharp = ~0u;
      const PolygonGeometry g1 = update_polygon_geometry(fused, lines.data(), sharp);
      CHECK(std::memcmp(&g0, &g1, sizeof g0) == 0);
      CHECK(std::memcmp(plain.n.data(), fused.n.data(), sizeof(Vec2) * static_cast<std::size_t>(n)) == 0);
      support_lines(plain, expect.data());
      CHECK(std::memcmp(lines.data(), expect.data(), sizeof(SupportLines::Pair) * pairs) == 0);
      CHECK(lines.back().off[0] == 12345.0);
      const std::uint32_t want = sharp_corners(plain);
      CHECK(sharp == want);
      ++(want ? with_sharp : without_sharp);
    }
  }
  // Both kinds of polygon were met (the comparison is not of zeros only).
  CHECK(with_sharp > 20);
  CHECK(without_sharp > 20);
}

TEST_CASE("support lines kept by the caller give the overlap test's bits", "[overlap]") {
  // overlap_and_intersection with the polygons' sharp corners and support
  // lines given (as a simulation keeps them per block) must return the same
  // verdict, IP vertices, normals and edge sources as when it builds them,
  // for every pair of counts the dispatch tells apart (3 to 8) and a
  // polygon of more than kMaxBlockVertices vertices (lines then ignored).
  const auto ngon = [](int n, Vec2 c, double r, double turn) {
    std::vector<Vec2> v;
    for (int k = 0; k < n; ++k) {
      const double a = turn + 2.0 * 3.141592653589793 * k / n;
      v.push_back({c.x + r * std::cos(a), c.y + r * (1.0 + 0.3 * (k % 2)) * std::sin(a)});
    }
    return make_polygon(v.data(), n);
  };
  int overlapping = 0;
  for (int na : {3, 4, 5, 6, 7, 8, 20}) {
    for (int nb : {3, 4, 5, 8, 20}) {
      for (int s = 0; s < 12; ++s) {
        const Polygon a = ngon(na, {0.1, -0.2}, 1.0, 0.37 * s);
        const Polygon b = ngon(nb, {0.25 * s - 1.0, 0.9 - 0.13 * s}, 0.8, 0.11 * s);
        // Pooled as a simulation keeps them: b's pairs right after a's, and
        // a sentinel pair after both that support_lines must leave alone.
        const std::size_t pa = static_cast<std::size_t>(support_line_pairs(na));
        const std::size_t pb = static_cast<std::size_t>(support_line_pairs(nb));
        std::vector<SupportLines::Pair> pool(pa + pb + 1);
        pool.back().off[0] = 12345.0;
        support_lines(a, pool.data());
        support_lines(b, pool.data() + pa);
        REQUIRE(pool.back().off[0] == 12345.0);
        const double tol = pair_tolerance(a, b);
        Polygon ip0, ip1;
        std::array<IpEdge, kMaxVertices> src0{}, src1{};
        const OverlapState s0 = overlap_and_intersection(a, b, tol, ip0, src0.data());
        const OverlapState s1 =
            overlap_and_intersection(a, b, tol, ip1, src1.data(), nullptr, OverlapFacts{sharp_corners(a), pool.data(), pool.data() + pa});
        REQUIRE(s0 == s1);
        REQUIRE(ip0.count == ip1.count);
        if (s0 == OverlapState::kOverlapping) ++overlapping;
        for (int k = 0; k < ip0.count; ++k) {
          CHECK(ip0.vertex(k).x == ip1.vertex(k).x);
          CHECK(ip0.vertex(k).y == ip1.vertex(k).y);
          CHECK(ip0.normal(k).x == ip1.normal(k).x);
          CHECK(ip0.normal(k).y == ip1.normal(k).y);
          CHECK(src0[static_cast<std::size_t>(k)].on_contact == src1[static_cast<std::size_t>(k)].on_contact);
          CHECK(src0[static_cast<std::size_t>(k)].edge == src1[static_cast<std::size_t>(k)].edge);
        }
      }
    }
  }
  CHECK(overlapping > 50);  // the cases reach the clip, not only the verdict
}
