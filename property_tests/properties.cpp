// rapidcheck properties of the geometry kernel (lib/include/dda/{polygon,
// overlap,potential}.hpp) against CGAL's exact kernel. Each property draws
// inputs from generators.hpp (random and degenerate families), discards the
// rare input validate_polygon rejects, and runs one check of checks.hpp;
// tolerances and the touching band are in tolerances.hpp.
//
// Case count and seed come from RC_PARAMS: ctest sets a fixed seed and
// 10,000 cases per property (CMakeLists.txt); property_fuzz sets FUZZ_CASES
// cases and a random seed. Tags: [property] plus one group tag per test case,
// which is how ctest and property_fuzz select them.
#include <rapidcheck/catch.h>

#include <string>

#include "checks.hpp"
#include "dda/potential.hpp"
#include "generators.hpp"

using namespace prop;

namespace {

// The generator family (first word) tags every case, so that rapidcheck
// prints how often each family ran.
std::string family_tag(const std::string& family) { return family.substr(0, family.find(' ')); }

void pass(const std::string& failure) {
  if (!failure.empty()) RC_FAIL(failure);
}

}  // namespace

TEST_CASE("overlap_state equals the exact interiors-overlap test outside the touching band", "[property][overlap]") {
  rc::prop("overlap verdict vs exact contact", [] {
    const PairCase c = *gen::polygon_pair();
    RC_PRE(is_valid(c.a) && is_valid(c.b));
    std::string contact;
    const std::string failure = check_overlap(c.a, c.b, &contact);
    RC_TAG(family_tag(c.family), contact);
    pass(failure);
  });
}

TEST_CASE("entrance_block equals the exact Minkowski sum B + (-A) + a0", "[property][entrance]") {
  rc::prop("entrance block vs exact Minkowski difference", [] {
    const PairCase c = *gen::polygon_pair();
    RC_PRE(is_valid(c.a) && is_valid(c.b));
    Vec2 a0{};
    switch (*gen::index(0, 4)) {
      case 0:  // what overlap_state uses: the vertex mean of A
        for (Vec2 v : c.a) a0 += v;
        a0 = a0 / static_cast<double>(c.a.size());
        break;
      case 1: a0 = c.a[static_cast<std::size_t>(*gen::index(0, static_cast<int>(c.a.size())))]; break;
      case 2: a0 = {0.0, 0.0}; break;
      default: a0 = (*gen::sample_points(c.a, c.a[0], 1)).v[0];
    }
    RC_TAG(family_tag(c.family));
    pass(check_entrance(c.a, c.b, a0));
  });
}

TEST_CASE("intersection_polygon equals the exact intersection, in either order", "[property][intersection]") {
  rc::prop("IP area, convexity, sandwich and CP/TP symmetry vs exact", [] {
    const PairCase c = *gen::polygon_pair();
    RC_PRE(is_valid(c.a) && is_valid(c.b));
    RC_TAG(family_tag(c.family));
    pass(check_intersection(c.a, c.b));
  });
}

TEST_CASE("intersection_polygon moves with a rigid motion of both inputs", "[property][motion]") {
  rc::prop("IP of moved inputs equals the moved IP", [] {
    const PairCase c = *gen::polygon_pair();
    RC_PRE(is_valid(c.a) && is_valid(c.b));
    const Motion m = *gen::rigid_motion(c.a);
    RC_PRE(is_valid(transformed(c.a, m)) && is_valid(transformed(c.b, m)));
    RC_TAG(family_tag(c.family));
    pass(check_motion(c.a, c.b, m));
  });
}

TEST_CASE("area_moments equal the exact moments of the same vertices", "[property][moments]") {
  rc::prop("area, centroid, sxx, syy, sxy vs exact", [] {
    const PolygonCase c = *gen::polygon();
    RC_PRE(is_valid(c.v));
    RC_TAG(family_tag(c.family));
    pass(check_moments(c.v));
  });
}

TEST_CASE("split_polygon conserves area and cuts like the exact half-planes", "[property][split]") {
  rc::prop("split parts vs exact half-plane cuts", [] {
    const PolygonCase c = *gen::polygon();
    RC_PRE(is_valid(c.v));
    const LineCase line = *gen::cutting_line(c.v);
    RC_TAG(family_tag(line.family));
    pass(check_split(c.v, line));
  });
}

TEST_CASE("exit_distance, locate_point, potential_gradient and inscribed_circle vs exact", "[property][potential]") {
  rc::prop("exit distance and inscribed circle", [] {
    const PolygonCase c = *gen::polygon();
    RC_PRE(is_valid(c.v));
    const Vec2 centre = dda::inscribed_circle(to_polygon(c.v)).centre;
    const Samples samples = *gen::sample_points(c.v, centre, 6);
    RC_TAG(family_tag(c.family));
    pass(check_exit(c.v, samples.v));
  });
}
