// Paper A Sect. 3.2.2: the potential grids of both figures, their files and
// the grid statistics the checks read (potential_fields.hpp).
#include <algorithm>
#include <cmath>
#include <limits>

#include "repro/3_2_2_potential_fields/potential_fields.hpp"

namespace potential_fields {

Grid make_grid(const std::vector<Vec2>& pts) {
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

void write_grid(const std::string& path, const Grid& g, std::vector<std::string> comments) {
  comments.push_back("grid nx=" + std::to_string(g.nx) + " ny=" + std::to_string(g.ny) + " spacing_m=" +
                     repro::format_full(g.h) + "; rows y-major (x varies fastest); phi in Pa, lengths in m");
  struct Point {
    int i, j;
  };
  const auto at = [&g](Point p) { return g.at(p.i, p.j); };
  const auto k = [&g](Point p) { return g.idx(p.i, p.j); };
  std::vector<Point> points;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) points.push_back({i, j});
  repro::write_table<Point>(path,
                            {{"x", [&](Point p) { return at(p).x; }},
                             {"y", [&](Point p) { return at(p).y; }},
                             {"inside", [&](Point p) { return g.inside[k(p)] != 0; }},
                             {"d_exit", [&](Point p) { return g.d_exit[k(p)]; }},
                             {"phi", [&](Point p) { return g.phi[k(p)]; }}},
                            points, comments);
}

void write_outline(const std::string& path, const std::vector<Vec2>& pts, const std::vector<std::string>& comments) {
  std::vector<std::size_t> vertices(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) vertices[i] = i;
  repro::write_table<std::size_t>(
      path,
      {{"vertex", [](std::size_t i) { return i; }},
       {"x", [&pts](std::size_t i) { return pts[i].x; }},
       {"y", [&pts](std::size_t i) { return pts[i].y; }},
       {"edge_length", [&pts](std::size_t i) { return dda::distance(pts[i], pts[(i + 1) % pts.size()]); }}},
      vertices, comments);
}

// Max |phi| at points sampled along every edge (vertices included).
double boundary_max_abs(const std::vector<Vec2>& pts, const Field& phi) {
  double m = 0.0;
  for (std::size_t e = 0; e < pts.size(); ++e)
    for (int s = 0; s <= kBoundarySamples; ++s) {
      const Vec2 p = dda::lerp(pts[e], pts[(e + 1) % pts.size()], static_cast<double>(s) / kBoundarySamples);
      const double v = phi(p);
      m = std::isfinite(v) ? std::max(m, std::fabs(v)) : std::numeric_limits<double>::infinity();
    }
  return m;
}

InteriorStats interior_stats(const Grid& g) {
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
double max_slope(const Grid& g) {
  double m = 0.0;
  for (int j = 0; j < g.ny; ++j)
    for (int i = 0; i < g.nx; ++i) {
      const double v = g.phi[g.idx(i, j)];
      if (i + 1 < g.nx) m = std::max(m, std::fabs(g.phi[g.idx(i + 1, j)] - v) / g.h);
      if (j + 1 < g.ny) m = std::max(m, std::fabs(g.phi[g.idx(i, j + 1)] - v) / g.h);
    }
  return m;
}

// Fig. 4b field: Eqs. 13-14 (dda::exit_distance, dda::potential) on the
// convex polygon pts; inside from dda::locate_point.
Grid convex_grid(const std::vector<Vec2>& pts) {
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
Grid concave_grid(const std::vector<Vec2>& pts) {
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

}  // namespace potential_fields
