// Convex polygon value type and its pure free functions: validation, area
// moments (for the DDA mass matrix, Paper A Eq. 5a), bounds, point location,
// and cutting by a line. Nothing here allocates.
#pragma once
#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <type_traits>
#include "dda/vec2.hpp"

namespace dda {

// Capacity of a Polygon. An intersection polygon or an entrance block of two
// blocks has at most n + m vertices, so blocks are limited to half of it.
// 16 is enough for every generated rock mass: a block cut from a convex
// region of r edges by k joint sets has at most r + 2 k edges (each set's
// parallel joints bound it twice at most), and the test "generated blocks
// fit kMaxBlockVertices" (test_polygon.cpp) checks the scenes of
// rock_scenes.cpp and joint_sets.cpp; a scene file's block with more is
// refused with a message naming the limit (kTooManyVertices).
inline constexpr int kMaxVertices = 32;
inline constexpr int kMaxBlockVertices = kMaxVertices / 2;

// Largest |coordinate| a block may have, m: the second area moments (the
// mass matrix's, Paper A Eq. 5a) grow as size^4 and must stay finite:
// (2e75)^4 = 1.6e301 < DBL_MAX. Above it validate_polygon says kOverflow
// (coordinates of 1e308 were reported as a duplicate vertex).
inline constexpr double kMaxCoordinate = 1e75;

// Round-off budget for geometric predicates, in units of machine epsilon times
// the coordinate magnitude: the absolute error of a difference of coordinates
// of size X is about eps*X, and a predicate chains a few dozen such operations.
inline constexpr double kRoundoffUlps = 64.0;

// Sine of the smallest turn accepted between consecutive edges of a block
// (dimensionless, ~1e-9 rad): below it, three vertices are taken as collinear.
// Far below the paper's smallest angle (5 deg) and our tested 0.5 deg.
inline constexpr double kCollinearSin = 1e-9;

// Smallest edge accepted in a block, relative to the block's diameter:
// shorter edges are duplicate vertices. 1e-6 is tested; 1e-9 leaves margin
// above round-off at coordinate offsets of 1e6.
inline constexpr double kMinEdgeRelative = 1e-9;

// A convex polygon: CCW vertices and outward unit normals; n[i] is the normal
// of edge i, which runs from v[i] to v[(i+1) % count].
struct Polygon {
  int count = 0;  // first: it shares a cache line with the first vertices
  std::array<Vec2, kMaxVertices> v{};
  std::array<Vec2, kMaxVertices> n{};

  Vec2 vertex(int i) const { return v[static_cast<std::size_t>(i)]; }
  Vec2 normal(int i) const { return n[static_cast<std::size_t>(i)]; }
  int next(int i) const { return i + 1 == count ? 0 : i + 1; }
  int prev(int i) const { return i == 0 ? count - 1 : i - 1; }
  Vec2 edge(int i) const { return vertex(next(i)) - vertex(i); }
  bool empty() const { return count < 3; }
};

// A convex polygon stored elsewhere: its count, CCW vertices v[0..count)
// and outward unit normals n[0..count), with Polygon's accessors. Why:
// a Simulation keeps its blocks' geometry in one pool
// sized by vertex count (most blocks have 3-8 vertices; a Polygon value has
// room for kMaxVertices = 32), and the kernels take these forms, of a pooled
// block or of a Polygon value alike. Small: pass them by value. They own
// nothing; they are valid while their storage is.
//   PolygonView (T = const Vec2): read-only, for the geometry kernels.
//   PolygonSpan (T = Vec2): writable, for the functions that move a block
//   (displace_vertices, update_polygon_geometry, ...); the count is fixed (a
//   block keeps its vertices). A span goes wherever a view is taken.
template <class T>
struct PolygonRef {
  int count = 0;  // first, as in Polygon
  T* v = nullptr;
  T* n = nullptr;

  PolygonRef() = default;
  PolygonRef(int count_, T* v_, T* n_) : count(count_), v(v_), n(n_) {}
  // Implicit: a Polygon value (const for a view) goes wherever one is taken.
  using Source = std::conditional_t<std::is_const<T>::value, const Polygon, Polygon>;
  PolygonRef(Source& p) : count(p.count), v(p.v.data()), n(p.n.data()) {}  // NOLINT(google-explicit-constructor)
  // Implicit: a span as a view.
  template <class U, class = std::enable_if_t<std::is_const<T>::value && std::is_same<U, Vec2>::value>>
  PolygonRef(const PolygonRef<U>& span) : count(span.count), v(span.v), n(span.n) {}  // NOLINT(google-explicit-constructor)

  Vec2 vertex(int i) const { return v[i]; }
  Vec2 normal(int i) const { return n[i]; }
  int next(int i) const { return i + 1 == count ? 0 : i + 1; }
  int prev(int i) const { return i == 0 ? count - 1 : i - 1; }
  Vec2 edge(int i) const { return vertex(next(i)) - vertex(i); }
  bool empty() const { return count < 3; }
};
using PolygonView = PolygonRef<const Vec2>;
using PolygonSpan = PolygonRef<Vec2>;

// A Polygon value holding a copy of the view's vertices and normals (the
// rest zero, as make_polygon leaves it). count is clamped to capacity.
Polygon copy_polygon(PolygonView view);

// Builds a polygon from CCW points and computes its normals. Does not check:
// call validate_polygon first on untrusted input. count is clamped to capacity.
Polygon make_polygon(const Vec2* points, int count);
// Recomputes the outward unit normals from the vertices (after a move):
// n = (e.y, -e.x) / sqrt(e.x^2 + e.y^2) for edge e, 0 for a zero-length edge.
void update_normals(PolygonSpan poly);

enum class PolygonFault {
  kNone,
  kTooFewVertices,   // fewer than 3
  kTooManyVertices,  // more than kMaxBlockVertices
  kNonFinite,        // NaN or infinite coordinate
  kDuplicateVertex,  // an edge shorter than kMinEdgeRelative * diameter
  kCollinear,        // a turn smaller than kCollinearSin
  kClockwise,        // every turn is to the right (a convex polygon in clockwise order)
  kNonConvex,        // turns both ways (including a self-intersecting bow tie), or winds more than once
  kOverflow,         // a |coordinate| above kMaxCoordinate: area moments would overflow
};

struct PolygonCheck {
  PolygonFault fault = PolygonFault::kNone;
  int vertex = -1;  // 0-based index of the offending vertex, -1 if none
  bool ok() const { return fault == PolygonFault::kNone; }
};

// Checks that points form a block polygon this library accepts.
PolygonCheck validate_polygon(const Vec2* points, int count);
// A short human-readable reason for a fault ("clockwise vertex order", ...).
const char* describe(PolygonFault fault);

// Area moments about the centroid: S = area, Sxx = int (x-xc)^2 dS,
// Syy = int (y-yc)^2 dS, Sxy = int (x-xc)(y-yc) dS.
struct AreaMoments {
  double area = 0.0;
  Vec2 centroid{};
  double sxx = 0.0, syy = 0.0, sxy = 0.0;
};
AreaMoments area_moments(PolygonView poly);
// Area and centroid only (second moments left 0), bit-identical to area_moments'.
AreaMoments area_centroid(PolygonView poly);
// The same for a CCW ring of `count` points (no normals needed).
AreaMoments area_centroid(const Vec2* ring, int count);
double area(PolygonView poly);
Vec2 centroid(PolygonView poly);

struct Aabb {
  Vec2 lo{DBL_MAX, DBL_MAX};
  Vec2 hi{-DBL_MAX, -DBL_MAX};
};
Aabb bounds(PolygonView poly);
inline bool aabb_overlap(const Aabb& a, const Aabb& b) {
  return a.lo.x <= b.hi.x && b.lo.x <= a.hi.x && a.lo.y <= b.hi.y && b.lo.y <= a.hi.y;
}
double diameter(PolygonView poly);
double min_edge_length(PolygonView poly);
double max_edge_length(PolygonView poly);
double perimeter(PolygonView poly);

// Absolute tolerance for predicates on this polygon, m: kRoundoffUlps * eps
// times (largest |coordinate| + size), where size is the larger side of the
// bounding box (not the diameter: the box is at hand per step, and it is
// within a factor sqrt(2) of the diameter). Scales with offsets and size.
double geometric_tolerance(PolygonView poly);
// The same from the polygon's bounds (a caller that has them; inline: a
// simulation takes it per block and step).
inline double geometric_tolerance(const Aabb& b) {
  const double coord = std::max({std::fabs(b.lo.x), std::fabs(b.lo.y), std::fabs(b.hi.x), std::fabs(b.hi.y)});
  const double size = std::max(b.hi.x - b.lo.x, b.hi.y - b.lo.y);
  return kRoundoffUlps * DBL_EPSILON * (coord + size);
}

// What a moved block needs of its polygon at every step, in one call: the
// normals (recomputed in place, as update_normals), the area moments and
// bounds (the same bits as area_moments and bounds) and the smallest
// squared edge length, m^2 (for the small-edge test).
struct PolygonGeometry {
  AreaMoments moments;
  Aabb box;
  double min_edge2 = DBL_MAX;
};
PolygonGeometry update_polygon_geometry(PolygonSpan poly);

enum class PointLocation { kInside, kOnBoundary, kOutside };

// Point in convex polygon. With d = max_i n_i.(p - v_i) the signed distance
// to the farthest-out edge line: d < -tol inside, d > tol outside, else on
// the boundary. tol < 0 means geometric_tolerance(poly).
PointLocation locate_point(PolygonView poly, Vec2 p, double tol = -1.0);

// Cuts a convex polygon by the line through `point` with unit normal `normal`.
// `below` gets the part with normal.(x - point) <= 0, `above` the rest; either
// may come back empty (count 0). Vertices within tol of the line are shared.
void split_polygon(PolygonView poly, Vec2 point, Vec2 normal, Polygon& below, Polygon& above,
                   double tol = -1.0);

// The one clipping step shared by the cutting routines (intersection_polygon,
// split_polygon, the potential's cells in potential_integral): keeps the
// part of the ring in[0..n) where dist <= 0 (signed distances to a line,
// already snapped to 0 within the caller's tolerance), in order, with the
// points where an edge crosses the line. Writes at most kMaxVertices points
// to out; returns how many.
// Edge labels (optional): in_label[i] names the line edge i of the ring lies
// on; out_label gets the same for the output ring, with line_label for the
// new edge along the cutting line.
int clip_ring(const Vec2* in, const double* dist, int n, Vec2* out, const int* in_label = nullptr,
              int line_label = 0, int* out_label = nullptr);

// Removes repeated vertices (closer than tol) and vertices whose turn is
// within tol of straight from the ring v[0..count); returns the new count,
// 0 when fewer than 3 are left. With label (one per edge, as clip_ring's):
// an edge merged over a repeated vertex keeps the label of the edge that
// remains; two nearly collinear edges merge into one labelled
// kMixedEdgeLabel unless they had the same label (they lie on two lines
// within tol of each other, and neither line alone is known to hold the
// merged edge to within tol). Normals untouched.
inline constexpr int kMixedEdgeLabel = std::numeric_limits<int>::min();  // never a clip_ring label in use
int clean_ring(Vec2* v, int count, double tol, int* label = nullptr);
// clean_ring on the polygon's vertices, then recomputes its normals; empties
// a polygon left with fewer than 3 vertices. Used on clipper output.
void clean_polygon(Polygon& poly, double tol);

// Rigid motion helpers (used by tests and scene set-up).
Polygon translated(const Polygon& poly, Vec2 t);
Polygon rotated(const Polygon& poly, double angle, Vec2 about);

}  // namespace dda
