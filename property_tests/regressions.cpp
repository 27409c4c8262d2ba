// Regression tests: every counterexample the properties found, saved with its
// exact inputs (17 significant digits round-trip every double) and run
// through the same checks as the properties (checks.hpp), plus the specific
// symptom of the bug it exposed. One TEST_CASE per failure found; the name
// says which kernel function failed and why.
#include <catch2/catch.hpp>

#include "checks.hpp"
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
