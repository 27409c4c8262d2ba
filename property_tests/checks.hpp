// The checks behind every property, on explicit inputs, so that a property
// (properties.cpp, random inputs) and a regression test (regressions.cpp, a
// saved counterexample) run the same code. Each returns "" when the kernel
// passes and otherwise a message with the numbers that failed. Inputs must
// pass validate_polygon (the properties discard the rest with RC_PRE).
//
// What is checked, against CGAL's exact kernel (exact.hpp), with the
// tolerances of tolerances.hpp:
//  check_overlap       overlap_state(A,B) and (B,A) vs the exact contact
//                      (intersection area > 0 / boundaries meet / apart),
//                      outside the touching band |sigma| <= 2 tol, or
//                      touching for an exact overlap whose intersection
//                      shrunk by kSandwich tol is empty (a sliver); and
//                      kOverlapping iff overlap_and_intersection's IP is
//                      not empty, in both orders.
//  check_entrance      entrance_block(A,B,a0) vs the exact conv{b_j - a_i + a0}
//                      (Hausdorff), its edge lines support it, its normals are
//                      unit and outward, and every edge obeys the pair rule.
//  check_intersection  intersection_polygon(A,B) and (B,A): area vs the exact
//                      intersection area; strictly convex, CCW, simple (exact
//                      orientation of every vertex triple, winding once) with
//                      no edge <= tol; exact sandwich P_in(t) within IP within
//                      P_out(t); the two orders within Hausdorff H(P_out, P_in);
//                      every vertex within dda::kIpVertexReach tol of both
//                      inputs (Euclidean); area within
//                      dda::kIpAreaBound (n + m) tol D (overlap.hpp).
//                      validate_polygon is deliberately not required of an IP:
//                      its block thresholds (edges >= 1e-9 of the diameter,
//                      turns >= 1e-9) reject true intersections, e.g. of a
//                      polygon and its copy turned by 1e-12 rad (turns of
//                      1e-12) -- about 3% of the non-empty IPs generated.
//                      overlap_and_intersection, both orders: overlap_state's
//                      verdict and intersection_polygon's vertices bit for
//                      bit; each IP edge on its source edge's line (within
//                      kSandwich tol) with that edge's normal.
//  check_motion        IP of rigidly moved inputs = moved IP (Hausdorff).
//  check_moments       area_moments / area vs exact moments of the same vertices.
//  check_split         split_polygon: areas sum to the whole; each part is
//                      strictly convex, on its side, and sandwiched around the
//                      exact half-plane cut.
//  check_exit          exit_distance and locate_point vs exact values at the
//                      sample points; potential_gradient is the nearest edge's
//                      normal; the inscribed circle's radius equals the exit
//                      distance at its centre and bounds it everywhere.
#pragma once
#include <string>

#include "support.hpp"

namespace prop {

// `contact`, if given, receives the exact contact's name (for tagging cases).
std::string check_overlap(const Points& a, const Points& b, std::string* contact = nullptr);
std::string check_entrance(const Points& a, const Points& b, Vec2 a0);
std::string check_intersection(const Points& cp, const Points& tp);
std::string check_motion(const Points& cp, const Points& tp, const Motion& m);
std::string check_moments(const Points& p);
std::string check_split(const Points& p, const LineCase& line);
std::string check_exit(const Points& p, const Points& samples);

}  // namespace prop
