// Regression tests: every counterexample the properties found, saved with its
// exact inputs (17 significant digits round-trip every double) and run
// through the same checks as the properties (checks.hpp), plus the specific
// symptom of the bug it exposed. One TEST_CASE per failure found; the name
// says which kernel function failed and why.
#include <catch2/catch.hpp>

#include "checks.hpp"
#include "dda/overlap.hpp"
#include "dda/potential.hpp"

using namespace prop;

// Found by property "exit distance and inscribed circle" (seed 1, 1,000
// cases): a 0.5-degree sliver at an offset of 1e6. inscribed_circle solved its
// 3x3 systems in absolute coordinates (right-hand sides ~1e6, round-off
// ~1e-10) and accepted a centre only if exit_distance(c) >= r (1 - 1e-12), a
// relative slack of 5e-17 here: every candidate was rejected and the radius
// came back 0. Fixed in lib/src/potential.cpp: systems solved relative to
// v_0, each candidate scored by its actual exit distance.
TEST_CASE("regression: inscribed_circle of a sliver at offset 1e6 is not 0", "[regression]") {
  const Points p = {{-1000000.03125, -1000000}, {-999999.96875, -1000000}, {-1000000.018750476, -999999.99989091826}};
  REQUIRE(is_valid(p));
  const dda::Polygon poly = to_polygon(p);
  const dda::InscribedCircle ic = dda::inscribed_circle(poly);
  // The inradius of the same triangle moved exactly to the origin, within the
  // kernel's round-off at this offset.
  CHECK(ic.radius == Approx(5.4540609723142346e-05).margin(dda::geometric_tolerance(poly)));
  CHECK(dda::exit_distance(poly, ic.centre) == ic.radius);
  CHECK(check_exit(p, {}) == "");
}

// Found by property "overlap verdict vs exact contact" once its check
// required kOverlapping to come with an intersection polygon (seed
// 20240611, 10,000 cases, after 109): two thin rectangles (aspect
// 1e-3..1e-6) one inside the other at y = 4e7. The separating-axis test
// found an overlap deeper than tol along every axis, while the clipper's
// sliver (thinner than tol) was cleaned to nothing: "overlapping" with no
// polygon to integrate. Fixed in lib/src/overlap.cpp: the verdict is
// kOverlapping only with an IP, else kTouching (one computation).
TEST_CASE("regression: overlapping never comes with an empty intersection polygon", "[regression]") {
  const Points a = {{-2.583680971016094, 39845660.817367658}, {-2.3874520478258803, 39845660.817367658},
                    {-2.3874531654129698, 39845660.817368224}, {-2.5836820886031835, 39845660.817368224}};
  const Points b = {{-2.6098446784298441, 39845660.817367584}, {-2.3612880423889062, 39845660.817367584},
                    {-2.3612894579992196, 39845660.817368299}, {-2.6098460940401571, 39845660.817368299}};
  REQUIRE(is_valid(a));
  REQUIRE(is_valid(b));
  const dda::Polygon pa = to_polygon(a), pb = to_polygon(b);
  dda::Polygon ip;
  const dda::OverlapState s = dda::overlap_and_intersection(pb, pa, dda::pair_tolerance(pa, pb), ip, nullptr);
  CHECK((s == dda::OverlapState::kOverlapping) == (ip.count >= 3));
  CHECK(dda::overlap_state(pb, pa) == s);
  CHECK(check_overlap(a, b) == "");
  CHECK(check_intersection(a, b) == "");
}

// Found by property "IP area, convexity, sandwich and CP/TP symmetry vs
// exact" once it checked Euclidean distances (seed 20240611,
// after 271): a sliver triangle (huge, ~2e4 m) along the edge of another.
// A vertex of IP(TP, CP) lay 12.5 tol from TP, the contact there: within
// tol of both edge lines at TP's sharp corner, tol / sin(theta / 2) from
// the corner. Fixed in lib/src/overlap.cpp (clip_target): the contact's
// corners under 30 degrees are bevelled.
TEST_CASE("regression: IP vertices stay within kIpVertexReach tol of a sharp contact corner", "[regression]") {
  const Points a = {{-13783.342628453845, -12128.338442188669}, {7178.4361848190274, 5705.2974118540869},
                    {-7176.436184819795, -5705.297411853122}};
  const Points b = {{-7176.4361848194112, -5705.2974118536049}, {7178.4361848194112, 5705.2974118536049},
                    {-4325.4860209597837, -3398.2116825478802}};
  REQUIRE(is_valid(a));
  REQUIRE(is_valid(b));
  const dda::Polygon pa = to_polygon(a), pb = to_polygon(b);
  const double tol = dda::pair_tolerance(pa, pb);
  const Points ip = points_of(dda::intersection_polygon(pb, pa));
  for (Vec2 q : ip) CHECK(region_distance(q, b) <= dda::kIpVertexReach * tol);
  CHECK(check_intersection(a, b) == "");
}

// Found by property "exit distance and inscribed circle" with the tiny-block
// family (seed 20240611, after 660): a rectangle 1e-6 m long and
// 1e-12 m wide at x = 8192, where the coordinate spacing is 1.8e-12 m. Every
// triple's centre lies 5e-13 m from a short edge, rounds onto it, and has
// exit distance 0: the radius came back 0 at (0, 0). Fixed in
// lib/src/potential.cpp: the vertex mean (here on the plateau's middle line).
TEST_CASE("regression: inscribed_circle of a rectangle below the coordinate spacing", "[regression]") {
  const Points p = {{8192.0000000000127, -5.0000050000000038e-13}, {8192.0000010000131, -4.9999950000000041e-13},
                    {8192.0000010000131, 5.0000050000000038e-13}, {8192.0000000000127, 4.9999950000000041e-13}};
  REQUIRE(is_valid(p));
  const dda::Polygon poly = to_polygon(p);
  const dda::InscribedCircle ic = dda::inscribed_circle(poly);
  CHECK(ic.radius > 0.0);
  CHECK(dda::locate_point(poly, ic.centre, 0.0) == dda::PointLocation::kInside);
  CHECK(check_exit(p, {}) == "");
}
