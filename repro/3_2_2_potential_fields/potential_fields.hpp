// Paper A Sect. 3.2.2 (potential_fields.cpp says what it reproduces): the
// reconstructed polygons, the potential grids and the checks shared by both
// figures and the criteria of every check row, here so that the negative
// controls (repro/common/test_controls.cpp, controls_geometry.cpp) apply the
// same criteria to a deliberately wrong field or polygon.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
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
// The negative controls of the figure-specific rows (controls_geometry.cpp).
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

// ---- geometry -------------------------------------------------------------

// Replaces corner i of a closed polyline by two points on its neighbouring
// edges so that the new (cut) edge has length `len`.
inline std::vector<Vec2> cut_corner(const std::vector<Vec2>& pts, std::size_t i, double len) {
  const std::size_t n = pts.size();
  const Vec2 v = pts[i], a = pts[(i + n - 1) % n], b = pts[(i + 1) % n];
  const Vec2 ua = dda::normalized(a - v), ub = dda::normalized(b - v);
  const double t = len / dda::length(ua - ub);
  std::vector<Vec2> out;
  for (std::size_t k = 0; k < n; ++k) {
    if (k == i) {
      out.push_back(v + t * ua);
      out.push_back(v + t * ub);
    } else {
      out.push_back(pts[k]);
    }
  }
  return out;
}

// (a) Reconstructed Fig. 4b polygon: a ~1.2 m convex pentagon whose corners
// 1 and 3 are cut by edges of 0.03 m and 0.05 m.
inline std::vector<Vec2> small_edge_polygon() {
  std::vector<Vec2> p = {{0.0, 0.0}, {1.0, -0.05}, {1.15, 0.55}, {0.55, 1.0}, {-0.1, 0.65}};
  p = cut_corner(p, 3, 0.05);  // cut the later corner first: indices below stay valid
  p = cut_corner(p, 1, 0.03);
  return p;
}

// (b) Reconstructed Fig. 5 polygon: simple, CCW, 13 vertices, 4 reflex.
inline std::vector<Vec2> concave_polygon() {
  return {{0.0, 0.0},  {0.55, 0.05}, {0.7, 0.35},  {0.85, 0.1}, {1.3, 0.15}, {1.2, 0.5},  {0.95, 0.55},
          {1.25, 0.95}, {0.75, 1.1},  {0.55, 0.75}, {0.3, 1.05}, {-0.05, 0.8}, {0.2, 0.5}};
}

inline double segment_distance(Vec2 p, Vec2 a, Vec2 b) {
  const Vec2 e = b - a;
  const double ee = dda::dot(e, e);
  const double t = ee > 0.0 ? std::clamp(dda::dot(p - a, e) / ee, 0.0, 1.0) : 0.0;
  return dda::distance(p, a + t * e);
}

// Shortest distance from p to the boundary of the closed polygon `pts`.
inline double boundary_distance(const std::vector<Vec2>& pts, Vec2 p) {
  double d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < pts.size(); ++i) d = std::min(d, segment_distance(p, pts[i], pts[(i + 1) % pts.size()]));
  return d;
}

// Crossing-number point-in-polygon test (any simple polygon).
inline bool inside_simple(const std::vector<Vec2>& pts, Vec2 p) {
  bool in = false;
  for (std::size_t i = 0, j = pts.size() - 1; i < pts.size(); j = i++) {
    const Vec2 a = pts[i], b = pts[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

inline double signed_area(const std::vector<Vec2>& pts) {
  double s = 0.0;
  for (std::size_t i = 0; i < pts.size(); ++i) s += dda::cross(pts[i], pts[(i + 1) % pts.size()]);
  return 0.5 * s;
}

inline bool segments_cross(Vec2 a, Vec2 b, Vec2 c, Vec2 d) {
  const double o1 = dda::cross(b - a, c - a), o2 = dda::cross(b - a, d - a);
  const double o3 = dda::cross(d - c, a - c), o4 = dda::cross(d - c, b - c);
  return ((o1 > 0) != (o2 > 0)) && ((o3 > 0) != (o4 > 0));
}

// Throws unless the polygon is simple (no two non-adjacent edges cross) and CCW.
inline void check_simple_ccw(const std::vector<Vec2>& pts) {
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i)
    for (std::size_t j = i + 2; j < n; ++j) {
      if (i == 0 && j == n - 1) continue;  // adjacent through vertex 0
      if (segments_cross(pts[i], pts[(i + 1) % n], pts[j], pts[(j + 1) % n]))
        throw std::runtime_error("concave polygon: edges " + std::to_string(i) + " and " + std::to_string(j) + " cross");
    }
  if (signed_area(pts) <= 0.0) throw std::runtime_error("concave polygon: not counter-clockwise");
}

inline int reflex_count(const std::vector<Vec2>& pts) {
  int r = 0;
  const std::size_t n = pts.size();
  for (std::size_t i = 0; i < n; ++i)
    if (dda::cross(pts[i] - pts[(i + n - 1) % n], pts[(i + 1) % n] - pts[i]) < 0.0) ++r;
  return r;
}

// ---- fields ----------------------------------------------------------------

struct Grid {
  int nx = 0, ny = 0;
  double x0 = 0, y0 = 0, h = 0;
  std::vector<double> d_exit, phi;
  std::vector<char> inside;
  Vec2 at(int i, int j) const { return {x0 + i * h, y0 + j * h}; }
  std::size_t idx(int i, int j) const { return static_cast<std::size_t>(j) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(i); }
};

inline Grid make_grid(const std::vector<Vec2>& pts) {
  Vec2 lo{1e300, 1e300}, hi{-1e300, -1e300};
  for (Vec2 p : pts) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
  }
  const double span = std::max(hi.x - lo.x, hi.y - lo.y);
  const double margin = 0.04 * span;
  Grid g;
  g.h = (span + 2 * margin) / kGridCells;
  g.x0 = lo.x - margin;
  g.y0 = lo.y - margin;
  g.nx = static_cast<int>(std::ceil((hi.x - lo.x + 2 * margin) / g.h)) + 1;
  g.ny = static_cast<int>(std::ceil((hi.y - lo.y + 2 * margin) / g.h)) + 1;
  const std::size_t n = static_cast<std::size_t>(g.nx) * static_cast<std::size_t>(g.ny);
  g.d_exit.assign(n, 0.0);
  g.phi.assign(n, 0.0);
  g.inside.assign(n, 0);
  return g;
}

inline void write_grid(const std::string& path, const Grid& g, std::vector<std::string> comments) {
  comments.push_back("grid nx=" + std::to_string(g.nx) + " ny=" + std::to_string(g.ny) + " spacing_m=" +
                     repro::format_full(g.h) + "; rows y-major (x varies fastest); phi in Pa, lengths in m");
  repro::CsvWriter w(path, {"x", "y", "inside", "d_exit", "phi"}, comments);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Vec2 p = g.at(i, j);
      const std::size_t k = g.idx(i, j);
      w.row({p.x, p.y, g.inside[k] ? 1.0 : 0.0, g.d_exit[k], g.phi[k]});
    }
  w.commit();
}

inline void write_outline(const std::string& path, const std::vector<Vec2>& pts, const std::vector<std::string>& comments) {
  repro::CsvWriter w(path, {"vertex", "x", "y", "edge_length"}, comments);
  for (std::size_t i = 0; i < pts.size(); ++i)
    w.row({static_cast<double>(i), pts[i].x, pts[i].y, dda::distance(pts[i], pts[(i + 1) % pts.size()])});
  w.commit();
}

// ---- checks shared by both polygons -----------------------------------------

// Max |phi| at points sampled along every edge (vertices included).
template <class Phi>
inline double boundary_max_abs(const std::vector<Vec2>& pts, Phi phi) {
  double m = 0.0;
  for (std::size_t e = 0; e < pts.size(); ++e)
    for (int s = 0; s <= kBoundarySamples; ++s) {
      const Vec2 p = dda::lerp(pts[e], pts[(e + 1) % pts.size()], static_cast<double>(s) / kBoundarySamples);
      const double v = phi(p);
      m = std::isfinite(v) ? std::max(m, std::fabs(v)) : std::numeric_limits<double>::infinity();
    }
  return m;
}

struct InteriorStats {
  long interior = 0, undefined = 0;  // undefined: phi <= 0 or non-finite
  double min_phi = std::numeric_limits<double>::infinity();
  double max_phi = 0.0;
};

inline InteriorStats interior_stats(const Grid& g) {
  InteriorStats s;
  for (std::size_t k = 0; k < g.phi.size(); ++k) {
    if (!g.inside[k]) continue;
    ++s.interior;
    const double v = g.phi[k];
    if (!std::isfinite(v) || v <= 0.0) ++s.undefined;
    if (std::isfinite(v)) {
      s.min_phi = std::min(s.min_phi, v);
      s.max_phi = std::max(s.max_phi, v);
    }
  }
  return s;
}

// Largest |phi(neighbour) - phi| / spacing over horizontally and vertically
// adjacent grid points (inside and outside): the continuity / slope check.
inline double max_slope(const Grid& g) {
  double m = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double v = g.phi[g.idx(i, j)];
      if (i + 1 < g.nx) m = std::max(m, std::fabs(g.phi[g.idx(i + 1, j)] - v) / g.h);
      if (j + 1 < g.ny) m = std::max(m, std::fabs(g.phi[g.idx(i, j + 1)] - v) / g.h);
    }
  return m;
}

inline std::string figure_tag(const std::string& fig) { return fig + " (reconstructed polygon)"; }

inline void add_common_claims(std::vector<Claim>& claims, const std::string& fig, const Grid& g, double bmax) {
  const InteriorStats s = interior_stats(g);
  const double zero_tol = 1e-12 * kKn / kH;  // round-off of a unit-size coordinate difference
  claims.push_back({kSection, figure_tag(fig) + ": potential is zero on the boundary and positive inside",
                    "'the potential values of any points on polygon boundary should be equal and the definition "
                    "satisfies this requirement' (Sect. 3.2.2, Eq. 12)",
                    "max |phi| on boundary = " + format_short(bmax, 3) + " Pa; min phi at " +
                        std::to_string(s.interior) + " interior grid points = " + format_short(s.min_phi, 4) + " Pa",
                    "boundary <= " + format_short(zero_tol, 2) + " Pa; interior min > 0",
                    bmax <= zero_tol && s.interior > 0 && s.min_phi > 0.0});
  claims.back().control = kFieldControl;
  claims.back().scope = repro::Scope::kPaper;
  claims.push_back({kSection, figure_tag(fig) + ": every interior point has a defined potential (no undefined inner region)",
                    "'the proposed definition ensures the potential value can be obtained for each point inside a "
                    "polygon' (Sect. 3.2.2, Fig. 4)",
                    std::to_string(s.undefined) + " of " + std::to_string(s.interior) +
                        " interior grid points with phi <= 0 or non-finite",
                    "0 points", s.interior > 0 && s.undefined == 0});
  claims.back().control = kFieldControl;
  claims.back().scope = repro::Scope::kPaper;
  const double slope = max_slope(g);
  claims.push_back({kSection, figure_tag(fig) + ": phi is continuous with slope at most kn/H",
                    "d_exit is a shortest distance, so it changes no faster than p moves (kn/H = 1 Pa/m)",
                    "max |finite difference| over " + std::to_string(g.nx) + "x" + std::to_string(g.ny) +
                        " grid = " + format_short(slope, 6) + " Pa/m",
                    "<= kn/H * (1 + 1e-9)", slope <= (kKn / kH) * (1.0 + 1e-9)});
  claims.back().control = kFieldControl;
  claims.back().scope = repro::Scope::kExtension;  // a property Eqs. 12-14 imply, not a statement of the paper
}

// ---- figure-specific checks --------------------------------------------------

// Fig. 4b field: Eqs. 13-14 (dda::exit_distance, dda::potential) on the
// convex polygon pts; inside from dda::locate_point.
inline Grid convex_grid(const std::vector<Vec2>& pts) {
  const dda::Polygon poly = dda::make_polygon(pts.data(), static_cast<int>(pts.size()));
  Grid g = make_grid(pts);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Vec2 p = g.at(i, j);
      const std::size_t k = g.idx(i, j);
      g.inside[k] = dda::locate_point(poly, p) == dda::PointLocation::kInside;
      g.d_exit[k] = dda::exit_distance(poly, p);
      g.phi[k] = dda::potential(poly, p, kKn, kH);
    }
  return g;
}

// Fig. 5 field: d_exit = shortest distance to the boundary segments (signed,
// negative outside), phi = kn d_exit / H inside, 0 outside.
inline Grid concave_grid(const std::vector<Vec2>& pts) {
  Grid g = make_grid(pts);
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const Vec2 p = g.at(i, j);
      const std::size_t k = g.idx(i, j);
      const double dist = boundary_distance(pts, p);
      const bool in = inside_simple(pts, p) && dist > 0.0;
      g.inside[k] = in;
      g.d_exit[k] = in ? dist : -dist;
      g.phi[k] = in ? kKn * dist / kH : 0.0;
    }
  return g;
}

// Eqs. 13-14 applied to any polygon (edge lines): min_i n_i . (v_i - p).
inline double edge_line_distance(const std::vector<Vec2>& pts, Vec2 p) {
  double dl = std::numeric_limits<double>::infinity();
  for (std::size_t e = 0; e < pts.size(); ++e) {
    const Vec2 a = pts[e], b = pts[(e + 1) % pts.size()];
    dl = std::min(dl, dda::dot(dda::normalized(dda::perp_right(b - a)), a - p));
  }
  return dl;
}

// Fig. 4b: phi at depth delta = min edge / 4 below every edge midpoint
// equals kn delta / H (relative deviation <= 1e-9).
template <class Phi>
inline Claim equal_penetration_row(const dda::Polygon& poly, Phi phi) {
  double min_edge = std::numeric_limits<double>::infinity(), max_edge = 0.0;
  for (int i = 0; i < poly.count; ++i) {
    min_edge = std::min(min_edge, dda::length(poly.edge(i)));
    max_edge = std::max(max_edge, dda::length(poly.edge(i)));
  }
  const double delta = 0.25 * min_edge;
  double worst_rel = 0.0;
  for (int i = 0; i < poly.count; ++i) {
    const Vec2 mid = 0.5 * (poly.vertex(i) + poly.vertex(poly.next(i)));
    const double v = phi(mid - delta * poly.normal(i));
    worst_rel = std::max(worst_rel, std::fabs(v - kKn * delta / kH) / (kKn * delta / kH));
  }
  Claim c{kSection, figure_tag("Fig. 4b") + ": the same penetration below any edge, small edges included, gives the same potential",
          "'with the same H value ... it ensures the contact potential of the points with the same penetrations "
          "keeps equal' (Sect. 3.2.2)",
          "max relative deviation from kn*delta/H at delta = " + format_short(delta, 3) + " m below the " +
              std::to_string(poly.count) + " edge midpoints (edges " + format_short(min_edge, 3) + " to " +
              format_short(max_edge, 3) + " m) = " + format_short(worst_rel, 3),
          "<= 1e-9", worst_rel <= kPenetrationTolerance};
  c.control = std::string("repro_controls: ") + kControlPenetration;
  return c;
}

// Fig. 4b: the grid's d_exit (Eqs. 13-14) equals the distance to the boundary
// segments of pts at every interior grid point (<= 1e-12 m).
inline Claim edge_lines_row(const std::vector<Vec2>& pts, const Grid& g) {
  double line_vs_segment = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const std::size_t k = g.idx(i, j);
      if (g.inside[k])
        line_vs_segment = std::max(line_vs_segment, std::fabs(g.d_exit[k] - boundary_distance(pts, g.at(i, j))));
    }
  Claim c{kSection, figure_tag("Fig. 4b") + ": Eqs. 13-14 (edge lines) equal the shortest distance to the boundary",
          "'Using this definition for convex polygons, the shortest distance ... can be obtained by' Eq. 13 "
          "(Sect. 3.2.2)",
          "max |d_exit - distance to boundary segments| at interior grid points = " + format_short(line_vs_segment, 3) +
              " m",
          "<= 1e-12 m", line_vs_segment <= kLineTolerance};
  c.control = std::string("repro_controls: ") + kControlEdgeLines;
  return c;
}

// Fig. 4b: the grid's largest phi lies within one grid step (kn h / H) below
// kn r / H, r the inscribed radius of poly, and phi(centre) = kn r / H.
template <class Phi>
inline Claim inscribed_row(const dda::Polygon& poly, const Grid& g, Phi phi) {
  const dda::InscribedCircle ic = dda::inscribed_circle(poly);
  const double phi_max_grid = interior_stats(g).max_phi, phi_ic = kKn * ic.radius / kH;
  const double phi_at_centre = phi(ic.centre);
  const bool ic_ok = phi_max_grid <= phi_ic * (1 + 1e-12) && phi_max_grid >= phi_ic - kKn * g.h / kH &&
                     std::fabs(phi_at_centre - phi_ic) <= 1e-12;
  Claim c{kSection, figure_tag("Fig. 4b") + ": the largest potential is kn*r/H at the inscribed-circle centre",
          "follows from Eqs. 12-14 (max of d_exit = inscribed radius r)",
          "r = " + format_short(ic.radius, 6) + " m; phi(centre) = " + format_short(phi_at_centre, 6) +
              " Pa; grid max = " + format_short(phi_max_grid, 6) + " Pa",
          "grid max in [kn*r/H - kn*h/H, kn*r/H], h = " + format_short(g.h, 3) + " m", ic_ok};
  c.control = std::string("repro_controls: ") + kControlInscribed;
  return c;
}

// Fig. 5: the grid's phi equals kn/H times the distance to a dense sampling
// of the boundary of pts (spacing <= kSampleSpacing) at every third interior
// grid point, within kn/H times half the sample spacing: an independent
// evaluation of the nearest boundary point.
inline Claim nearest_point_row(const std::vector<Vec2>& pts, const Grid& g) {
  std::vector<Vec2> samples;
  double max_seg = 0.0;  // largest gap between consecutive samples
  for (std::size_t e = 0; e < pts.size(); ++e) {
    const Vec2 a = pts[e], b = pts[(e + 1) % pts.size()];
    const int n = std::max(1, static_cast<int>(std::ceil(dda::distance(a, b) / kSampleSpacing)));
    max_seg = std::max(max_seg, dda::distance(a, b) / n);
    for (int s = 0; s < n; ++s) samples.push_back(dda::lerp(a, b, static_cast<double>(s) / n));
  }
  double worst_sample = 0.0;
  long checked = 0;
  for (int j = 0; j < g.ny; j += 3)
    for (int i = 0; i < g.nx; i += 3) {
      const std::size_t k = g.idx(i, j);
      if (!g.inside[k]) continue;
      double ds = std::numeric_limits<double>::infinity();
      for (Vec2 q : samples) ds = std::min(ds, dda::distance(g.at(i, j), q));
      worst_sample = std::max(worst_sample, std::fabs(kKn * ds / kH - g.phi[k]));
      ++checked;
    }
  Claim c{kSection, figure_tag("Fig. 5") + ": phi equals kn/H times the distance to the nearest boundary point",
          "'a point penetrated in a polygon will always be pushed out along the shortest path' (Sect. 3.2.2, Fig. 5)",
          "max |phi - kn/H * distance to " + std::to_string(samples.size()) + " boundary samples| at " +
              std::to_string(checked) + " interior points = " + format_short(worst_sample, 3) + " Pa",
          "<= kn/H * half the sample spacing = " + format_short(kKn * max_seg / (2 * kH), 3) + " Pa",
          checked > 0 && worst_sample <= kKn * max_seg / (2 * kH) * (1 + 1e-9)};
  c.control = std::string("repro_controls: ") + kControlNearest;
  return c;
}

// Fig. 5: Eqs. 13-14 applied blindly to pts give d_exit <= 0 at some interior
// grid point of g (so the shortest-distance evaluation is needed).
inline Claim concave_lines_row(const std::vector<Vec2>& pts, const Grid& g) {
  long fails = 0, interior = 0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      if (!g.inside[g.idx(i, j)]) continue;
      ++interior;
      if (edge_line_distance(pts, g.at(i, j)) <= 0.0) ++fails;
    }
  Claim c{kSection, figure_tag("Fig. 5") + ": Eqs. 13-14 (edge lines) alone do not give the concave potential",
          "'obtained by decomposing the concave polygon into six convex ones' (Sect. 3.2.2, Fig. 5): Eq. 13 is "
          "stated for convex polygons",
          std::to_string(fails) + " of " + std::to_string(interior) +
              " interior grid points get d_exit <= 0 from the edge-line formula",
          "> 0 points (the convex formula fails, so the shortest-distance evaluation is needed)", fails > 0};
  c.control = std::string("repro_controls: ") + kControlConcaveLines;
  return c;
}

}  // namespace potential_fields
