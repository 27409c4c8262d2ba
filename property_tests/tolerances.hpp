// Every tolerance of the property tests, with its unit and the reason for it.
//
// Units. The kernel's own round-off unit is its absolute tolerance
//   g(P)     = dda::geometric_tolerance(P) = 64 eps (max|coordinate| + size)   [length]
//   tol(A,B) = dda::pair_tolerance(A, B)  = max(g(A), g(B))                    [length]
// (eps = DBL_EPSILON). It grows with the coordinate offset C and the size D,
// as the absolute error of every difference of coordinates does (~eps C).
// Constants named k...Tol below are multiples of g or tol (dimensionless
// factors); derived tolerances are lengths, areas or second moments as noted.
//
// THE TOUCHING BAND (overlap verdict, point location). overlap_state measures
// d = max over the edges of E(A,B) = B - A + a0 of n . (a0 - v), the signed
// distance from a0 to E's edge lines (equivalently, the largest separation of
// A and B along the edge normals of A and B), and answers touching when
// |d| <= tol. The test computes the same quantity exactly, sigma
// (exact::PairTruth): sigma = -(penetration depth) when the interiors
// overlap, 0 when the boundaries only touch, and > 0 (at most the separation)
// when apart. The kernel's error in d is a few eps (C + D) (dot products of
// unit normals with coordinates of size C), far below tol = 64 eps (C + D).
// Hence, with no band at all:
//   interiors overlap  => never kSeparate;   boundaries touch => kTouching;
//   apart              => never kOverlapping;
// and outside the band |sigma| <= kVerdictBand * tol the verdict is unique:
//   sigma < -band => kOverlapping,   sigma > band => kSeparate.
// Inside the band the kernel may say touching for an overlap shallower than
// tol or a gap narrower than tol -- by design (a0 within tol of E's boundary
// is "touching"), not by error. Note that sigma, not the Euclidean gap, is
// the measure: near a vertex of E with interior angle theta, a gap of
// tol / sin(theta / 2) still has sigma <= tol (Paper A's Table 2 test
// compares distances to edge lines, not to E).
#pragma once

namespace prop::tol {

// Half-width of the touching band, x tol(A,B): tol (the kernel's deliberate
// "touching" zone) plus at most tol of round-off in d.
inline constexpr double kVerdictBand = 2.0;

// Entrance block vs the exact Minkowski difference, Hausdorff distance, x tol:
// E's vertices are b_j - a_i + a0 with two roundings each (<= 1.5 eps C).
inline constexpr double kEntranceHausdorff = 1.0;
// How far an entrance-block vertex may lie outside an edge line of E, x tol:
// every edge line of E must support E (the inside test takes a max over them).
inline constexpr double kEntranceSupport = 1.0;
// Slack of the vertex-edge pair rule (Table 1), x tol: the vertex of a pair
// must be extreme along the edge's normal up to round-off in n . v.
inline constexpr double kPairRuleSlack = 1.0;
// |1 - |n|| for a unit normal, dimensionless: hypot and a division, 2 eps each.
inline constexpr double kUnitNormal = 8.0 * 2.220446049250313e-16;

// Width t of the exact "sandwich" P_in(t) within K within P_out(t) for a
// clipping result K, x the clipper's tolerance: a vertex within tol of a
// cutting line is kept without moving (1 tol), plus the round-off of crossing
// points and of clean_polygon's chord test (< 1 tol).
inline constexpr double kSandwich = 2.0;
// Extra sandwich width for a rigidly moved input, x tol: the moved vertices
// and the moved result are rounded once more (a few eps C << tol).
inline constexpr double kMotionRounding = 1.0;
// Area of a split_polygon part, x (vertex count n + 2) x tol x diameter
// [area] (the intersection polygon's bound is the kernel's own promise,
// dda::kIpAreaBound in overlap.hpp, of the same form):
// each vertex decision (snap, crossing, clean) moves the boundary by <= tol
// along a chord no longer than the diameter.
inline constexpr double kClipArea = 1.0;
// Slack for a Hausdorff distance measured in double (support.hpp), x tol: its
// error is a few eps times the polygons' size (< tol / 16).
inline constexpr double kMeasureSlack = 0.125;

// Area moments, with g = g(P), perimeter L, diameter D, area S: the kernel's
// sums see each vertex perturbed by at most eps C (relative coordinates) and
// add n terms; g bounds that perturbation with a margin of 64. Moving the
// boundary by g changes the area by <= g L, the first moments by <= g L D (so
// the centroid by <= 2 g L D / S plus g for its final addition), and the
// second moments about the centroid by <= g L D^2 (the centroid shift enters
// only at second order, since int (x - xc) dS = 0).
inline constexpr double kMomentArea = 1.0;      // x g L            [area]
inline constexpr double kMomentCentroid = 2.0;  // x g L D / S, + g [length]
inline constexpr double kMomentSecond = 1.0;    // x g L D^2        [length^4]

// exit_distance vs its exact value, x g(P): n . (v - p) with a rounded unit
// normal and a difference of coordinates, a few eps (C + D).
inline constexpr double kExitTol = 1.0;
// Touching band of locate_point, x g(P): as kVerdictBand.
inline constexpr double kLocateBand = 2.0;

}  // namespace prop::tol
