// The shortest-exit contact potential of Paper A Sect. 3.2.2 (Eqs. 12-14) and
// the geometry its integration needs (Sect. 3.2.3): angle-bisector rays from
// the vertices and virtual nodes of small edges, and the inscribed-circle
// radius used as the 'previous' per-polygon H.
#pragma once
#include "dda/polygon.hpp"

namespace dda {

// d_exit(p) = min_i n_i . (v_i - p)  (Eqs. 13-14): the shortest distance for
// p to leave the polygon; positive inside, negative outside. Inline: the
// contact integration evaluates it at every demarcation point.
inline double exit_distance(PolygonView poly, Vec2 p) {
  double d = DBL_MAX;
  for (int i = 0; i < poly.count; ++i) {
    const double di = dot(poly.normal(i), poly.vertex(i) - p);
    d = di < d ? di : d;
  }
  return d;
}

// phi(p) = kn * d_exit(p) / H inside the polygon, 0 outside (Eq. 12).
inline double potential(PolygonView poly, Vec2 p, double kn, double h) {
  const double d = exit_distance(poly, p);
  return d > 0.0 ? kn * d / h : 0.0;
}

// Gradient of phi at p: -kn/H times the normal of the nearest edge (inside).
Vec2 potential_gradient(PolygonView poly, Vec2 p, double kn, double h);

// Radius and centre of the largest inscribed circle: the maximum of d_exit,
// a small linear programme solved exactly by enumerating triples of edge
// lines (O(n^4) but n <= 16 and it runs once per block or per H update).
// radius == exit_distance(poly, centre) > 0 for a valid block. When no
// triple's centre has a positive exit distance (a polygon below the
// coordinate spacing at its offset, or a plateau optimum whose ends round
// onto an edge), the centre is the vertex mean, a point of the polygon,
// and the radius its exit distance if positive, else 0: callers that
// divide by the radius must test radius > 0 (the error).
struct InscribedCircle {
  Vec2 centre{};
  double radius = 0.0;
};
InscribedCircle inscribed_circle(PolygonView poly);

// A bisector of Sect. 3.2.3 in the form the contact integration uses: the
// points where edge lines line_a and line_b of a polygon are equally far,
// d_line_a = d_line_b >= d0 (signed distances inside the lines, as in
// exit_distance). Along an IP edge those distances are at hand, so a
// crossing costs two subtractions and a sign test. The vertex ray at v_i
// is lines i-1 and i with d0 = 0; the virtual node of a small edge e is
// lines e-1 and e+1 with d0 = the node's distance from them.
struct Bisector {
  int line_a = -1, line_b = -1;  // edge indices of the polygon
  double d0 = 0.0;               // distance of the ray's origin from both lines, m
};

// The same ray drawn: from `origin` along unit `dir` into the polygon.
struct Ray {
  Vec2 origin{};
  Vec2 dir{};
  Bisector lines;
};

// What a virtual node does to the rays of a small edge's two vertices.
enum class SmallEdgeRays {
  // Paper A Sect. 3.2.3 as printed: "Both the real nodes and virtual nodes
  // of CP or TP are used in locating the demarcation points."
  kVirtualAndVertex,
  // SPEC.md's reading: the virtual node "replaces its two vertices as ray
  // origins". Kept as an option: the difference is a measured result.
  kVirtualReplacesVertex,
};

// Angle-bisector rays of Sect. 3.2.3. From every vertex, the inward bisector
// of its angle. An edge shorter than `small_edge` gets one more ray from a
// virtual node: the crossing of the two vertex bisectors, pointing along the
// bisector of the two neighbouring edges (the direction in which the
// potential stays equidistant from them); with kVirtualReplacesVertex it
// replaces the two vertex rays. Returns the number of rays written to `out`,
// at most 2 * poly.count (out must hold that many).
int bisector_rays(PolygonView poly, double small_edge, SmallEdgeRays mode, Ray* out);
// The same rays (count and order) as bisectors only: what a simulation
// rebuilds per block and step (no direction, so no square root per vertex).
int bisectors(PolygonView poly, double small_edge, SmallEdgeRays mode, Bisector* out);
// The replacing form (at most poly.count rays).
inline int bisector_rays(PolygonView poly, double small_edge, Ray* out) {
  return bisector_rays(poly, small_edge, SmallEdgeRays::kVirtualReplacesVertex, out);
}

// The bisectors of one polygon, kept so that a block's are built once per
// step, not once per contact.
struct BisectorSet {
  std::array<Bisector, 2 * kMaxVertices> b;  // left uninitialised: count says how many are set
  int count = 0;
};

}  // namespace dda
