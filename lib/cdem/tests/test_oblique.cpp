// Oblique impacts of two CST-meshed 1 m squares with the two-scale contact
// (Paper B Sects. 3-5): every node that crosses the other block within a
// step is found (also after a release in the same step), a node found deep
// inside stops the run with a ContactError, and the impacts bounce: no
// pass-through, kinetic energy never above its initial value, the blocks
// separate, and the loss stays within Eq. 5's bound for the two blocks.
#include <catch2/catch.hpp>
#include <algorithm>
#include <cmath>

#include "dda/cdem/model.hpp"

using dda::Vec2;
using namespace dda::cdem;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kSide = 1.0;       // m, the squares' side
constexpr double kDensity = 2000.0;  // kg/m^3
// Relative slack on energy comparisons: round-off of sums of ~1e3 terms.
constexpr double kEnergySlack = 1e-9;

std::vector<Vec2> square(double x0, double y0) {
  return {{x0, y0}, {x0 + kSide, y0}, {x0 + kSide, y0 + kSide}, {x0, y0 + kSide}};
}

// A (left) moving with `velocity` onto B at rest, faces `gap` apart.
CdemScene oblique(Vec2 velocity, double tan_phi, bool subdivision, double gap = 0.05,
                  SubdivisionMode mode = SubdivisionMode::kInPlace) {
  CdemScene s;
  s.materials = {{kDensity, 1e9, 0.25}};
  s.dt = 1e-4;
  CdemBlock a, b;
  a.outline = square(-kSide - gap, -0.5);
  a.divisions = 2;
  a.velocity = velocity;
  b.outline = square(0.0, -0.5);
  b.divisions = 2;
  s.blocks = {a, b};
  s.options.subdivision = subdivision;
  s.options.subdivision_mode = mode;  // the in-place refinement under test unless told otherwise
  s.options.strength.friction_deg = std::atan(tan_phi) * 180.0 / kPi;
  return s;
}

// Area of the intersection of two convex CCW polygons (Sutherland-Hodgman).
double overlap_area(std::vector<Vec2> p, const std::vector<Vec2>& clip) {
  for (std::size_t i = 0; i < clip.size() && !p.empty(); ++i) {
    const Vec2 a = clip[i], b = clip[(i + 1) % clip.size()];
    auto side = [&](Vec2 q) { return dda::cross(b - a, q - a); };
    std::vector<Vec2> out;
    for (std::size_t j = 0; j < p.size(); ++j) {
      const Vec2 c = p[j], d = p[(j + 1) % p.size()];
      const double sc = side(c), sd = side(d);
      if (sc >= 0.0) out.push_back(c);
      if ((sc >= 0.0) != (sd >= 0.0)) out.push_back(c + (sc / (sc - sd)) * (d - c));
    }
    p.swap(out);
  }
  double a2 = 0.0;
  for (std::size_t i = 0; i < p.size(); ++i) a2 += dda::cross(p[i], p[(i + 1) % p.size()]);
  return 0.5 * a2;
}

struct ImpactResult {
  double min_centroid_dx = 1e300;  // B's centroid x minus A's, m
  double max_overlap = 0.0;        // m^2
  double ke0 = 0.0, max_ke = 0.0, max_total = 0.0;
  double loss = 0.0;               // initial minus final kinetic + strain, J/m
  double bound_normal = 0.0;       // Eq. 5 for the blocks, normal relative velocity, J/m
  double bound_full = 0.0;         // Eq. 5 for the blocks, full relative velocity, J/m
  bool separated = false;          // no clone left and B moving away from A
  std::size_t touches = 0;
  std::size_t submodels = 0;       // sub-models built (SubdivisionMode::kSubModel)
};

// Runs until `t_end`, checking every step.
ImpactResult run_impact(const CdemScene& s, double t_end) {
  Model m(s);
  ImpactResult r;
  r.ke0 = m.energy().kinetic;
  r.max_ke = r.ke0;
  r.max_total = m.energy().kinetic + m.energy().strain;
  const double mass = kDensity * kSide * kSide, mu = 0.5 * mass;  // reduced mass of the two blocks
  const Vec2 v = s.blocks[0].velocity;
  r.bound_normal = 0.5 * mu * v.x * v.x;
  r.bound_full = 0.5 * mu * dda::length_squared(v);
  while (m.time() < t_end - 1e-12) {
    m.step();
    const CdemEnergy e = m.energy();
    r.max_ke = std::max(r.max_ke, e.kinetic);
    r.max_total = std::max(r.max_total, e.kinetic + e.strain);
    r.min_centroid_dx = std::min(r.min_centroid_dx, m.block_mean_position(1).x - m.block_mean_position(0).x);
    r.max_overlap = std::max(r.max_overlap, overlap_area(m.block_outline(0), m.block_outline(1)));
  }
  const CdemEnergy e = m.energy();
  r.loss = r.ke0 - (e.kinetic + e.strain);
  r.separated = m.clones().empty() && m.block_velocity(1).x > m.block_velocity(0).x;
  r.touches = m.touches().size();
  r.submodels = m.submodels().size();
  return r;
}

void check_bounce(const ImpactResult& r, double bound) {
  INFO("min centroid dx " << r.min_centroid_dx << " max overlap " << r.max_overlap << " KE0 " << r.ke0 << " max KE "
                          << r.max_ke << " max KE+strain " << r.max_total << " loss " << r.loss << " bound " << bound
                          << " touches " << r.touches);
  // No pass-through: the run finished (a node deeper than d_tol inside the
  // other block throws ContactError) and the centres stay about a side apart
  // (the outline of corners overlaps by the impact's compression, ~v/c).
  CHECK(r.min_centroid_dx > 0.9 * kSide);
  CHECK(r.max_ke <= r.ke0 * (1.0 + kEnergySlack));
  CHECK(r.max_total <= r.ke0 * (1.0 + kEnergySlack));
  CHECK(r.separated);
  CHECK(r.loss >= -kEnergySlack * r.ke0);
  CHECK(r.loss <= bound);
}

}  // namespace

TEST_CASE("oblique impact at (5, 2) m/s with phi = 0 and subdivision bounces", "[cdem][oblique]") {
  // Before the fix: ~200 touch/release cycles, A passed through B keeping
  // 4.13 m/s against B's 0.87 (centres 0.87 m apart at 0.05 s) and the run
  // ended normally.
  const CdemScene s = oblique({5.0, 2.0}, 0.0, true);
  const ImpactResult r = run_impact(s, 0.05);
  check_bounce(r, r.bound_normal);
}

TEST_CASE("oblique impact at (1, 0.8) m/s with phi = 0 and subdivision bounces", "[cdem][oblique]") {
  // Before the fix: ~2000 touch/release cycles and the squares stuck,
  // moving on together at about 0.5 m/s, losing 814 J/m (Eq. 5 bound 500).
  const CdemScene s = oblique({1.0, 0.8}, 0.0, true);
  const ImpactResult r = run_impact(s, 0.08);
  check_bounce(r, r.bound_normal);
}

TEST_CASE("the two oblique impacts bounce with the paper's sub-model (the default) too", "[cdem][oblique]") {
  // Sect. 5 as written: the contact stays at the coarse nodes, so the loss
  // is bounded by the blocks' Eq. 5 as without subdivision.
  for (Vec2 v : {Vec2{5.0, 2.0}, Vec2{1.0, 0.8}}) {
    INFO("velocity (" << v.x << ", " << v.y << ") m/s");
    const CdemScene s = oblique(v, 0.0, true, 0.05, CdemOptions{}.subdivision_mode);
    REQUIRE(s.options.subdivision_mode == SubdivisionMode::kSubModel);
    const ImpactResult r = run_impact(s, v.x > 2.0 ? 0.05 : 0.08);
    CHECK(r.submodels > 0);  // the sub-model was built, not just the coarse clone
    check_bounce(r, r.bound_normal);
  }
}

TEST_CASE("a node deeper than d_tol inside another block stops the run with a ContactError", "[cdem][oblique]") {
  // Negative control of the depth check: A starts 2 d_tol inside B (an
  // overlap no step can resolve); within d_tol it is a touch at s = 0.
  for (double depth_in_tol : {2.0, 0.5}) {
    CdemScene s = oblique({1.0, 0.0}, 0.0, true);
    const double depth = depth_in_tol * s.options.tolerance;
    s.blocks[0].outline = square(-kSide + depth, -0.5);
    Model m(s);
    INFO("depth " << depth);
    if (depth_in_tol > 1.0) {
      try {
        m.step();
        FAIL("no ContactError");
      } catch (const ContactError& e) {
        CHECK(e.depth == Approx(depth).epsilon(1e-9));
        CHECK(e.step == 1);
        CHECK(e.block != e.other_block);
        CHECK(e.reason == dda::StopReason::kPenetration);  // callers classify by the reason, not the text
        CHECK_THAT(std::string(e.what()), Catch::Contains("node " + std::to_string(e.node)) &&
                                              Catch::Contains("inside block") && Catch::Contains("step 1"));
      }
    } else {
      CHECK_NOTHROW(m.step());
      CHECK_FALSE(m.touches().empty());
    }
  }
}

TEST_CASE("impact sweep: no pass-through, no energy growth", "[cdem][oblique]") {
  // Angle of A's velocity from the face normal, speed, friction tan(phi),
  // subdivision on/off. The loss bound is Eq. 5 for the two blocks with the
  // full relative velocity (a perfectly inelastic impact of the blocks): the
  // touches' Eq. 4 impacts take the contact nodes' tangential relative
  // velocity too, so with phi = 0 the loss may exceed the normal-only value
  // (measured at 60 deg, 10 m/s with subdivision: 14.2 kJ/m against 12.5).
  for (double angle_deg : {0.0, 30.0, 60.0})
    for (double speed : {0.5, 10.0})
      for (double tan_phi : {0.0, 0.3})
        for (bool sub : {false, true}) {
          const double a = angle_deg * kPi / 180.0;
          const Vec2 v{speed * std::cos(a), speed * std::sin(a)};
          const double gap = 0.01;
          const CdemScene s = oblique(v, tan_phi, sub, gap);
          INFO("angle " << angle_deg << " speed " << speed << " tan(phi) " << tan_phi << " subdivision " << sub);
          const ImpactResult r = run_impact(s, gap / v.x + 0.012);
          check_bounce(r, r.bound_full);
        }
}
