// Paper A Sect. 3.2.2, Fig. 4a (previous_potential.cpp says what it
// reproduces): the reconstructed "previous sub-polygon" potential, its grid
// scan and the criteria of the check rows, here so that the negative controls
// (controls.cpp beside this file) apply the same criteria to a
// deliberately wrong configuration.
#pragma once
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "dda/polygon.hpp"
#include "dda/potential.hpp"
#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/claims.hpp"
#include "repro/common/table.hpp"

namespace previous_potential {

using dda::Vec2;
using repro::format_short;
constexpr double kKn = 1.0, kH = 1.0;
constexpr int kGridCells = 300;
constexpr double kLargeUndefined = 0.10;   // "a large inner part": more than 10 % of the area
constexpr double kRatioTolerance = 1e-9;   // hexagon: d* / inscribed radius = 1 within this
constexpr double kMismatchTolerance = 1e-12;  // Pa: previous = shortest-exit where defined

// The negative controls of the check rows (test names in repro_controls).
inline const char* const kControlUndefined =
    "3.2.2 Fig. 4a undefined part: FAIL on a regular hexagon (no small edge)";
inline const char* const kControlHexagon =
    "3.2.2 Fig. 4a hexagon control: FAIL when the hexagon is replaced by the Fig. 4a polygon";
inline const char* const kControlMismatch =
    "3.2.2 Fig. 4a previous = shortest exit: FAIL with sub-polygons offset to the inscribed radius";
inline const char* const kControlImpact = "3.2.2 / 5.3 impact beyond d*: FAIL when kn is 100 times too stiff";

// The reconstructed sub-polygons: sub[i] = {v_i, v_i+1, inner_i+1, inner_i}.
struct SubPolygons {
  double depth = 0.0;  // d*
  std::vector<std::vector<Vec2>> sub;
};

// Sub-polygon i: edge i, the bisectors at its ends and the inward offset by
// `depth`; depth < 0: d*, where the first edge shrinks to a point.
inline SubPolygons sub_polygons(const dda::Polygon& p, double depth = -1.0) {
  const int n = p.count;
  std::vector<Vec2> dir(static_cast<std::size_t>(n));
  std::vector<double> half(static_cast<std::size_t>(n));  // half interior angle
  for (int k = 0; k < n; ++k) {
    const Vec2 a = p.normal(p.prev(k)), b = p.normal(k);
    dir[k] = dda::normalized(-1.0 * (a + b));
    // Interior angle = pi - turn; the half angle from the normals.
    half[k] = 0.5 * (M_PI - std::atan2(dda::cross(a, b), dda::dot(a, b)));
  }
  SubPolygons s;
  s.depth = std::numeric_limits<double>::infinity();
  for (int i = 0; i < n; ++i) {
    const double h = dda::length(p.edge(i)) / (1.0 / std::tan(half[i]) + 1.0 / std::tan(half[p.next(i)]));
    s.depth = std::min(s.depth, h);
  }
  if (depth >= 0.0) s.depth = depth;
  for (int i = 0; i < n; ++i) {
    const int j = p.next(i);
    s.sub.push_back({p.vertex(i), p.vertex(j), p.vertex(j) + (s.depth / std::sin(half[j])) * dir[j],
                     p.vertex(i) + (s.depth / std::sin(half[i])) * dir[i]});
  }
  return s;
}

// Point in a (possibly degenerate) convex quadrilateral, CCW: all cross >= -eps.
inline bool inside_quad(const std::vector<Vec2>& q, Vec2 x) {
  for (std::size_t k = 0; k < q.size(); ++k) {
    const Vec2 a = q[k], b = q[(k + 1) % q.size()];
    if (dda::length(b - a) < 1e-15) continue;
    if (dda::cross(b - a, x - a) < -1e-12) return false;
  }
  return true;
}

// The grid scan of the previous potential beside the shortest-exit one.
struct FieldScan {
  long inside = 0, defined = 0;
  double mismatch = 0.0;  // max |phi_previous - phi_current| where defined
  double undefined() const {
    return inside > 0 ? 1.0 - static_cast<double>(defined) / static_cast<double>(inside) : 0.0;
  }
};

// One grid point of fig04a_grid.csv: inside the polygon or not, the
// sub-polygon holding it (-1: none, the previous potential undefined) and
// both potentials.
struct GridPoint {
  Vec2 p;
  bool inside;
  int owner;
  double phi_previous, phi_current;
};
inline std::vector<repro::Column<GridPoint>> grid_columns() {
  return {{"x", [](const GridPoint& g) { return g.p.x; }},
          {"y", [](const GridPoint& g) { return g.p.y; }},
          {"inside", [](const GridPoint& g) { return g.inside; }},
          {"defined", [](const GridPoint& g) { return g.owner >= 0; }},
          {"subpolygon", [](const GridPoint& g) { return g.owner; }},
          {"phi_previous", [](const GridPoint& g) { return g.phi_previous; }},
          {"phi_current", [](const GridPoint& g) { return g.phi_current; }}};
}

// Scans a kGridCells grid over poly (y outer, x inner, as the potential_fields
// driver); its points go to `grid` if given.
inline FieldScan scan_field(const dda::Polygon& poly, const SubPolygons& sp, repro::TableWriter<GridPoint>* grid) {
  const dda::Aabb box = dda::bounds(poly);
  const double span = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y), margin = 0.04 * span;
  const double h = (span + 2 * margin) / kGridCells;
  const int nx = static_cast<int>(std::ceil((box.hi.x - box.lo.x + 2 * margin) / h)) + 1;
  const int ny = static_cast<int>(std::ceil((box.hi.y - box.lo.y + 2 * margin) / h)) + 1;
  FieldScan f;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const Vec2 p{box.lo.x - margin + i * h, box.lo.y - margin + j * h};
      const bool in = dda::locate_point(poly, p) == dda::PointLocation::kInside;
      int owner = -1;
      double phi_prev = 0.0;
      if (in)
        for (std::size_t k = 0; k < sp.sub.size(); ++k)
          if (inside_quad(sp.sub[k], p)) {
            owner = static_cast<int>(k);
            phi_prev = kKn * dda::dot(poly.normal(owner), poly.vertex(owner) - p) / kH;
            break;
          }
      const double phi_cur = dda::potential(poly, p, kKn, kH);
      f.inside += in ? 1 : 0;
      f.defined += owner >= 0 ? 1 : 0;
      if (owner >= 0) f.mismatch = std::max(f.mismatch, std::fabs(phi_prev - phi_cur));
      if (grid) grid->row({p, in, owner, phi_prev, phi_cur});
    }
  return f;
}

// The control polygon of the hexagon row: a regular hexagon of circumradius 1 m.
inline dda::Polygon regular_hexagon() {
  std::vector<Vec2> hex;
  for (int k = 0; k < 6; ++k) hex.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3)});
  return dda::make_polygon(hex.data(), 6);
}

// d* / inscribed radius (1 for a regular polygon: nothing undefined).
inline double depth_ratio(const dda::Polygon& poly) {
  return sub_polygons(poly).depth / dda::inscribed_circle(poly).radius;
}

// How deep the 5.3 impact on the small edge reaches into the lower block.
struct Impact {
  double lower_depth = 0.0;  // the lower block's d*, m
  double deepest = 0.0;      // deepest IP vertex in the lower block (a lower bound of the IP's depth), m
  long contact_steps = 0, beyond = 0;
};

inline Impact impact_depth(const dda::paper::SmallEdgeImpact& si) {
  dda::Simulation sim(si.scene);
  Impact r;
  r.lower_depth = sub_polygons(sim.polygon(si.lower)).depth;
  while (sim.time() < si.scene.duration - 0.5 * sim.dt()) {
    sim.step();
    if (sim.contact_count() == 0) continue;
    ++r.contact_steps;
    const dda::Polygon& lo = sim.polygon(si.lower);
    const dda::Polygon ip = dda::intersection_polygon(lo, sim.polygon(si.upper));
    double d = 0.0;
    for (int k = 0; k < ip.count; ++k) d = std::max(d, dda::exit_distance(lo, ip.vertex(k)));
    r.deepest = std::max(r.deepest, d);
    r.beyond += d > r.lower_depth ? 1 : 0;
  }
  return r;
}

// ---- the check rows -------------------------------------------------------------

inline repro::Claim undefined_row(const FieldScan& f, double depth, double r_in) {
  repro::Claim c{"3.2.2",
                 "Fig. 4a (reconstructed definition and polygon): the previous sub-polygon potential leaves a large inner part undefined",
                 "'there would be a large inner part without a valid potential definition when the previous "
                 "definition is used' (Sect. 3.2.2, Fig. 4a)",
                 format_short(100.0 * f.undefined(), 3) + " % of " + std::to_string(f.inside) +
                     " interior grid points lie in no sub-polygon (offset depth d* = " + format_short(depth, 3) +
                     " m vs inscribed radius " + format_short(r_in, 3) + " m)",
                 "> 10 % of the area (criterion set before the run)", f.undefined() > kLargeUndefined};
  c.control = std::string("repro_controls: ") + kControlUndefined;
  c.scope = repro::Scope::kPaper;
  return c;
}

inline repro::Claim hexagon_row(double ratio) {
  repro::Claim c{"3.2.2", "Fig. 4a control: a regular hexagon has no undefined part under the same reconstruction",
                 "(the small edges are the cause)", "d* / inscribed radius = " + format_short(ratio, 6),
                 "= 1 within 1e-9", std::fabs(ratio - 1.0) < kRatioTolerance};
  c.control = std::string("repro_controls: ") + kControlHexagon;
  c.scope = repro::Scope::kExtension;
  return c;
}

inline repro::Claim mismatch_row(const FieldScan& f) {
  repro::Claim c{"3.2.2", "Fig. 4a (reconstruction): where the previous potential is defined it equals the shortest-exit one",
                 "(both are kn d / H to the owning edge)",
                 "max |phi_previous - phi_current| = " + format_short(f.mismatch, 3) + " Pa", "<= 1e-12 Pa",
                 f.mismatch <= kMismatchTolerance};
  c.control = std::string("repro_controls: ") + kControlMismatch;
  c.scope = repro::Scope::kExtension;
  return c;
}

inline repro::Claim impact_row(const Impact& r) {
  repro::Claim c{"5.3", "the 5.3 impact on the 0.01 m edge reaches the part where the previous potential is undefined",
                 "'part of the intersection polygon may locate to the inner parts without potential function "
                 "definition when previous approach [56] is applied' (Sect. 5.3)",
                 "lower block's offset depth d* = " + format_short(r.lower_depth, 3) + " m; deepest IP vertex " +
                     format_short(r.deepest, 3) + " m; deeper than d* in " + std::to_string(r.beyond) + " of " +
                     std::to_string(r.contact_steps) + " contact steps",
                 "> 0 steps", r.beyond > 0};
  c.control = std::string("repro_controls: ") + kControlImpact;
  c.scope = repro::Scope::kPaper;
  return c;
}

}  // namespace previous_potential
