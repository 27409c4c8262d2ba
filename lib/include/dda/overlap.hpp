// Overlap examination with the entrance block (Paper A Sect. 3.1.2, Eq. 9)
// and the intersection polygon by cutting (Sect. 3.1.3).
#pragma once
#include <array>
#include <cstdint>

#include "dda/polygon.hpp"

namespace dda {

// Where an edge of the entrance block comes from: the Minkowski sum B - A has
// exactly two kinds of edges, an edge of B translated by a vertex of -A, or an
// edge of -A translated by a vertex of B (the vertex-edge pairs of Table 1).
struct EntranceEdgeSource {
  bool from_b = true;  // true: edge `edge` of B at vertex `vertex` of A
  int edge = -1;       // index into B (from_b) or into A (!from_b)
  int vertex = -1;     // index into A (from_b) or into B (!from_b)
};

struct EntranceBlock {
  Polygon poly;  // E(A, B) = B - A + a0, CCW
  std::array<EntranceEdgeSource, kMaxVertices> source{};  // source of edge i
};

// Builds E(A,B) = B - A + a0 in O(n + m): both polygons are walked from their
// lowest vertex and the edges of B and of -A are merged by the angle of their
// outward normals. Only vertex-edge pairs whose vertex is extreme along the
// edge's normal appear, which is the pair-skipping rule of Table 1. Exactly
// parallel edges of B and -A merge into one edge; nearly parallel ones give a
// very short edge whose normal is still exact (taken from its source edge).
EntranceBlock entrance_block(const PolygonView& a, const PolygonView& b, Vec2 a0);

// kTouching: the boundaries meet within tol but there is no intersection
// polygon; the solver applies no contact force (contact_forces.cpp counts
// only kOverlapping pairs with an IP).
enum class OverlapState { kSeparate, kTouching, kOverlapping };

// A and B overlap iff a0 lies inside E(A,B) (Table 2) by more than tol AND
// the intersection polygon (A the contact, B the target) is not empty: one
// verdict from one computation, the same as overlap_and_intersection's, so
// kOverlapping always comes with an IP of >= 3 vertices (a sharp
// wedge deep in a block at offset 1e9 overlaps by far more than tol along
// every axis, yet the exact intersection is a sliver thinner than tol).
// a0 on E's boundary (within tol) is touching: boundaries meet, interiors
// do not; so is a deeper overlap whose IP is empty. tol < 0 means
// the geometric tolerance of the two inputs. Evaluated on E's edge lines
// directly (see the source), which is what entrance_block() + locate_point()
// decide, without building E; the property tests check both against CGAL.
OverlapState overlap_state(const PolygonView& a, const PolygonView& b, double tol = -1.0);
inline bool overlaps(const PolygonView& a, const PolygonView& b) {
  return overlap_state(a, b) == OverlapState::kOverlapping;
}

// How far an intersection-polygon vertex may lie from either input polygon,
// Euclidean, in units of the pair tolerance tol (dimensionless). Every IP
// vertex is within tol of every edge line of both inputs; near a corner of
// interior angle theta that allows tol / sin(theta / 2) from the polygon
// (1e6 tol at 1e-6 rad), so the clipper bevels the contact's corners under
// 30 degrees (see overlap.cpp, clip_target): then tol / sin(15 deg) = 3.86
// tol at most (a 30-degree corner), or 4.1 tol with the round-off of the
// distances (a few eps C, < tol / 16) added to tol; 4.5 with margin. Holds
// at any angle and offset (checked against CGAL's exact kernel by
// property_tests).
inline constexpr double kIpVertexReach = 4.5;
// The corners that the clipper bevels when the polygon is the contact: bit
// c set when corner c (between edges c - 1 and c) has an interior angle
// below 30 degrees (see overlap.cpp, kBevelCos). At most two corners of a
// convex polygon are that sharp (three would turn by more than 360
// degrees). A fact of the polygon alone, computed once per block and step
// by a simulation rather than once per pair.
std::uint32_t sharp_corners(const PolygonView& poly);
// "Not given": no convex polygon has that many sharp corners.
inline constexpr std::uint32_t kSharpCornersUnknown = ~std::uint32_t{0};

// Bound on the IP's area error, in units of (n + m) tol D (dimensionless;
// see intersection_polygon): the boundary moves by at most tol per vertex
// decision (snap, crossing, clean) along chords no longer than D.
inline constexpr double kIpAreaBound = 1.0;

// The intersection polygon (IP): the target polygon cut by the line of each
// edge of the contact polygon, keeping the inner half-plane each time (Table 3).
// Vertices within tol of a cutting line are taken as on it, so a line through
// a vertex or along an edge makes no duplicate vertex or zero-length edge.
// Returns an empty polygon (count 0) when the interiors do not overlap.
// What the result promises (tol = the pair tolerance, n + m vertex counts,
// D = the smaller diameter of the two inputs), checked exactly against CGAL
// by property_tests at any angle (corners and crossings down to 1e-6 rad)
// and at offsets up to 1e9 times the block size:
//  - every vertex within kIpVertexReach tol (Euclidean) of both inputs;
//  - strictly convex, CCW, no edge shorter than tol; it contains the exact
//    intersection shrunk by 2 tol and lies within it grown by 2 tol (every
//    half-plane moved by 2 tol);
//  - |area(IP) - area(contact and target)| <= kIpAreaBound (n + m) tol D
//    (each vertex decision moves the boundary by <= tol along a chord <= D);
//  - empty (count 0) only if that shrunk intersection is empty: a sliver
//    thinner than ~tol may have no IP (and overlap_state says touching).
Polygon intersection_polygon(const PolygonView& contact, const PolygonView& target, double tol = -1.0);
// The same, into `out` (no 1 KB Polygon constructed: for the hot path).
void intersection_polygon(const PolygonView& contact, const PolygonView& target, double tol, Polygon& out);

// Which input an edge of an intersection polygon lies on: the contact
// polygon's edge `edge` (the IP edge is part of CP's boundary, where phi_CP
// = 0) or the target polygon's (phi_TP = 0 there). The IP's normal of that
// edge is the source edge's normal. Like a Box2D feature id, it lets the
// contact integration skip potentials that vanish by construction.
// An edge left by merging two nearly collinear edges of different
// polygons (or of two edges of one), or cut by a bevel at a sharp corner
// of the contact (overlap.cpp, clip_target), has edge = -1: its source is
// not known and its normal is computed from its end points.
struct IpEdge {
  bool on_contact = false;  // true: an edge of the contact polygon; false: of the target
  int edge = -1;            // its index in that polygon; -1: not known
  bool known() const { return edge >= 0; }
};

// A polygon's support lines as the overlap test reads them (Eq. 9's edge
// lines): the components of the outward edge normals n_j and the support
// offsets n_j . v_j of the edges' start vertices, two edges at a time
// (pair k: edges 2k and 2k + 1, an odd count's last edge repeated in the
// last pair), each pair's values together so that a quadrilateral's
// lines are 96 contiguous bytes. A fact of the polygon alone, for a caller
// that keeps it per block (at most kMaxBlockVertices vertices) and step
// rather than the test building it for every pair
// (overlap_and_intersection's contact_support, target_support). The test
// reads a polygon's lines through a pointer to its first Pair, so that a
// caller may pool them, support_line_pairs(count) per polygon; SupportLines
// holds room for any block polygon's.
struct SupportLines {
  struct Pair {
    alignas(16) double nx[2];
    double ny[2], off[2];
  };
  std::array<Pair, kMaxBlockVertices / 2> pair{};
};
// The number of Pairs support_lines writes for a polygon of `count`
// vertices: (count + 1) / 2 for 3 to kMaxBlockVertices, 0 otherwise.
constexpr int support_line_pairs(int count) {
  return count >= 3 && count <= kMaxBlockVertices ? (count + 1) / 2 : 0;
}
// Fills out[0 .. support_line_pairs(poly.count)) from `poly` (count 3 to
// kMaxBlockVertices; others: nothing).
void support_lines(const PolygonView& poly, SupportLines::Pair* out);
inline void support_lines(const PolygonView& poly, SupportLines& out) { support_lines(poly, out.pair.data()); }
// update_polygon_geometry(poly) and, in the same pass over the edges,
// support_lines(poly, support) and sharp = sharp_corners(poly) (defined in
// polygon.cpp; the same bits): a simulation's per-block update, with the
// normals at hand. A polygon support_lines writes nothing for leaves
// support as it is.
PolygonGeometry update_polygon_geometry(PolygonSpan poly, SupportLines::Pair* support, std::uint32_t& sharp);
// The same with the moments and box written to `moments` and `box` (a
// simulation's per-block arrays); returns min_edge2.
double update_polygon_geometry(PolygonSpan poly, SupportLines::Pair* support, std::uint32_t& sharp,
                               AreaMoments& moments, Aabb& box);

// The overlap verdict and, when overlapping, the intersection polygon with
// its edge sources, in one pass (the hot path of a contact pair). The
// verdict is overlap_state(contact, target, tol)'s; the IP is
// intersection_polygon(contact, target, tol)'s vertices, except that its
// normals are the source edges' (exact, no square root). The overlap test's
// edge-line distances tell which of the contact polygon's edge lines cut the
// target at all; the others are skipped by the clipping, which they would
// leave unchanged. `ip` is emptied when the result is not kOverlapping.
// witness (optional, kept by the caller per pair between calls, -1 at
// first): the separating axis found last time, tried first; set to the axis
// whenever the verdict is kSeparate, to -1 otherwise. A pair that stays
// apart is then rejected by one axis instead of a search. The verdict does
// not depend on it: any axis separating by more than tol makes the full
// test say kSeparate. The views by reference (here and in the rest of this
// header): the simulation's pair loop passes the ones it keeps per block,
// read in place (measured: fewer instructions than copies by value).
// contact_sharp (optional): sharp_corners(contact), when the caller keeps
// it per polygon (a simulation builds it once per block and step);
// kSharpCornersUnknown: found here.
OverlapState overlap_and_intersection(const PolygonView& contact, const PolygonView& target, double tol, Polygon& ip,
                                      IpEdge* source, int* witness = nullptr,
                                      std::uint32_t contact_sharp = kSharpCornersUnknown);

// What a caller may keep per polygon and give the overlap test, in one
// reference (a simulation builds them once per block and step):
// contact_sharp as above; contact_support, target_support: the first Pair
// of the support_lines() of the two polygons as they are now, each followed
// by the rest of its polygon's pairs (nullptr: built by the test; ignored
// for a polygon of more than kMaxBlockVertices vertices). The verdict and
// the IP are the same bits either way.
struct OverlapFacts {
  std::uint32_t contact_sharp = kSharpCornersUnknown;
  const SupportLines::Pair* contact_support = nullptr;
  const SupportLines::Pair* target_support = nullptr;
};
OverlapState overlap_and_intersection(const PolygonView& contact, const PolygonView& target, double tol, Polygon& ip,
                                      IpEdge* source, int* witness, const OverlapFacts& facts);

// Tolerance used for a pair: the larger of the two polygons' tolerances.
double pair_tolerance(const PolygonView& a, const PolygonView& b);

}  // namespace dda
