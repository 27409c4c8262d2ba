#include "dda/polygon.hpp"

#include <algorithm>
#include <cmath>

#include "dda/overlap.hpp"

#include "area_kernels.hpp"
#include "geometry_kernels.hpp"
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

using detail::bounds_n;
using detail::edge_normals;
using detail::green_moments;
using detail::polygon_geometry;

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

Aabb bounds(PolygonView poly) { return bounds_n<0>(poly); }

PolygonGeometry update_polygon_geometry(PolygonSpan poly) {
  PolygonGeometry g;
  if (poly.count == 4) g.min_edge2 = polygon_geometry<4, false>(poly, nullptr, nullptr, g.moments, g.box);
  else g.min_edge2 = polygon_geometry<0, false>(poly, nullptr, nullptr, g.moments, g.box);
  return g;
}

// Flattened: the kernels (geometry_kernels.hpp) inline (no call per block
// and step).
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
