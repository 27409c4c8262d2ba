// Reference geometry in CGAL's exact kernel (Exact_predicates_exact_constructions_kernel,
// EPECK). Only exact.cpp includes CGAL; this interface speaks doubles.
//
// Inputs are doubles and enter the exact kernel exactly. Every predicate
// (inside / on / outside, sign of an area, left turn) is decided exactly.
// Every number handed back is computed exactly and rounded once at the end
// (CGAL::to_double of the *exact* value, never of a lazy interval, which
// would only be accurate to about 1e-5 relative).
#pragma once
#include <memory>
#include <vector>

#include "support.hpp"

namespace prop::exact {

// Convex hull of double points, CCW, without collinear points; the hull
// vertices are input points (used by the generators).
Points convex_hull(const Points& pts);

// Every turn of p is strictly to the left (exact orientation) and p winds
// once: a strictly convex, CCW, simple polygon. Empty p is rejected.
bool is_strictly_convex_ccw(const Points& p);

enum class Contact { kApart, kTouching, kOverlapping };
const char* name(Contact c);

// Exact classification of two convex polygons (closed sets).
struct PairTruth {
  Contact contact = Contact::kApart;  // kOverlapping iff the exact intersection area is > 0
  double area = 0.0;                  // exact intersection area (rounded)
  // sigma = max over the edges of D = B - A of the signed distance from the
  // origin to the edge line (outward positive): -(penetration depth) when
  // the interiors overlap, 0 when touching, and when apart a lower bound of
  // the separation that is exact when the nearest feature of D is an edge.
  // It is the exact value of the quantity the kernel compares with its
  // tolerance (Paper A Table 2: a0 in E(A,B) = B - A + a0).
  double sigma = 0.0;
  double separation = 0.0;  // Euclidean distance between A and B (0 if they meet)
};
PairTruth pair_truth(const Points& a, const Points& b);

// The entrance block E = B - A + a0 = conv{ b_j - a_i + a0 }, exact, CCW,
// vertices rounded to double.
Points entrance_block(const Points& a, const Points& b, Vec2 a0);

// Area moments about the centroid, computed exactly on the same vertices.
struct Moments {
  double area = 0.0, cx = 0.0, cy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;
};
Moments area_moments(const Points& p);

// min_i of the signed distance from q to the line of edge i (positive on the
// inner side): the exit distance of Paper A Eqs. 13-14, evaluated exactly.
double exit_distance(const Points& p, Vec2 q);
enum class Location { kInside, kOnBoundary, kOutside };
Location locate(const Points& p, Vec2 q);

// A half-plane normal . (x - point) <= 0 (split_polygon's `below` side).
struct HalfPlane {
  Vec2 point, normal;
};

// The convex region P = intersection of the inner half-planes of the edges of
// every polygon in `polys` (CCW) and of `lines`, together with its inner and
// outer parallel versions P_in(t) and P_out(t), where every half-plane is
// moved by t inward or outward (t a length). A clipper that decides "on the
// line" within a tolerance below t must return a polygon K with
// P_in(t) within K within P_out(t); any two such polygons are then within
// Hausdorff distance H(P_out(t), P_in(t)) of each other.
class Region {
 public:
  Region(const std::vector<Points>& polys, const std::vector<HalfPlane>& lines, double t);
  ~Region();
  Region(const Region&) = delete;
  Region& operator=(const Region&) = delete;

  double area() const;         // exact area of P, rounded
  bool has_interior() const;   // exact area of P > 0
  bool inner_empty() const;    // P_in(t) has no interior
  Points vertices() const;     // of P, rounded
  Points inner() const;        // of P_in(t), rounded
  Points outer() const;        // of P_out(t), rounded
  // H(P_out(t), P_in(t)) measured in double; +infinity when P_in(t) is empty.
  double hausdorff_bound() const;
  // Index of the first vertex of k outside P_out(t) (exact), or -1.
  int first_vertex_outside_outer(const Points& k) const;
  // Index of the first vertex of P_in(t) not in the closed convex polygon k
  // (exact), or -1. Requires k strictly convex CCW.
  int first_inner_vertex_outside(const Points& k) const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace prop::exact
