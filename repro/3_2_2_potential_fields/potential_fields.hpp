// Paper A Sect. 3.2.2 (potential_fields.cpp says what it reproduces): the
// reconstructed polygons (geometry.cpp), the potential grids (fields.cpp)
// and the criteria of every check row (checks.cpp), declared here so that
// the negative controls (controls.cpp beside it) apply the same criteria
// to a deliberately wrong field or polygon.
#pragma once
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

#include "dda/polygon.hpp"
#include "dda/potential.hpp"
#include "repro/common/common.hpp"

namespace potential_fields {

using dda::Vec2;
using repro::Claim;
using repro::format_short;

constexpr double kKn = 1.0;  // Pa, Paper A Sect. 3.2.2
constexpr double kH = 1.0;   // m
constexpr int kGridCells = 300;        // grid cells along the longer side
constexpr int kBoundarySamples = 200;  // samples per edge for the boundary check
const char* const kSection = "3.2.2";
// The negative control of the checks every field gets (add_common_claims).
const char* const kFieldControl =
    "repro_controls: 3.2.2 potential field: FAIL on an offset, a shifted and a doubled field";
// The negative controls of the figure-specific rows (controls.cpp).
inline const char* const kControlPenetration = "3.2.2 Fig. 4b equal penetration: FAIL with H set to each edge's length";
inline const char* const kControlEdgeLines =
    "3.2.2 Fig. 4b edge lines = shortest distance: FAIL on the concave Fig. 5 polygon";
inline const char* const kControlInscribed = "3.2.2 Fig. 4b largest potential: FAIL with H halved in the field";
inline const char* const kControlNearest =
    "3.2.2 Fig. 5 nearest boundary point: FAIL with the edge-line formula as the field";
inline const char* const kControlConcaveLines =
    "3.2.2 Fig. 5 edge lines fail on the concave polygon: FAIL on the convex Fig. 4b polygon";
constexpr double kPenetrationTolerance = 1e-9;  // relative
constexpr double kLineTolerance = 1e-12;        // m
constexpr double kSampleSpacing = 5e-4;         // m: boundary samples of the nearest-point check

// ---- geometry (geometry.cpp) ---------------------------------------------------

// Replaces corner i of a closed polyline by two points on its neighbouring
// edges so that the new (cut) edge has length `len`.
std::vector<Vec2> cut_corner(const std::vector<Vec2>& pts, std::size_t i, double len);
// (a) Reconstructed Fig. 4b polygon: a ~1.2 m convex pentagon whose corners
// 1 and 3 are cut by edges of 0.03 m and 0.05 m.
std::vector<Vec2> small_edge_polygon();
// (b) Reconstructed Fig. 5 polygon: simple, CCW, 13 vertices, 4 reflex.
std::vector<Vec2> concave_polygon();
double segment_distance(Vec2 p, Vec2 a, Vec2 b);
// Shortest distance from p to the boundary of the closed polygon `pts`.
double boundary_distance(const std::vector<Vec2>& pts, Vec2 p);
// Crossing-number point-in-polygon test (any simple polygon).
bool inside_simple(const std::vector<Vec2>& pts, Vec2 p);
double signed_area(const std::vector<Vec2>& pts);
bool segments_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d);
// Throws unless the polygon is simple (no two non-adjacent edges cross) and CCW.
void check_simple_ccw(const std::vector<Vec2>& pts);
int reflex_count(const std::vector<Vec2>& pts);
// Eqs. 13-14 applied to any polygon (edge lines): min_i n_i . (v_i - p).
double edge_line_distance(const std::vector<Vec2>& pts, Vec2 p);

// ---- fields (fields.cpp) ---------------------------------------------------------

struct Grid {
  int nx = 0, ny = 0;
  double x0 = 0, y0 = 0, h = 0;
  std::vector<double> d_exit, phi;
  std::vector<char> inside;
  Vec2 at(int i, int j) const { return {x0 + i * h, y0 + j * h}; }
  std::size_t idx(int i, int j) const { return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i); }
};

// A potential as a function of the point (Pa).
using Field = std::function<double(Vec2)>;

// The grid around pts: kGridCells along the longer side plus a 4 % margin.
Grid make_grid(const std::vector<Vec2>& pts);
// Fig. 4b field: Eqs. 13-14 (dda::exit_distance, dda::potential) on the convex polygon.
Grid convex_grid(const std::vector<Vec2>& pts);
// Fig. 5 field: the shortest distance to the boundary segments.
Grid concave_grid(const std::vector<Vec2>& pts);
void write_grid(const std::string& path, const Grid& g, std::vector<std::string> comments);
void write_outline(const std::string& path, const std::vector<Vec2>& pts, const std::vector<std::string>& comments);

// Max |phi| at points sampled along every edge (vertices included).
double boundary_max_abs(const std::vector<Vec2>& pts, const Field& phi);
struct InteriorStats {
  long interior = 0, undefined = 0;  // undefined: phi <= 0 or non-finite
  double min_phi = std::numeric_limits<double>::infinity();
  double max_phi = 0.0;
};

InteriorStats interior_stats(const Grid& g);
// Largest |phi(neighbour) - phi| / spacing over adjacent grid points.
double max_slope(const Grid& g);

// ---- check rows (checks.cpp) -------------------------------------------------------

std::string figure_tag(const std::string& fig);
// The rows every field gets: zero on the boundary and positive inside,
// defined everywhere inside, slope at most kn/H.
void add_common_claims(std::vector<Claim>& claims, const std::string& fig, const Grid& g, double bmax);
// Fig. 4b: phi at depth delta = min edge / 4 below every edge midpoint
// equals kn delta / H (relative deviation <= 1e-9).
Claim equal_penetration_row(const dda::Polygon& poly, const Field& phi);
// Fig. 4b: the grid's d_exit (Eqs. 13-14) equals the distance to the
// boundary segments of pts at every interior grid point (<= 1e-12 m).
Claim edge_lines_row(const std::vector<Vec2>& pts, const Grid& g);
// Fig. 4b: the grid's largest phi lies within one grid step below kn r / H
// (r the inscribed radius of poly), and phi(centre) = kn r / H.
Claim inscribed_row(const dda::Polygon& poly, const Grid& g, const Field& phi);
// Fig. 5: the grid's phi equals kn/H times the distance to a dense sampling
// of the boundary of pts at every third interior grid point.
Claim nearest_point_row(const std::vector<Vec2>& pts, const Grid& g);
// Fig. 5: Eqs. 13-14 applied blindly to pts give d_exit <= 0 at some
// interior grid point of g.
Claim concave_lines_row(const std::vector<Vec2>& pts, const Grid& g);

}  // namespace potential_fields
