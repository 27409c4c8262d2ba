// Shared by the pair benchmarks against Box2D (bench_pair_cost,
// bench_pair_instructions): the same random polygon pairs, each polygon with
// what both libraries precompute per body and step. The bisectors of each
// polygon (Sect. 3.2.3) and its geometric tolerance are built once, as the
// simulation builds them once per block and step (update_block_geometry:
// sides_[i].tol, the bisector store) and takes the pair's tolerance as the
// larger of the two (pair_forces), its sharp corners (the clipper's
// bevels when it is the contact polygon), as the simulation finds them
// once per block and step (sharp_corners_), and its edge lines
// (dda::support_lines, what the overlap test reads of each polygon); Box2D's
// shapes likewise carry their normals.
#pragma once
#include <box2d/b2_collision.h>
#include <box2d/b2_polygon_shape.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "dda/overlap.hpp"
#include "dda/polygon.hpp"
#include "dda/potential.hpp"
#include "pair_bench.hpp"

namespace bench {

inline constexpr std::size_t kPairs = 1024;         // power of two: index with a mask
inline constexpr double kKn = 1e9;                  // Pa: a rock joint's penalty (Sect. 6)
inline constexpr double kH = 1.0;                   // m: H of Eq. 12 for blocks of this size
inline constexpr double kSmallEdgeFraction = 0.05;  // of H: the library's default (ContactParams)

inline b2PolygonShape to_box2d(const dda::Polygon& p) {
  std::array<b2Vec2, b2_maxPolygonVertices> v{};
  for (int k = 0; k < p.count; ++k)
    v[static_cast<std::size_t>(k)] = b2Vec2(static_cast<float>(p.v[k].x), static_cast<float>(p.v[k].y));
  b2PolygonShape s;
  s.Set(v.data(), p.count);
  return s;
}

// One polygon with what both libraries precompute per body and step.
struct Side {
  dda::Polygon poly;
  std::vector<dda::Bisector> bisectors;
  dda::PotentialSide side;
  double tol = 0.0;  // geometric_tolerance(poly), m
  std::uint32_t sharp = 0;  // dda::sharp_corners(poly)
  dda::SupportLines lines;     // dda::support_lines(poly)
  b2PolygonShape b2;
};

inline Side make_side(const dda::Polygon& p) {
  Side s;
  s.poly = p;
  s.bisectors.resize(2 * dda::kMaxVertices);
  const double small = kSmallEdgeFraction * kH;
  const int nb = dda::bisectors(p, small, dda::SmallEdgeRays::kVirtualAndVertex, s.bisectors.data());
  s.side.kn_over_h = kKn / kH;
  s.side.small_edge = small;
  s.side.bisector_count = nb;
  s.tol = dda::geometric_tolerance(p);
  s.sharp = dda::sharp_corners(p);
  dda::support_lines(p, s.lines);
  s.b2 = to_box2d(p);
  return s;
}

struct Pair {
  Side a, b;
  // pair_tolerance(a, b), as the simulation's pair loop takes it from the
  // blocks' stored tolerances.
  double tol() const { return std::max(a.tol, b.tol); }
};

inline bool boxes_overlap(const dda::Polygon& a, const dda::Polygon& b) {
  const dda::Aabb x = dda::bounds(a), y = dda::bounds(b);
  return x.lo.x <= y.hi.x && y.lo.x <= x.hi.x && x.lo.y <= y.hi.y && y.lo.y <= x.hi.y;
}

// kPairs pairs of n-gons into `v` (emptied first), overlapping or separated
// with overlapping boxes; deterministic for a given (n, kind). The
// PotentialSide pointers are set after the vector stops growing, so `v`
// must not grow or move afterwards.
inline void fill_pairs(int n, bool overlapping, std::vector<Pair>& v) {
  v.clear();
  std::mt19937_64 rng(0x5eed0000u + static_cast<unsigned>(n) + (overlapping ? 0u : 100u));
  std::uniform_real_distribution<double> u(0.0, 1.0);
  while (v.size() < kPairs) {
    const dda::Polygon a = random_convex(n, rng);
    const double ang = 2 * kPi * u(rng), dist = (overlapping ? 1.2 : 2.0) * u(rng);
    const dda::Polygon b = dda::translated(random_convex(n, rng), {dist * std::cos(ang), dist * std::sin(ang)});
    const dda::OverlapState s = dda::overlap_state(a, b);
    const bool keep = overlapping ? s == dda::OverlapState::kOverlapping
                                  : s == dda::OverlapState::kSeparate && boxes_overlap(a, b);
    if (keep) v.push_back({make_side(a), make_side(b)});
  }
  for (Pair& p : v)
    for (Side* s : {&p.a, &p.b}) {
      s->side.poly = s->poly;
      s->side.bisectors = s->bisectors.data();
    }
}

}  // namespace bench
