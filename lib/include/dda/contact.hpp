// Contact force between two overlapping convex polygons: Paper A Sect. 3.2.
// Pure functions; nothing here allocates.
#pragma once
#include "dda/overlap.hpp"
#include "dda/potential.hpp"

namespace dda {

// How the boundary integral of Eq. 11 is split into linear pieces.
enum class Integration {
  // Paper A Sect. 3.2.3 as written: each IP edge is split at its start, end
  // and midpoint and where it crosses the angle-bisector rays of CP and TP
  // (virtual nodes for small edges); the trapezoid rule of Eq. 16 is exact
  // only if those are all the kinks of phi along the edge.
  kPaperBisector,
  // Exact for the min-of-linear potential: each IP edge is split at the true
  // breakpoints of the lower envelope of the per-edge distance functions.
  kExactEnvelope,
};

// One polygon's side of the potential: phi = kn / H * max(0, d_exit).
struct PotentialSide {
  PolygonView poly;  // a view of a Polygon value or of a simulation's pooled block
  double kn_over_h = 0.0;   // kn / H, Pa / m
  double small_edge = 0.0;  // edges shorter than this get a virtual node, m
  SmallEdgeRays small_edge_rays = SmallEdgeRays::kVirtualAndVertex;
  // The polygon's bisectors for (small_edge, small_edge_rays), if the
  // caller keeps them (a simulation builds them once per block and step);
  // null: built on each call. The count before the pointer: it fills the
  // enum's padding, so that a simulation's side and tolerance fit one
  // cache line (56 bytes with the 24-byte view).
  int bisector_count = 0;
  const Bisector* bisectors = nullptr;
};

// Where the loading point pg of Eq. 20 goes when the acting line crosses
// the auxiliary line outside the intersection polygon (segment forces that
// nearly cancel: the lever arm -M / |f| grows without bound).
enum class LoadingPoint {
  // Paper A as printed: the crossing, wherever it lies (couple = 0).
  kPaper,
  // The crossing where it lies inside the IP (the same bits as kPaper);
  // outside, the IP's boundary point on the auxiliary line nearest to it,
  // and the moment the force no longer carries there as a couple (see
  // contact.cpp, bound_to_ip). Beyond the paper, where the paper's point
  // leaves the contact; what the simulation uses (it applies the couple).
  kWithinIp,
};

// Global normal force on CP (f_TP = -force) and where it acts.
struct NormalForce {
  Vec2 force{};          // f_ng_CP, Eq. 18, N (per unit thickness)
  Vec2 point{};          // loading point pg (Eq. 20 and the auxiliary line)
  // Moment of the segment forces about ip_centroid (Eq. 20), N m/m, and
  // the part of it that force at point does not carry: a pure couple on CP
  // (-couple on TP), zero unless LoadingPoint::kWithinIp moved the point.
  // Always moment = cross(point - ip_centroid, force) + couple (round-off).
  double moment = 0.0;
  double couple = 0.0;
  Vec2 ip_centroid{};    // centroid of the intersection polygon
  double ip_area = 0.0;  // m^2
  double ip_perimeter = 0.0;  // m, the edges longer than tol
  int segments = 0;      // integration segments used (trapezoids of Eqs. 16-17 summed)
  bool valid = false;    // false when the net force vanishes
};

// Integrates Eq. 11 over the boundary of ip = CP n TP, segment by segment
// with Eqs. 16-17, and finds the loading point: the acting line is where the
// moment of the segment forces vanishes (Eq. 20); pg is its crossing with the
// perpendicular through the IP centroid (point: `where` says what happens
// when that crossing lies outside the IP). tol: geometric tolerance of the pair.
// source (optional, from overlap_and_intersection): where each IP edge lies.
// An edge on CP's boundary carries phi_CP = 0 and one on TP's phi_TP = 0, and
// so does a vertex at which such an edge starts or ends: those exit
// distances are not evaluated (without sources, the same zeros are found
// within tol from the distances; the two agree to round-off).
NormalForce normal_contact_force(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip,
                                 Integration rule, double tol, const IpEdge* source = nullptr,
                                 LoadingPoint where = LoadingPoint::kPaper);

// Contact (penalty) energy stored in the overlap: the integral over IP of
// phi_CP + phi_TP, exact (IP is cut into the cells where one edge of each
// polygon is nearest, on which the integrand is linear). Its negative
// gradient with respect to the relative position is the force of Eq. 10.
double contact_energy(const PotentialSide& cp, const PotentialSide& tp, const Polygon& ip, double tol);

// Integral over `region` of kn/H * d_exit of `side` (region inside side.poly).
double potential_integral(const PotentialSide& side, const Polygon& region, double tol);

}  // namespace dda
