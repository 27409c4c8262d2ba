#include "dda/polygon.hpp"

#include <algorithm>
#include <cmath>

#include "dda/overlap.hpp"

#include "area_kernels.hpp"
#include "lanes.hpp"
#include "ring_kernels.hpp"
#include "support_kernels.hpp"

namespace dda {

namespace {
constexpr double kPi = 3.14159265358979323846;
// Slack on the total turning, rad: a simple convex polygon turns 2 pi, a
// star that winds twice 4 pi (a bow tie 0); half a turn between the cases
// is far above the round-off of the atan2 sum (a few eps per vertex).
constexpr double kWindingSlack = kPi;
}  // namespace

Polygon copy_polygon(PolygonView view) {
  Polygon poly;
  poly.count = std::min(std::max(view.count, 0), kMaxVertices);
  for (int i = 0; i < poly.count; ++i) {
    poly.v[static_cast<std::size_t>(i)] = view.v[i];
    poly.n[static_cast<std::size_t>(i)] = view.n[i];
  }
  return poly;
}

Polygon make_polygon(const Vec2* points, int count) {
  Polygon poly;
  poly.count = std::min(std::max(count, 0), kMaxVertices);
  for (int i = 0; i < poly.count; ++i) poly.v[static_cast<std::size_t>(i)] = points[i];
  update_normals(poly);
  return poly;
}

namespace {

using detail::LaneMask;
using detail::Lanes;

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

}  // namespace

void update_normals(PolygonSpan poly) {
  if (poly.count == 4) edge_normals<4>(poly);
  else edge_normals<0>(poly);
}

const char* describe(PolygonFault fault) {
  switch (fault) {
    case PolygonFault::kNone: return "valid";
    case PolygonFault::kTooFewVertices: return "fewer than 3 vertices";
    case PolygonFault::kTooManyVertices:
      return "more than 16 vertices (the block limit kMaxBlockVertices: two blocks' intersection must fit 32)";
    case PolygonFault::kNonFinite: return "non-finite coordinate (NaN or infinity)";
    case PolygonFault::kDuplicateVertex: return "duplicate vertex (zero-length edge)";
    case PolygonFault::kCollinear: return "three collinear vertices";
    case PolygonFault::kClockwise: return "clockwise vertex order (counter-clockwise required)";
    case PolygonFault::kNonConvex: return "polygon is not convex (or its edges cross)";
    case PolygonFault::kOverflow: return "coordinate too large (|x| or |y| above 1e75 m: the area moments overflow)";
  }
  return "unknown fault";
}

PolygonCheck validate_polygon(const Vec2* p, int count) {
  if (count < 3) return {PolygonFault::kTooFewVertices, -1};
  if (count > kMaxBlockVertices) return {PolygonFault::kTooManyVertices, -1};
  for (int i = 0; i < count; ++i)
    if (!is_finite(p[i])) return {PolygonFault::kNonFinite, i};
  for (int i = 0; i < count; ++i)
    if (!(std::fabs(p[i].x) <= kMaxCoordinate && std::fabs(p[i].y) <= kMaxCoordinate)) return {PolygonFault::kOverflow, i};

  double diam = 0.0;
  for (int i = 0; i < count; ++i)
    for (int j = i + 1; j < count; ++j) diam = std::max(diam, distance(p[i], p[j]));
  for (int i = 0; i < count; ++i) {
    const Vec2 e = p[(i + 1) % count] - p[i];
    if (length(e) <= kMinEdgeRelative * diam) return {PolygonFault::kDuplicateVertex, (i + 1) % count};
  }

  // Classify every turn; record the first of each sign.
  int first_left = -1, first_right = -1, first_straight = -1;
  double turning = 0.0;
  for (int i = 0; i < count; ++i) {
    const Vec2 a = p[i] - p[(i + count - 1) % count];
    const Vec2 b = p[(i + 1) % count] - p[i];
    const double s = cross(a, b) / (length(a) * length(b));
    turning += std::atan2(cross(a, b), dot(a, b));
    if (s > kCollinearSin) {
      if (first_left < 0) first_left = i;
    } else if (s < -kCollinearSin) {
      if (first_right < 0) first_right = i;
    } else if (dot(a, b) < 0.0) {
      // A 180-degree turn back along the same line: a spike, not a straight run.
      if (first_right < 0) first_right = i;
    } else if (first_straight < 0) {
      first_straight = i;
    }
  }
  // Clockwise only when every turn is to the right and the ring winds once
  // (a convex polygon listed backwards: reversing it fixes it). Turns both
  // ways are non-convex whatever the total turning: a bow tie (edges that
  // cross) turns right, right, left, left... and totals 0, and a concave
  // polygon in clockwise order is no better when reversed (a bow
  // tie was labelled clockwise).
  if (first_left < 0 && first_right >= 0 && first_straight < 0) {
    if (turning < -2.0 * kPi - kWindingSlack) return {PolygonFault::kNonConvex, 0};  // winds twice, clockwise
    return {PolygonFault::kClockwise, first_right};
  }
  if (first_left >= 0 && first_right >= 0) return {PolygonFault::kNonConvex, turning < 0.0 ? first_left : first_right};
  if (first_straight >= 0) return {PolygonFault::kCollinear, first_straight};
  if (turning > 2.0 * kPi + kWindingSlack) return {PolygonFault::kNonConvex, 0};
  return {};
}

namespace {

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
template <int kN = 0>
AreaMoments green_moments(const Vec2* v, int n) {
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

}  // namespace

AreaMoments area_moments(PolygonView poly) {
  if (poly.count == 4) return green_moments<4>(poly.v, 4);
  return green_moments(poly.v, poly.count);
}

// Mostly an intersection polygon: those of shallow contacts are triangles
// and quadrilaterals (about half each in the Sect. 6.1 collapse).
AreaMoments area_centroid(PolygonView poly) {
  if (poly.count == 4) return detail::green_centroid<4>(poly.v, 4);
  if (poly.count == 3) return detail::green_centroid<3>(poly.v, 3);
  return detail::green_centroid(poly.v, poly.count);
}

AreaMoments area_centroid(const Vec2* ring, int count) { return detail::green_centroid(ring, count); }

double area(PolygonView poly) {
  if (poly.count < 3) return 0.0;
  const Vec2 o = poly.v[0];
  double s = 0.0;
  for (int i = 1; i + 1 < poly.count; ++i) s += cross(poly.vertex(i) - o, poly.vertex(i + 1) - o);
  return 0.5 * s;
}

Vec2 centroid(PolygonView poly) { return area_moments(poly).centroid; }

namespace {

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

}  // namespace

Aabb bounds(PolygonView poly) { return bounds_n<0>(poly); }

namespace {

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

}  // namespace

PolygonGeometry update_polygon_geometry(PolygonSpan poly) {
  PolygonGeometry g;
  if (poly.count == 4) g.min_edge2 = polygon_geometry<4, false>(poly, nullptr, nullptr, g.moments, g.box);
  else g.min_edge2 = polygon_geometry<0, false>(poly, nullptr, nullptr, g.moments, g.box);
  return g;
}

// Flattened: the kernels above inline (no call per block and step).
[[gnu::flatten]] double update_polygon_geometry(PolygonSpan poly, SupportLines::Pair* support, std::uint32_t& sharp,
                                                AreaMoments& moments, Aabb& box) {
  if (poly.count == 4) return polygon_geometry<4, true>(poly, support, &sharp, moments, box);
  if (poly.count < 3 || poly.count > kMaxBlockVertices) {  // no support lines: sharp_corners
    sharp = sharp_corners(poly);
    return polygon_geometry<0, false>(poly, nullptr, nullptr, moments, box);
  }
  return polygon_geometry<0, true>(poly, support, &sharp, moments, box);
}

PolygonGeometry update_polygon_geometry(PolygonSpan poly, SupportLines::Pair* support, std::uint32_t& sharp) {
  PolygonGeometry g;
  g.min_edge2 = update_polygon_geometry(poly, support, sharp, g.moments, g.box);
  return g;
}

double diameter(PolygonView poly) {
  double d = 0.0;
  for (int i = 0; i < poly.count; ++i)
    for (int j = i + 1; j < poly.count; ++j) d = std::max(d, distance(poly.vertex(i), poly.vertex(j)));
  return d;
}

double min_edge_length(PolygonView poly) {
  double l = DBL_MAX;
  for (int i = 0; i < poly.count; ++i) l = std::min(l, length(poly.edge(i)));
  return l;
}

double max_edge_length(PolygonView poly) {
  double l = 0.0;
  for (int i = 0; i < poly.count; ++i) l = std::max(l, length(poly.edge(i)));
  return l;
}

double perimeter(PolygonView poly) {
  double l = 0.0;
  for (int i = 0; i < poly.count; ++i) l += length(poly.edge(i));
  return l;
}

double geometric_tolerance(PolygonView poly) { return geometric_tolerance(bounds(poly)); }


PointLocation locate_point(PolygonView poly, Vec2 p, double tol) {
  if (tol < 0.0) tol = geometric_tolerance(poly);
  double d = -DBL_MAX;
  for (int i = 0; i < poly.count; ++i) d = std::max(d, dot(poly.normal(i), p - poly.vertex(i)));
  if (d < -tol) return PointLocation::kInside;
  if (d > tol) return PointLocation::kOutside;
  return PointLocation::kOnBoundary;
}

int clean_ring(Vec2* v, int count, double tol, int* label) {
  // Squared comparisons: no square root per vertex.
  const double tol2 = tol * tol;
  // The usual ring has nothing to remove: one read-only sweep tells.
  if (count >= 3 && !detail::ring_needs_clean<0>(v, count, tol2)) return count;
  bool changed = true;
  while (changed && count >= 3) {
    changed = false;
    for (int i = 0; i < count && count >= 3; ++i) {
      const int ip = i == 0 ? count - 1 : i - 1;
      const Vec2 a = v[ip];
      const Vec2 b = v[i];
      const Vec2 c = v[i + 1 == count ? 0 : i + 1];
      // Repeated vertex, or b within tol of the chord a-c (straight or spike).
      if (detail::removable_vertex(a, b, c, tol2)) {
        // The merged edge a-c: along b-c when a-b was a repeated vertex; at a
        // straight turn, on both lines within tol: mixed unless they agree.
        const bool repeated = length_squared(a - b) <= tol2;
        if (label) label[ip] = repeated ? label[i] : label[ip] == label[i] ? label[i] : kMixedEdgeLabel;
        for (int j = i; j + 1 < count; ++j) {
          v[j] = v[j + 1];
          if (label) label[j] = label[j + 1];
        }
        --count;
        changed = true;
        --i;
      }
    }
  }
  return count < 3 ? 0 : count;
}

void clean_polygon(Polygon& poly, double tol) {
  poly.count = clean_ring(poly.v.data(), poly.count, tol);
  update_normals(poly);
}

int clip_ring(const Vec2* in, const double* dist, int n, Vec2* out, const int* in_label, int line_label,
              int* out_label) {
  // The rule per edge is detail::clip_edge's. A ring of at most
  // kMaxVertices / 2 points cannot fill the output (each edge appends at
  // most two), so only a longer one checks the capacity on every append.
  if (n <= 0) return 0;
  const bool guard = 2 * n > kMaxVertices;
  if (out_label)
    return guard ? detail::clip_ring_n<true, true>(in, dist, n, out, in_label, line_label, out_label)
                 : detail::clip_ring_n<true, false>(in, dist, n, out, in_label, line_label, out_label);
  return guard ? detail::clip_ring_n<false, true>(in, dist, n, out, in_label, line_label, out_label)
               : detail::clip_ring_n<false, false>(in, dist, n, out, in_label, line_label, out_label);
}

void split_polygon(PolygonView poly, Vec2 point, Vec2 normal, Polygon& below, Polygon& above, double tol) {
  if (tol < 0.0) tol = geometric_tolerance(poly);
  // Signed distances snapped within tol; `above` is the same clip with the
  // signs flipped (the crossing points come out bit-identical: negation is exact).
  std::array<double, kMaxVertices> d{}, flipped{};
  for (int i = 0; i < poly.count; ++i) {
    double di = dot(normal, poly.vertex(i) - point);
    if (std::fabs(di) <= tol) di = 0.0;
    d[static_cast<std::size_t>(i)] = di;
    flipped[static_cast<std::size_t>(i)] = -di;
  }
  below.count = clip_ring(poly.v, d.data(), poly.count, below.v.data());
  above.count = clip_ring(poly.v, flipped.data(), poly.count, above.v.data());
  clean_polygon(below, tol);
  clean_polygon(above, tol);
}

Polygon translated(const Polygon& poly, Vec2 t) {
  Polygon out = poly;
  for (int i = 0; i < out.count; ++i) out.v[static_cast<std::size_t>(i)] += t;
  return out;
}

Polygon rotated(const Polygon& poly, double angle, Vec2 about) {
  Polygon out = poly;
  for (int i = 0; i < out.count; ++i)
    out.v[static_cast<std::size_t>(i)] = about + rotate(poly.vertex(i) - about, angle);
  update_normals(out);
  return out;
}

}  // namespace dda
