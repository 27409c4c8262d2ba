#include "dda/potential.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace dda {

namespace {

// Smallest |determinant| of a triple of edge lines' system [n_x n_y 1]
// (dimensionless; unit normals make it at most about 3): below it two of
// the lines are parallel within ~1e-12 rad, far below the turns a block may
// have (kCollinearSin = 1e-9), and the triple has no tangent circle.
constexpr double kParallelLinesDet = 1e-12;

// Smallest |cross product| of two unit bisector directions of a small
// edge's end vertices (dimensionless, the sine of their angle): below it
// they are parallel and meet nowhere (cannot happen for a convex block,
// whose turns exceed kCollinearSin).
constexpr double kParallelBisectorsSin = 1e-14;

}  // namespace

Vec2 potential_gradient(PolygonView poly, Vec2 p, double kn, double h) {
  double d = DBL_MAX;
  int best = -1;
  for (int i = 0; i < poly.count; ++i) {
    const double di = dot(poly.normal(i), poly.vertex(i) - p);
    if (di < d) {
      d = di;
      best = i;
    }
  }
  if (best < 0 || d <= 0.0) return {};
  return -(kn / h) * poly.normal(best);
}

InscribedCircle inscribed_circle(PolygonView poly) {
  // Maximise r subject to n_i . (v_i - c) >= r for all i. The optimum is a
  // vertex of the feasible set in (c, r) space: three constraints tight.
  // The systems are solved relative to v_0, so that a large coordinate offset
  // does not swamp the right-hand sides, and each candidate centre is scored
  // by its actual exit distance: the answer is feasible by construction
  // (radius == exit_distance(centre)) and needs no feasibility tolerance.
  InscribedCircle best;
  const int n = poly.count;
  if (n > 0) best.centre = poly.vertex(0);  // a point of the polygon, whatever follows
  if (n < 3) return best;
  const Vec2 o = poly.vertex(0);
  for (int i = 0; i < n; ++i)
    for (int j = i + 1; j < n; ++j)
      for (int k = j + 1; k < n; ++k) {
        // Rows: n_x c_x + n_y c_y + r = n . (v - o)  for edges i, j, k.
        const Vec2 ni = poly.normal(i), nj = poly.normal(j), nk = poly.normal(k);
        const double bi = dot(ni, poly.vertex(i) - o), bj = dot(nj, poly.vertex(j) - o), bk = dot(nk, poly.vertex(k) - o);
        const double det = ni.x * (nj.y - nk.y) - ni.y * (nj.x - nk.x) + (nj.x * nk.y - nj.y * nk.x);
        if (std::fabs(det) < kParallelLinesDet) continue;  // two parallel lines met twice: no vertex
        // Cramer's rule on [nx ny 1 | b].
        const double dx = bi * (nj.y - nk.y) - ni.y * (bj - bk) + (bj * nk.y - nj.y * bk);
        const double dy = ni.x * (bj - bk) - bi * (nj.x - nk.x) + (nj.x * bk - bj * nk.x);
        const double dr = ni.x * (nj.y * bk - bj * nk.y) - ni.y * (nj.x * bk - bj * nk.x) + bi * (nj.x * nk.y - nj.y * nk.x);
        if (dr / det <= best.radius) continue;  // the exit distance at c is at most dr / det
        const Vec2 c = o + Vec2{dx / det, dy / det};
        const double r = exit_distance(poly, c);  // < dr / det if another edge is closer
        if (r > best.radius) best = {c, r};
      }
  if (best.radius > 0.0) return best;
  // No triple gave a centre with a positive exit distance: every candidate
  // rounded onto (or past) an edge. Either the polygon is below the
  // coordinate spacing at its offset, or the optimum is a plateau whose
  // ends are not representable: a rectangle 1e-12 m wide at x = 8192
  // (spacing 1.8e-12 m) has its tangent circles' centres 5e-13 m from the
  // short edges. This returned r = 0 at (0, 0), a point far from
  // the polygon. Now the vertex mean (a point of the polygon: on the
  // plateau's middle line for the rectangle), with its exit distance when
  // positive, else r = 0 there (the error callers test).
  Vec2 mean{};
  for (int i = 0; i < n; ++i) mean += poly.vertex(i);
  best.centre = mean / static_cast<double>(n);
  best.radius = std::max(0.0, exit_distance(poly, best.centre));
  return best;
}

namespace {

// bisector_rays (Out = Ray) and bisectors (Out = Bisector): one walk, so the
// two give the same rays in the same order.
template <class Out>
int make_bisectors(PolygonView poly, double small_edge, SmallEdgeRays mode, Out* out) {
  constexpr bool kDraw = std::is_same_v<Out, Ray>;
  const int n = poly.count;
  int count = 0;
  // Inward bisector at vertex i, between edges i-1 and i.
  auto vertex_dir = [&](int i) { return normalized(-(poly.normal(poly.prev(i)) + poly.normal(i))); };
  const double small2 = small_edge * small_edge;  // squared: no square root per edge
  std::uint32_t replaced = 0;                      // bit i: vertex i's ray gave way to a virtual node
  for (int e = 0; e < n; ++e) {
    if (length_squared(poly.edge(e)) >= small2) continue;
    const int a = e, b = poly.next(e);
    const std::uint32_t ab_bits = (std::uint32_t{1} << a) | (std::uint32_t{1} << b);
    if (replaced & ab_bits) continue;  // consecutive small edges: first one wins
    // Virtual node: crossing of the bisectors from v_a and v_b. By symmetry
    // of the construction it lies on the line equidistant from edges e-1 and
    // e+1 at distance (|e| / 2) / tan-ish from the edge; solve the 2x2 system.
    const Vec2 pa = poly.vertex(a), pb = poly.vertex(b);
    const Vec2 da = vertex_dir(a), db = vertex_dir(b);
    const double den = cross(da, db);
    if (std::fabs(den) < kParallelBisectorsSin) continue;  // parallel bisectors (cannot happen when convex)
    const double s = cross(pb - pa, db) / den;
    const Vec2 node = pa + s * da;
    if (mode == SmallEdgeRays::kVirtualReplacesVertex) replaced |= ab_bits;
    // The node is as far from edge e's line as from its neighbours'.
    const Bisector lines{poly.prev(a), b, dot(poly.normal(e), pa - node)};
    if constexpr (kDraw)
      out[count++] = {node, normalized(-(poly.normal(poly.prev(a)) + poly.normal(b))), lines};
    else
      out[count++] = lines;
  }
  for (int i = 0; i < n; ++i) {
    if (replaced >> i & 1u) continue;
    const Bisector lines{poly.prev(i), i, 0.0};
    if constexpr (kDraw)
      out[count++] = {poly.vertex(i), vertex_dir(i), lines};
    else
      out[count++] = lines;
  }
  return count;
}

}  // namespace

int bisector_rays(PolygonView poly, double small_edge, SmallEdgeRays mode, Ray* out) {
  return make_bisectors(poly, small_edge, mode, out);
}

int bisectors(PolygonView poly, double small_edge, SmallEdgeRays mode, Bisector* out) {
  return make_bisectors(poly, small_edge, mode, out);
}

}  // namespace dda
