// Shared plumbing of the property tests: the printable input types that the
// generators produce and the checks consume, conversions to dda::Polygon, and
// plain double-precision geometry used only to *measure* distances between
// polygons (never to decide a verdict; verdicts use exact.hpp).
//
// Inputs print as compilable C++ initialisers with 17 significant digits, so
// a counterexample from rapidcheck can be pasted into regressions.cpp as is.
#pragma once
#include <iosfwd>
#include <string>
#include <vector>

#include "dda/polygon.hpp"

namespace prop {

using dda::Polygon;
using dda::Vec2;
using Points = std::vector<Vec2>;

// One polygon, CCW.
struct PolygonCase {
  Points v;
  std::string family;  // which generator made it (for tags and messages)
};

// Two polygons: A (the contact polygon, CP) and B (the target polygon, TP).
struct PairCase {
  Points a, b;
  std::string family;
};

// A cutting line: split_polygon's `below` side is normal . (x - point) <= 0.
struct LineCase {
  Vec2 point, normal;
  std::string family;
};

// Points at which a polygon is probed.
struct Samples {
  Points v;
};

// A proper rigid motion x -> centre + R(angle) (x - centre) + shift.
struct Motion {
  double angle = 0.0;
  Vec2 centre, shift;
  Vec2 apply(Vec2 p) const;
};

void showValue(const PolygonCase& c, std::ostream& os);
void showValue(const PairCase& c, std::ostream& os);
void showValue(const LineCase& c, std::ostream& os);
void showValue(const Motion& m, std::ostream& os);
void showValue(const Points& p, std::ostream& os);
void showValue(const Samples& s, std::ostream& os);

// "{{x, y}, {x, y}, ...}" with 17 significant digits (round-trips exactly).
std::string to_code(const Points& p);
std::string to_code(Vec2 p);

Polygon to_polygon(const Points& p);
Points points_of(const Polygon& poly);
// validate_polygon accepts p (the precondition of every property).
bool is_valid(const Points& p);

Points transformed(const Points& p, const Motion& m);

// ---- measurement in double (see the file comment) -------------------------
// Distance from q to segment [a, b].
double segment_distance(Vec2 q, Vec2 a, Vec2 b);
// Distance from q to the closed convex CCW polygon p (0 inside).
double region_distance(Vec2 q, const Points& p);
// Directed Hausdorff distance max_{x in from} d(x, to) between convex regions:
// the maximum is at a vertex of `from` because d(., to) is convex.
double directed_hausdorff(const Points& from, const Points& to);
double hausdorff(const Points& p, const Points& q);
// Largest |coordinate| and diameter of the vertex set.
double max_abs_coordinate(const Points& p);
double diameter_of(const Points& p);

}  // namespace prop
