#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <cstdint>

#include "dda/contact.hpp"
#include "test_helpers.hpp"

using namespace dda;
using namespace dda::test;

namespace {
Polygon hexagon(Vec2 c, double r, double phase) {
  Vec2 p[6];
  for (int k = 0; k < 6; ++k) p[k] = c + r * Vec2{std::cos(phase + k * M_PI / 3), std::sin(phase + k * M_PI / 3)};
  return make_polygon(p, 6);
}

// A small deterministic generator for the randomised tests.
struct Lcg {
  std::uint64_t state;
  double uniform(double lo, double hi) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return lo + (hi - lo) * static_cast<double>(state >> 11) / 9007199254740992.0;
  }
};

// The shape of a random convex polygon: n_min + [0, n_spread) vertices at
// r_lo r to r from its centre, each angular step 2 pi / n times step_lo to 1.
struct ConvexShape {
  int n_min;
  double n_spread, r_lo, step_lo;
};
constexpr ConvexShape kSmallBlock{3, 6.0, 0.5, 0.6};    // 3 to 8 vertices
constexpr ConvexShape kManySided{9, 8.0, 0.8, 0.8};   // 9 to 16 vertices

// A random convex polygon around c of radius up to r (kSmallBlock: 3 to 8
// vertices, radius 0.5 r to r).
Polygon random_convex(Lcg& rng, Vec2 c, double r, ConvexShape shape = kSmallBlock) {
  const int n = shape.n_min + static_cast<int>(rng.uniform(0.0, shape.n_spread));
  Vec2 p[16];
  REQUIRE(n <= 16);
  double a = rng.uniform(0.0, 6.3);
  for (int k = 0; k < n; ++k) {
    p[k] = c + rng.uniform(shape.r_lo, 1.0) * r * Vec2{std::cos(a), std::sin(a)};
    a += 2.0 * M_PI / n * rng.uniform(shape.step_lo, 1.0);
  }
  return make_polygon(p, n);
}

NormalForce force(const Polygon& cp, const Polygon& tp, Integration rule, double h = 1.0) {
  const PotentialSide a{cp, 1e7 / h, 0.05 * h}, b{tp, 1e7 / h, 0.05 * h};
  const Polygon ip = intersection_polygon(cp, tp);
  return normal_contact_force(a, b, ip, rule, pair_tolerance(cp, tp));
}

// Area form of Eq. 10 by a fine grid: f = int_IP (grad phi_CP - grad phi_TP) dS
// and its moment about the IP centroid, int (x - c) x (.) dS. Independent of
// any boundary segmentation.
void area_form(const Polygon& cp, const Polygon& tp, int n, Vec2& f, double& moment, Vec2 c) {
  const Polygon ip = intersection_polygon(cp, tp);
  const Aabb b = bounds(ip);
  const double dx = (b.hi.x - b.lo.x) / n, dy = (b.hi.y - b.lo.y) / n;
  f = {};
  moment = 0.0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const Vec2 p{b.lo.x + (i + 0.5) * dx, b.lo.y + (j + 0.5) * dy};
      if (locate_point(ip, p, 0.0) != PointLocation::kInside) continue;
      const Vec2 g = potential_gradient(cp, p, 1e7, 1.0) - potential_gradient(tp, p, 1e7, 1.0);
      f += dx * dy * g;
      moment += dx * dy * cross(p - c, g);
    }
}
}  // namespace

TEST_CASE("flat contact: f = 2 kn delta L / H - kn delta^2 / H, normal to the faces", "[contact]") {
  // Both potentials push: kn delta / H on each long side of the delta x L
  // overlap. Within delta of TP's corners its own side edges are nearer,
  // which removes two triangles of potential: kn delta^2 / (2 H) each.
  // Lower square CP, upper TP sunk by delta over its full width.
  const double delta = 1e-3;
  const Polygon cp = rect(0, 0, 1, 1), tp = rect(0.25, 1 - delta, 0.5, 1);
  for (Integration rule : {Integration::kPaperBisector, Integration::kExactEnvelope}) {
    const NormalForce nf = force(cp, tp, rule);
    REQUIRE(nf.valid);
    CHECK(nf.force.y == Approx(-(2e7 * delta * 0.5 - 1e7 * delta * delta)).epsilon(1e-12));  // CP pushed down
    CHECK(std::fabs(nf.force.x) < 1e-9 * std::fabs(nf.force.y));
    CHECK(nf.point.x == Approx(0.5));
  }
}

TEST_CASE("swapping CP and TP gives the same force pair", "[contact]") {
  const Polygon a = hexagon({0, 0}, 1.0, 0.1), b = hexagon({1.5, 0.3}, 0.8, 0.5);
  for (Integration rule : {Integration::kPaperBisector, Integration::kExactEnvelope}) {
    const NormalForce ab = force(a, b, rule), ba = force(b, a, rule);
    REQUIRE(ab.valid);
    REQUIRE(ba.valid);
    CHECK(ab.force.x == Approx(-ba.force.x).epsilon(1e-10));
    CHECK(ab.force.y == Approx(-ba.force.y).epsilon(1e-10));
    CHECK(ab.point.x == Approx(ba.point.x).epsilon(1e-10));
    CHECK(ab.point.y == Approx(ba.point.y).epsilon(1e-10));
  }
}

TEST_CASE("a rotated and translated pair gives the rotated force at the moved point", "[contact]") {
  const Polygon a = hexagon({0, 0}, 1.0, 0.1), b = hexagon({1.5, 0.3}, 0.8, 0.5);
  const double angle = 0.7;
  const Vec2 shift{12.0, -7.0};
  const Polygon a2 = translated(rotated(a, angle, {}), shift), b2 = translated(rotated(b, angle, {}), shift);
  for (Integration rule : {Integration::kPaperBisector, Integration::kExactEnvelope}) {
    const NormalForce f1 = force(a, b, rule), f2 = force(a2, b2, rule);
    const Vec2 rf = rotate(f1.force, angle), rp = rotate(f1.point, angle) + shift;
    CHECK(f2.force.x == Approx(rf.x).epsilon(1e-9));
    CHECK(f2.force.y == Approx(rf.y).epsilon(1e-9));
    CHECK(f2.point.x == Approx(rp.x).epsilon(1e-9));
    CHECK(f2.point.y == Approx(rp.y).epsilon(1e-9));
  }
}

TEST_CASE("exact integration equals a fine area quadrature of Eq. 10", "[contact]") {
  // A rectangle's potential has a ridge along its middle segment that no
  // vertex bisector reaches: the exact option must capture it.
  const Polygon cp = rect(0, 0, 3, 1), tp = hexagon({1.2, 1.25}, 0.6, 0.2);
  const NormalForce nf = force(cp, tp, Integration::kExactEnvelope);
  REQUIRE(nf.valid);
  Vec2 f;
  double m;
  area_form(cp, tp, 1500, f, m, nf.ip_centroid);
  // Midpoint rule with cells cut by the boundary: error ~ 1/N.
  CHECK(length(nf.force - f) < 3e-3 * length(f));
  // Zero moment about pg along the force line: (pg - c) x f = moment.
  CHECK(cross(nf.point - nf.ip_centroid, nf.force) == Approx(m).epsilon(5e-3).margin(1e-6 * length(f)));
}

namespace {
// A 1.6 m x 0.1 m bar CP, tilted 10 deg, inside a 2 m square TP (H = 1 m),
// shifted dx to the right of TP's centre. TP's potential pushes each half
// of the bar toward its nearer side of the square: the two halves' segment
// forces nearly cancel (exactly at dx = 0) and leave a couple.
struct BarInSquare {
  Polygon cp, tp, ip;
  double tol = 0.0;
  explicit BarInSquare(double dx) {
    const Vec2 sq[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
    tp = make_polygon(sq, 4);
    Vec2 b[4] = {{-0.8, -0.05}, {0.8, -0.05}, {0.8, 0.05}, {-0.8, 0.05}};
    for (Vec2& v : b) v = rotate(v, 10.0 * M_PI / 180.0) + Vec2{dx, 0.0};
    cp = make_polygon(b, 4);
    ip = intersection_polygon(cp, tp);
    tol = pair_tolerance(cp, tp);
  }
  NormalForce force(Integration rule, LoadingPoint where) const {
    const PotentialSide a{cp, 1e7, 0.05}, b{tp, 1e7, 0.05};
    return normal_contact_force(a, b, ip, rule, tol, nullptr, where);
  }
};
}  // namespace

TEST_CASE("opposed segment forces: pg stays inside the IP, force and moment unchanged", "[contact]") {
  for (double dx : {0.0, 0.001, 0.01, 0.05}) {
    const BarInSquare bar(dx);
    Vec2 f_ref;
    double m_ref;
    area_form(bar.cp, bar.tp, 1000, f_ref, m_ref, area_centroid(bar.ip).centroid);
    for (Integration rule : {Integration::kPaperBisector, Integration::kExactEnvelope}) {
      CAPTURE(dx, static_cast<int>(rule));
      const NormalForce paper = bar.force(rule, LoadingPoint::kPaper);
      const NormalForce bounded = bar.force(rule, LoadingPoint::kWithinIp);
      REQUIRE(paper.valid);
      REQUIRE(bounded.valid);
      // Negative control: the paper's crossing leaves the 0.1 m thick bar
      // (by 1 m and more: 5.2 m at dx = 1 cm, 4e14 m at dx = 0).
      CHECK(locate_point(bar.ip, paper.point, bar.tol) == PointLocation::kOutside);
      if (dx <= 0.01) CHECK(distance(paper.point, paper.ip_centroid) > 1.0);
      CHECK(paper.couple == 0.0);
      // The bounded point is in the IP (on its boundary: where the
      // auxiliary line leaves it).
      CHECK(locate_point(bar.ip, bounded.point, bar.tol) != PointLocation::kOutside);
      // The same force, and the same moment about the IP centroid: the part
      // the force at pg does not carry is the couple.
      CHECK(bounded.force == paper.force);
      CHECK(bounded.moment == paper.moment);
      const double carried = cross(bounded.point - bounded.ip_centroid, bounded.force);
      CHECK(carried + bounded.couple == Approx(paper.moment).epsilon(1e-12));
      CHECK(std::fabs(bounded.couple) > 0.5 * std::fabs(paper.moment));
      // And that moment is Eq. 10's (area quadrature, error ~ 1/N).
      CHECK(paper.moment == Approx(m_ref).epsilon(5e-3));
    }
  }
}

TEST_CASE("a loading point inside the IP is the paper's, to the bit", "[contact]") {
  const Polygon a = hexagon({0, 0}, 1.0, 0.1), b = hexagon({1.5, 0.3}, 0.8, 0.5);
  const PotentialSide sa{a, 1e7, 0.05}, sb{b, 1e7, 0.05};
  const Polygon ip = intersection_polygon(a, b);
  for (Integration rule : {Integration::kPaperBisector, Integration::kExactEnvelope}) {
    const NormalForce paper = normal_contact_force(sa, sb, ip, rule, pair_tolerance(a, b), nullptr, LoadingPoint::kPaper);
    const NormalForce bounded = normal_contact_force(sa, sb, ip, rule, pair_tolerance(a, b), nullptr, LoadingPoint::kWithinIp);
    REQUIRE(locate_point(ip, paper.point, 0.0) == PointLocation::kInside);
    CHECK(bounded.point == paper.point);
    CHECK(bounded.force == paper.force);
    CHECK(bounded.couple == 0.0);
  }
}

TEST_CASE("contact energy is the potential of the force: -dE/dx = f", "[contact]") {
  const Polygon tp = rect(0, 0, 3, 1), cp0 = hexagon({1.2, 1.3}, 0.6, 0.2);
  const PotentialSide st{tp, 1e7, 0.0};
  auto energy = [&](Vec2 u) {
    const Polygon cp = translated(cp0, u);
    const PotentialSide sc{cp, 1e7, 0.0};
    return contact_energy(sc, st, intersection_polygon(cp, tp), 1e-12);
  };
  const double h = 1e-6;
  const Vec2 grad{(energy({h, 0}) - energy({-h, 0})) / (2 * h), (energy({0, h}) - energy({0, -h})) / (2 * h)};
  const NormalForce nf = force(cp0, tp, Integration::kExactEnvelope);
  // Central difference with h = 1e-6 m: truncation ~h^2, round-off ~eps E / h.
  CHECK(length(grad + nf.force) < 1e-5 * length(nf.force));
}

TEST_CASE("edge sources from the fused overlap call change the force only by round-off", "[contact]") {
  // With sources the potentials that vanish on an IP edge or vertex are set
  // to zero, not evaluated: on random overlapping pairs (shallow and deep,
  // near-parallel faces included) force and loading point match the plain
  // call to round-off of the force scale. With sources, an edge on which
  // one edge line (or two adjacent ones) of the other polygon is nearest
  // all along is integrated as one (two) trapezoids, no more segments than
  // the plain call's demarcation points give; most pairs have such edges.
  Lcg rng{12345};
  auto uniform = [&rng](double lo, double hi) { return rng.uniform(lo, hi); };
  auto random_polygon = [&rng](Vec2 c, double r) { return random_convex(rng, c, r); };
  // Stacked parallelograms (joint faces): TP sunk by up to 1e-3 into CP's
  // top face, turned by up to 1e-3 rad, shifted along it.
  auto stacked = [&](Polygon& cp, Polygon& tp) {
    const double w = uniform(0.5, 2.0), h = uniform(0.3, 1.0), skew = uniform(-0.5, 0.5);
    const Vec2 p[4] = {{0, 0}, {w, 0}, {w + skew, h}, {skew, h}};
    cp = make_polygon(p, 4);
    const Vec2 q[4] = {{0, 0}, {w, 0}, {w + skew, h}, {skew, h}};
    tp = rotated(translated(make_polygon(q, 4), {uniform(-0.5 * w, 0.5 * w), h - uniform(0.0, 1e-3)}),
                 uniform(-1e-3, 1e-3), {0.5 * w, h});
  };
  int compared = 0, fewer = 0;
  for (int trial = 0; trial < 3000; ++trial) {
    Polygon cp = random_polygon({0, 0}, 1.0);
    Polygon tp = random_polygon({uniform(-1.8, 1.8), uniform(-1.8, 1.8)}, uniform(0.3, 1.5));
    if (trial % 2) stacked(cp, tp);
    if (!validate_polygon(cp.v.data(), cp.count).ok() || !validate_polygon(tp.v.data(), tp.count).ok()) continue;
    const double tol = pair_tolerance(cp, tp);
    Polygon ip;
    std::array<IpEdge, kMaxVertices> src;
    if (overlap_and_intersection(cp, tp, tol, ip, src.data()) != OverlapState::kOverlapping || ip.count < 3) continue;
    for (Integration rule : {Integration::kPaperBisector, Integration::kExactEnvelope}) {
      const PotentialSide a{cp, 1e7, 0.3}, b{tp, 2e7, 0.3};
      const NormalForce plain = normal_contact_force(a, b, ip, rule, tol);
      const NormalForce fused = normal_contact_force(a, b, ip, rule, tol, src.data());
      REQUIRE(plain.valid == fused.valid);
      if (!plain.valid) continue;
      const double scale = length(plain.force);
      CHECK(length(fused.force - plain.force) <= 1e-12 * scale);
      // The loading point moves by round-off of the moment over the force.
      CHECK(length(fused.point - plain.point) <= 1e-9 * (1.0 + length(plain.point)));
      CHECK(fused.segments <= plain.segments);
      if (rule == Integration::kPaperBisector && fused.segments < plain.segments) ++fewer;
      ++compared;
    }
  }
  CHECK(compared > 1500);
  CHECK(fewer > compared / 4);
}

TEST_CASE("edges nearest to one or two lines of a polygon beyond eight vertices: the plain call's force", "[contact]") {
  // The edge kernel with the vertex count read at run time (9 to 16
  // vertices): with sources, the edges on which one line, or two adjacent
  // lines, of the other polygon are nearest all along are integrated as one
  // or two trapezoids; force and loading point match the plain call (every
  // demarcation point) to round-off of the force scale, with fewer segments
  // on some pairs.
  Lcg rng{4242};
  auto polygon = [&rng](Vec2 c, double r) { return random_convex(rng, c, r, kManySided); };
  int compared = 0, fewer = 0;
  for (int trial = 0; trial < 4000; ++trial) {
    const Polygon cp = polygon({0, 0}, 1.0);
    const Polygon tp = polygon({rng.uniform(-1.6, 1.6), rng.uniform(-1.6, 1.6)}, rng.uniform(0.3, 1.5));
    if (!validate_polygon(cp.v.data(), cp.count).ok() || !validate_polygon(tp.v.data(), tp.count).ok()) continue;
    const double tol = pair_tolerance(cp, tp);
    Polygon ip;
    std::array<IpEdge, kMaxVertices> src;
    if (overlap_and_intersection(cp, tp, tol, ip, src.data()) != OverlapState::kOverlapping || ip.count < 3) continue;
    const PotentialSide a{cp, 1e7, 0.01}, b{tp, 2e7, 0.01};
    const NormalForce plain = normal_contact_force(a, b, ip, Integration::kPaperBisector, tol);
    const NormalForce fused = normal_contact_force(a, b, ip, Integration::kPaperBisector, tol, src.data());
    REQUIRE(plain.valid == fused.valid);
    if (!plain.valid) continue;
    CHECK(length(fused.force - plain.force) <= 1e-12 * length(plain.force));
    CHECK(length(fused.point - plain.point) <= 1e-9 * (1.0 + length(plain.point)));
    CHECK(fused.segments <= plain.segments);
    if (fused.segments < plain.segments) ++fewer;
    ++compared;
  }
  CHECK(compared > 300);
  CHECK(fewer > compared / 4);
}

TEST_CASE("vertex rays: the paired crossing test gives the general one's bits", "[contact]") {
  // With no small edge, bisectors() gives exactly the n vertex rays (lines
  // i - 1 and i, d0 = 0), and the force kernel tests them two at a time;
  // any other ray count takes the general per-ray test. The same rays with
  // one repeated (a repeated crossing adds no segment) must give the same
  // force, point and segments to the bit (without sources: every edge
  // meets its rays; with sources an edge nearest to two adjacent lines
  // takes their vertex ray's crossing without testing the others when the
  // rays are the n vertex rays, so the general test's round-off and its
  // count of segments may differ). Also: bisectors() gives n rays
  // only as the vertex rays, in order, in both small-edge modes.
  Lcg rng{777};
  int compared = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const Polygon cp = random_convex(rng, {0, 0}, 1.0);
    const Polygon tp = random_convex(rng, {rng.uniform(-1.5, 1.5), rng.uniform(-1.5, 1.5)}, rng.uniform(0.3, 1.5));
    if (!validate_polygon(cp.v.data(), cp.count).ok() || !validate_polygon(tp.v.data(), tp.count).ok()) continue;
    for (const Polygon* p : {&cp, &tp})
      for (SmallEdgeRays mode : {SmallEdgeRays::kVirtualAndVertex, SmallEdgeRays::kVirtualReplacesVertex}) {
        BisectorSet set;
        set.count = bisectors(*p, 0.3, mode, set.b.data());
        if (set.count != p->count) continue;
        for (int i = 0; i < p->count; ++i) {
          CHECK(set.b[static_cast<std::size_t>(i)].line_a == p->prev(i));
          CHECK(set.b[static_cast<std::size_t>(i)].line_b == i);
          CHECK(set.b[static_cast<std::size_t>(i)].d0 == 0.0);
        }
      }
    const double tol = pair_tolerance(cp, tp);
    Polygon ip;
    std::array<IpEdge, kMaxVertices> src;
    if (overlap_and_intersection(cp, tp, tol, ip, src.data()) != OverlapState::kOverlapping || ip.count < 3) continue;
    BisectorSet rays_cp, rays_tp;
    rays_cp.count = bisectors(cp, 1e-9, SmallEdgeRays::kVirtualAndVertex, rays_cp.b.data());
    rays_tp.count = bisectors(tp, 1e-9, SmallEdgeRays::kVirtualAndVertex, rays_tp.b.data());
    REQUIRE(rays_cp.count == cp.count);
    REQUIRE(rays_tp.count == tp.count);
    const PotentialSide a{cp, 1e7, 1e-9, SmallEdgeRays::kVirtualAndVertex, rays_cp.count, rays_cp.b.data()};
    const PotentialSide b{tp, 2e7, 1e-9, SmallEdgeRays::kVirtualAndVertex, rays_tp.count, rays_tp.b.data()};
    // The same rays, the first one twice: n + 1 rays, the general test.
    BisectorSet more_cp = rays_cp, more_tp = rays_tp;
    more_cp.b[static_cast<std::size_t>(more_cp.count++)] = rays_cp.b[0];
    more_tp.b[static_cast<std::size_t>(more_tp.count++)] = rays_tp.b[0];
    const PotentialSide a1{cp, 1e7, 1e-9, SmallEdgeRays::kVirtualAndVertex, more_cp.count, more_cp.b.data()};
    const PotentialSide b1{tp, 2e7, 1e-9, SmallEdgeRays::kVirtualAndVertex, more_tp.count, more_tp.b.data()};
    for (const IpEdge* sources : {static_cast<const IpEdge*>(nullptr), static_cast<const IpEdge*>(src.data())}) {
      const NormalForce paired = normal_contact_force(a, b, ip, Integration::kPaperBisector, tol, sources);
      const NormalForce general = normal_contact_force(a1, b1, ip, Integration::kPaperBisector, tol, sources);
      REQUIRE(paired.valid == general.valid);
      if (!paired.valid) continue;
      if (!sources) {
        CHECK(paired.force == general.force);
        CHECK(paired.point == general.point);
        CHECK(paired.segments == general.segments);
      } else {
        CHECK(length(paired.force - general.force) <= 1e-12 * length(general.force));
        CHECK(length(paired.point - general.point) <= 1e-9 * (1.0 + length(general.point)));
        CHECK(paired.segments <= general.segments);
      }
      ++compared;
    }
  }
  CHECK(compared > 500);
}
