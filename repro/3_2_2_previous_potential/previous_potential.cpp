// Paper A, Sect. 3.2.2, Fig. 4a: the "previous sub-polygon" potential of a
// polygon with small edges, beside the shortest-exit potential (Fig. 4b).
//
// RECONSTRUCTION (Fig. 4a is lost and the previous definition, ref. [56], is
// only described in words): "For a polygon with small edges, there would be
// a large inner part without a valid potential definition when the previous
// definition is used" and (Sect. 5.3) "when block penetrations around
// 0.01 m is allowed ... part of the intersection polygon may locate to the
// inner parts without potential function definition". We read the previous
// sub-polygon definition as: every edge i owns the sub-polygon bounded by
// the edge, the angle bisectors at its two ends and the inward offset of the
// edges by one common depth d*, where d* is the depth at which the first
// edge shrinks to a point when all edges move inward together (the smallest
// height of an edge's bisector triangle, L_i / (cot(a_i/2) + cot(a_i+1/2))).
// In sub-polygon i the potential is kn d_i / H (d_i: distance to edge i);
// deeper than d* no sub-polygon exists and the potential is undefined. A
// small edge makes d* small (its two bisectors meet at once), hence a large
// undefined inner part; a regular polygon has d* = its inscribed radius and
// none. This is OUR READING of the paper's words, not ref. [56]'s formulas.
//
// Polygon: the same RECONSTRUCTED Fig. 4 polygon as the potential_fields
// driver (a ~1.2 m pentagon with corners cut by 0.03 m and 0.05 m edges;
// construction copied from repro/3_2_2_potential_fields), kn = 1 Pa, H = 1 m.
// Also measured: d* of the Sect. 5.3 lower block (0.01 m edge) and whether
// the 5.3 impacts reach deeper than it, as the paper says.
//
// Output: data/previous_potential/fig04a_grid.csv, outline.csv,
// subpolygons.csv; claims/3_2_2_previous_potential.csv.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

#include "dda/polygon.hpp"
#include "dda/potential.hpp"
#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/3_2_2_potential_fields/potential_fields.hpp"
#include "repro/common/common.hpp"

namespace {
using dda::Vec2;
using repro::format_short;
constexpr double kKn = 1.0, kH = 1.0;
constexpr int kGridCells = 300;

// The Fig. 4b polygon is potential_fields::small_edge_polygon (shared).
using potential_fields::small_edge_polygon;

// The reconstructed sub-polygons: sub[i] = {v_i, v_i+1, inner_i+1, inner_i}.
struct SubPolygons {
  double depth = 0.0;  // d*
  std::vector<std::vector<Vec2>> sub;
};

SubPolygons sub_polygons(const dda::Polygon& p) {
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
  for (int i = 0; i < n; ++i) {
    const int j = p.next(i);
    s.sub.push_back({p.vertex(i), p.vertex(j), p.vertex(j) + (s.depth / std::sin(half[j])) * dir[j],
                     p.vertex(i) + (s.depth / std::sin(half[i])) * dir[i]});
  }
  return s;
}

// Point in a (possibly degenerate) convex quadrilateral, CCW: all cross >= -eps.
bool inside_quad(const std::vector<Vec2>& q, Vec2 x) {
  for (std::size_t k = 0; k < q.size(); ++k) {
    const Vec2 a = q[k], b = q[(k + 1) % q.size()];
    if (dda::length(b - a) < 1e-15) continue;
    if (dda::cross(b - a, x - a) < -1e-12) return false;
  }
  return true;
}
}  // namespace

int main(int argc, char** argv) try {
  repro::check_command_line(argc, argv, "Paper A Sect. 3.2.2 (Fig. 4a): the previous sub-polygon potential beside the shortest-exit one.");
  const std::string out = repro::out_dir(argc, argv);
  const repro::Progress progress("previous_potential");
  const std::string dir = out + "/data/previous_potential";
  const std::vector<Vec2> pts = small_edge_polygon();
  const dda::Polygon poly = dda::make_polygon(pts.data(), static_cast<int>(pts.size()));
  const SubPolygons sp = sub_polygons(poly);
  const double r_in = dda::inscribed_circle(poly).radius;
  progress("d* = " + format_short(sp.depth, 4) + " m, inscribed radius " + format_short(r_in, 4) + " m");

  const std::vector<std::string> notes = {
      "Paper A Sect. 3.2.2 Fig. 4a: 'previous sub-polygon' potential, RECONSTRUCTED from the paper's words (sub-polygon "
      "of an edge = edge + end bisectors + common inward offset depth d* where the first edge vanishes; undefined "
      "deeper); kn = 1 Pa, H = 1 m",
      "RECONSTRUCTED polygon (same as Fig. 4b of the potential_fields driver); d* = " + repro::format_full(sp.depth) +
          " m"};
  // Grid: y outer, x inner, as the potential_fields driver.
  dda::Aabb box = dda::bounds(poly);
  const double span = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y), margin = 0.04 * span;
  const double h = (span + 2 * margin) / kGridCells;
  const int nx = static_cast<int>(std::ceil((box.hi.x - box.lo.x + 2 * margin) / h)) + 1;
  const int ny = static_cast<int>(std::ceil((box.hi.y - box.lo.y + 2 * margin) / h)) + 1;
  repro::CsvWriter grid(dir + "/fig04a_grid.csv",
                        {"x", "y", "inside", "defined", "subpolygon", "phi_previous", "phi_current"}, notes);
  long inside = 0, defined = 0;
  double mismatch = 0.0;  // max |phi_previous - phi_current| where defined
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
      inside += in ? 1 : 0;
      defined += owner >= 0 ? 1 : 0;
      if (owner >= 0) mismatch = std::max(mismatch, std::fabs(phi_prev - phi_cur));
      grid.row({p.x, p.y, in ? 1.0 : 0.0, owner >= 0 ? 1.0 : 0.0, static_cast<double>(owner), phi_prev, phi_cur});
    }
  grid.commit();
  repro::CsvWriter outline(dir + "/outline.csv", {"vertex", "x", "y", "edge_length"}, notes);
  for (int k = 0; k < poly.count; ++k)
    outline.row({static_cast<double>(k), poly.vertex(k).x, poly.vertex(k).y, dda::length(poly.edge(k))});
  outline.commit();
  repro::CsvWriter subs(dir + "/subpolygons.csv", {"subpolygon", "vertex", "x", "y"}, notes);
  for (std::size_t k = 0; k < sp.sub.size(); ++k)
    for (std::size_t v = 0; v < sp.sub[k].size(); ++v)
      subs.row({static_cast<double>(k), static_cast<double>(v), sp.sub[k][v].x, sp.sub[k][v].y});
  subs.commit();
  const double undefined = inside > 0 ? 1.0 - static_cast<double>(defined) / static_cast<double>(inside) : 0.0;
  progress("undefined fraction " + format_short(undefined, 3));

  // A regular hexagon as the control: d* = inscribed radius, nothing undefined.
  std::vector<Vec2> hex;
  for (int k = 0; k < 6; ++k) hex.push_back({std::cos(k * M_PI / 3), std::sin(k * M_PI / 3)});
  const dda::Polygon hexp = dda::make_polygon(hex.data(), 6);
  const double hex_ratio = sub_polygons(hexp).depth / dda::inscribed_circle(hexp).radius;

  // Sect. 5.3: does the impact on the 0.01 m edge reach deeper than d*?
  const dda::paper::SmallEdgeImpact si = dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnSmallEdge);
  dda::Simulation sim(si.scene);
  const double lower_depth = sub_polygons(sim.polygon(si.lower)).depth;
  long contact_steps = 0, beyond = 0;
  double deepest = 0.0;
  while (sim.time() < si.scene.duration - 0.5 * sim.dt()) {
    sim.step();
    if (sim.contacts().empty()) continue;
    ++contact_steps;
    const dda::Polygon& lo = sim.polygon(si.lower);
    const dda::Polygon ip = dda::intersection_polygon(lo, sim.polygon(si.upper));
    double d = 0.0;  // deepest IP vertex in the lower block (a lower bound of the IP's depth)
    for (int k = 0; k < ip.count; ++k) d = std::max(d, dda::exit_distance(lo, ip.vertex(k)));
    deepest = std::max(deepest, d);
    beyond += d > lower_depth ? 1 : 0;
  }

  std::vector<repro::Claim> claims = {
      {"3.2.2", "Fig. 4a (reconstructed definition and polygon): the previous sub-polygon potential leaves a large inner part undefined",
       "Fig. 4a: 'a large inner part' without a valid potential",
       format_short(100.0 * undefined, 3) + " % of " + std::to_string(inside) +
           " interior grid points lie in no sub-polygon (offset depth d* = " + format_short(sp.depth, 3) +
           " m vs inscribed radius " + format_short(r_in, 3) + " m)",
       "> 10 % of the area (criterion set before the run)", undefined > 0.10},
      {"3.2.2", "Fig. 4a control: a regular hexagon has no undefined part under the same reconstruction",
       "(the small edges are the cause)", "d* / inscribed radius = " + format_short(hex_ratio, 6), "= 1 within 1e-9",
       std::fabs(hex_ratio - 1.0) < 1e-9},
      {"3.2.2", "Fig. 4a (reconstruction): where the previous potential is defined it equals the shortest-exit one",
       "(both are kn d / H to the owning edge)", "max |phi_previous - phi_current| = " + format_short(mismatch, 3) + " Pa",
       "<= 1e-12 Pa", mismatch <= 1e-12},
      {"5.3", "the 5.3 impact on the 0.01 m edge reaches the part where the previous potential is undefined",
       "Sect. 5.3: 'part of the intersection polygon may locate to the inner parts without potential function "
       "definition when previous approach [56] is applied'",
       "lower block's offset depth d* = " + format_short(lower_depth, 3) + " m; deepest IP vertex " +
           format_short(deepest, 3) + " m; deeper than d* in " + std::to_string(beyond) + " of " +
           std::to_string(contact_steps) + " contact steps",
       "> 0 steps", beyond > 0},
  };
  repro::write_claims(repro::claims_path(out, "3_2_2_previous_potential"), claims);
  progress("done");
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "previous_potential: error: %s\n", e.what());
  return 1;
}
