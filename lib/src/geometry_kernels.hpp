// Internal: the per-block geometry kernels of polygon.cpp (the normals,
// area moments, box and support lines of a moved block), inline for the
// simulation's block loop (integration.cpp) as for polygon.cpp's
// functions: the same bits wherever they run. Not part of the public API.
#pragma once
#include <algorithm>
#include <cfloat>
#include <cstdint>

#include "dda/overlap.hpp"
#include "dda/polygon.hpp"
#include "lanes.hpp"
#include "support_kernels.hpp"

namespace dda::detail {

// update_normals two edges at a time (lane 0 edge i, lane 1 edge i + 1; an
// odd count's last edge in both), lane by lane the same operations as one
// edge at a time; returns the smallest squared edge length of each lane
// (lane_min skips a NaN as std::min(m, l2) does; squares are never -0, so
// the two lanes' minima combine to the minimum over all edges whatever the
// order). kN: the vertex count when known at compile time (0: poly.count),
// so that a quadrilateral's loop is unrolled. support (optional): also
// writes support_lines()' pairs (Eq. 9's edge lines: lane by lane the
// normals just made and n . v of the edges' start vertices, as
// support_lines computes them from the stored normals: the same bits).
template <int kN>
[[gnu::always_inline]] inline Lanes edge_normals(const PolygonSpan& poly, SupportLines::Pair* support = nullptr) {
  using detail::high_lanes;
  using detail::lanes;
  using detail::low_lanes;
  const int count = kN ? kN : poly.count;
  const auto edge = [&](int i) { return lanes(poly.v[i + 1 == count ? 0 : i + 1]) - lanes(poly.v[i]); };
  Lanes min2{DBL_MAX, DBL_MAX};
  for (int i = 0; i < count; i += 2) {
    const int j = i + 1 < count ? i + 1 : i;
    const Lanes vi = lanes(poly.v[i]), vj = lanes(poly.v[j]);
    const Lanes ei = edge(i), ej = edge(j);
    const Lanes ex = low_lanes(ei, ej), ey = high_lanes(ei, ej);
    const Lanes l2 = ex * ex + ey * ey;
    const Lanes l = detail::lane_sqrt(l2);
    const LaneMask nonzero = l > Lanes{0.0, 0.0};
    const Lanes nx = detail::lane_where(nonzero, ey / l), ny = detail::lane_where(nonzero, -ex / l);
    poly.n[static_cast<std::size_t>(i)] = {nx[0], ny[0]};
    poly.n[static_cast<std::size_t>(j)] = {nx[1], ny[1]};
    min2 = detail::lane_min(min2, l2);
    if (support) {
      // support_lines' pair i / 2 (edges i and j): the normals as stored,
      // the offsets dot(n, v) of the edges' start vertices per lane.
      detail::store_support_pair(support[i / 2], nx, ny,
                                 detail::support_offsets(nx, ny, low_lanes(vi, vj), high_lanes(vi, vj)));
    }
  }
  return min2;
}

// Green's theorem on edges, in coordinates relative to v[0] so that large
// offsets do not cancel catastrophically. For edge (a, b), c = a x b:
//   S   += c / 2,  Sx += c (ax + bx) / 6,  Sy += c (ay + by) / 6,
//   Sxx += c (ax^2 + ax bx + bx^2) / 12,  Syy likewise,
//   Sxy += c (ax by + 2 ax ay + 2 bx by + bx ay) / 24.
// green_centroid (the area and centroid only): area_kernels.hpp.

// All the moments, two edges at a time: lane 0 holds edge i, lane 1 edge
// i + 1 (an odd count's last edge alone, repeated in lane 1 and not added),
// each term lane by lane the same operations as green_centroid's for one
// edge; the terms are then added edge by edge in order, S with Sxy, Sx
// with Sy and Sxx with Syy in the two lanes of one sum (bx ay is the
// ay bx of the cross product). The area and centroid are green_centroid's
// bits; for them alone the scalar loop is as short as the lanes. As in
// green_centroid, the two edges at v[0] are left out (zero terms).
// Inline in the block loop (polygon_geometry): no call per block and step.
template <int kN = 0>
[[gnu::always_inline]] inline AreaMoments green_moments(const Vec2* v, int n) {
  using detail::high_lanes;
  using detail::lanes;
  using detail::low_lanes;
  const int count = kN ? kN : n;
  AreaMoments m;
  if (count < 3) return m;
  const Lanes o = lanes(v[0]);
  const auto rel = [&](int i) { return lanes(v[i == count ? 0 : i]) - o; };
  Lanes s_sxy{0.0, 0.0}, sx_sy{0.0, 0.0}, sxx_syy{0.0, 0.0};
  // Edges i (lane 0) and j (lane 1): their terms added in that order, j's
  // only when `both`.
  const auto add_edges = [&](int i, int j, bool both) {
    const Lanes ai = rel(i), aj = rel(j), bi = rel(i + 1), bj = rel(j + 1);
    const Lanes ax = low_lanes(ai, aj), ay = high_lanes(ai, aj);
    const Lanes bx = low_lanes(bi, bj), by = high_lanes(bi, bj);
    const Lanes ax_by = ax * by, ay_bx = ay * bx;
    const Lanes c = ax_by - ay_bx;
    const Lanes two{2.0, 2.0};
    const Lanes tx = c * (ax + bx), ty = c * (ay + by);
    const Lanes txx = c * (ax * ax + ax * bx + bx * bx);
    const Lanes tyy = c * (ay * ay + ay * by + by * by);
    const Lanes txy = c * (ax_by + two * ax * ay + two * bx * by + ay_bx);
    s_sxy += low_lanes(c, txy);
    sx_sy += low_lanes(tx, ty);
    sxx_syy += low_lanes(txx, tyy);
    if (both) {
      s_sxy += high_lanes(c, txy);
      sx_sy += high_lanes(tx, ty);
      sxx_syy += high_lanes(txx, tyy);
    }
  };
  // Edges 1 to count - 2: the two at v[0] add zeros (green_centroid).
  int i = 1;
  for (; i + 2 < count; i += 2) add_edges(i, i + 1, true);
  if (i + 1 < count) add_edges(i, i, false);
  const double s = s_sxy[0] * 0.5;
  const Lanes sx_sy6 = sx_sy / Lanes{6.0, 6.0};
  m.area = s;
  if (s == 0.0) return m;
  const Lanes sl{s, s};
  const Lanes c = sx_sy6 / sl;
  m.centroid = detail::vec2(o + c);
  const Lanes sxx = sxx_syy / Lanes{12.0, 12.0} - sl * c * c;
  m.sxx = sxx[0];
  m.syy = sxx[1];
  m.sxy = s_sxy[1] / 24.0 - s * c[0] * c[1];
  return m;
}

// bounds for kN vertices (0: poly.count), lane by lane from the empty box in
// vertex order: lane_min / lane_max are std::min / std::max, operands in
// that order.
template <int kN>
Aabb bounds_n(const PolygonView& poly) {
  const int count = kN ? kN : poly.count;
  const Aabb empty;
  Lanes lo = detail::lanes(empty.lo), hi = detail::lanes(empty.hi);
  for (int i = 0; i < count; ++i) {
    const Lanes p = detail::lanes(poly.v[static_cast<std::size_t>(i)]);
    lo = detail::lane_min(lo, p);
    hi = detail::lane_max(hi, p);
  }
  return {detail::vec2(lo), detail::vec2(hi)};
}

// update_polygon_geometry for kN vertices (0: poly.count); kFacts: also
// the support lines and, from their normals, the sharp corners. The
// moments and box are written to `moments` and `box` (a simulation's
// arrays: no PolygonGeometry between); returns min_edge2.
template <int kN, bool kFacts>
[[gnu::always_inline]] inline double polygon_geometry(const PolygonSpan& poly, SupportLines::Pair* support,
                                                      std::uint32_t* sharp, AreaMoments& moments, Aabb& box) {
  const int count = kN ? kN : poly.count;
  const Lanes min2 = edge_normals<kN>(poly, kFacts ? support : nullptr);
  if (kFacts) *sharp = detail::sharp_corners_lines<kN>(support, count);
  moments = green_moments<kN>(poly.v, count);
  box = bounds_n<kN>(poly);
  return std::min(min2[0], min2[1]);
}

}  // namespace dda::detail
