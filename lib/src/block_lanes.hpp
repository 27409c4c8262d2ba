// Internal: the block kinematics of block.hpp (T(p) d and T(p)^T f, Eqs. 1-3
// and 22-23) lane by lane, for the per-vertex moves (block.cpp), the
// friction history and the per-block force sums (simulation/). Each
// element is computed with the scalar formula's operations in its order:
// the same bits. Not part of the public API.
#pragma once
#include <algorithm>

#include "dda/block.hpp"
#include "lanes.hpp"

namespace dda::detail {

// point_displacement(centroid, p, d) as (u, v): with t = (xt, yt) and
// s = (yt, xt),
//   (u, v) = (((d0, d1) + s (-d2, d2)) + t (d3, d4)) + (0.5 s) d5
// (d0 + yt (-d2) is d0 - yt d2 exactly).
inline Lanes point_displacement_lanes(Lanes centroid, Lanes p, const Vec6& d) {
  const Lanes t = p - centroid, s = swapped(t);
  return Lanes{d[0], d[1]} + s * Lanes{-d[2], d[2]} + t * Lanes{d[3], d[4]} + Lanes{0.5, 0.5} * s * Lanes{d[5], d[5]};
}

// displace_vertices for kN vertices (0: poly.count): each vertex moved by
// point_displacement_lanes, and the largest motion squared.
template <int kN>
[[gnu::always_inline]] inline double displace_n(const PolygonSpan& poly, Vec2 centroid, const Vec6& d) {
  const int count = kN ? kN : poly.count;
  const Lanes c = lanes(centroid);
  const Vec6 dd = d;  // a local copy: the vertex stores cannot alias it, its lanes stay in registers
  double motion2 = 0.0;
  for (int k = 0; k < count; ++k) {
    const Lanes p = lanes(poly.v[static_cast<std::size_t>(k)]);
    const Lanes u = point_displacement_lanes(c, p, dd);
    poly.v[static_cast<std::size_t>(k)] = vec2(p + u);
    const Lanes u2 = u * u;
    motion2 = std::max(motion2, u2[0] + u2[1]);
  }
  return motion2;
}

// displace_vertices inline (the per-block move, no call per block and
// step): the loops of triangles to pentagons unrolled.
[[gnu::always_inline]] inline double displace_polygon(const PolygonSpan& poly, Vec2 centroid, const Vec6& d) {
  switch (poly.count) {
    case 4: return displace_n<4>(poly, centroid, d);
    case 5: return displace_n<5>(poly, centroid, d);
    case 3: return displace_n<3>(poly, centroid, d);
    default: return displace_n<0>(poly, centroid, d);
  }
}

// A Vec6 as three lane pairs (g0, g1), (g2, g3), (g4, g5).
struct Lanes6 {
  Lanes g01, g23, g45;
};

// point_load(c, p, f): with t = (xt, yt), P = (yt, xt) * f and Q = t * f,
// T(p)^T f = (f, (P1 - P0, Q0), (Q1, 0.5 (P0 + P1))) (-yt fx + xt fy is
// xt fy - yt fx exactly).
inline Lanes6 point_load_lanes(Lanes c, Vec2 p, Vec2 f) {
  const Lanes t = lanes(p) - c, fl = lanes(f);
  const Lanes pl = swapped(t) * fl, q = t * fl;
  const Lanes ps = swapped(pl);
  const Lanes d = ps - pl, h = Lanes{0.5, 0.5} * (pl + ps);
  return {fl, low_lanes(d, q), Lanes{q[1], h[0]}};
}

}  // namespace dda::detail
