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
// construction shared from repro/3_2_2_potential_fields), kn = 1 Pa, H = 1 m.
// Also measured: d* of the Sect. 5.3 lower block (0.01 m edge) and whether
// the 5.3 impacts reach deeper than it, as the paper says.
//
// The sub-polygons, the grid scan and the criteria of the rows are in
// previous_potential.hpp (shared with the negative controls).
//
// Output: data/previous_potential/fig04a_grid.csv, outline.csv,
// subpolygons.csv; claims/3_2_2_previous_potential.csv.
#include <cmath>
#include <string>
#include <vector>

#include "dda/polygon.hpp"
#include "dda/robustness_scenes.hpp"
#include "repro/3_2_2_potential_fields/potential_fields.hpp"
#include "repro/3_2_2_previous_potential/previous_potential.hpp"
#include "repro/common/common.hpp"

using namespace previous_potential;
// The Fig. 4b polygon is potential_fields::small_edge_polygon (shared).
using potential_fields::small_edge_polygon;

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {
    "previous_potential", "previous_potential",
    "Paper A Sect. 3.2.2 (Fig. 4a): the previous sub-polygon potential beside the shortest-exit one."};

namespace {

// Fig. 4a's files: the grid scan, the outline and the sub-polygons.
FieldScan write_figure(const std::string& dir, const std::vector<Vec2>& pts, const dda::Polygon& poly,
                       const SubPolygons& sp) {
  const std::vector<std::string> notes = {
      "Paper A Sect. 3.2.2 Fig. 4a: 'previous sub-polygon' potential, RECONSTRUCTED from the paper's words (sub-polygon "
      "of an edge = edge + end bisectors + common inward offset depth d* where the first edge vanishes; undefined "
      "deeper); kn = 1 Pa, H = 1 m",
      "RECONSTRUCTED polygon (same as Fig. 4b of the potential_fields driver); d* = " + repro::format_full(sp.depth) +
          " m"};
  repro::TableWriter<GridPoint> grid(dir + "/fig04a_grid.csv", grid_columns(), notes);
  const FieldScan field = scan_field(poly, sp, &grid);
  grid.commit();
  potential_fields::write_outline(dir + "/outline.csv", pts, notes);
  struct SubVertex {
    std::size_t sub, vertex;
  };
  std::vector<SubVertex> vertices;
  for (std::size_t k = 0; k < sp.sub.size(); ++k)
    for (std::size_t v = 0; v < sp.sub[k].size(); ++v) vertices.push_back({k, v});
  const auto at = [&sp](const SubVertex& s) { return sp.sub[s.sub][s.vertex]; };
  repro::write_table<SubVertex>(dir + "/subpolygons.csv",
                                {{"subpolygon", [](const SubVertex& s) { return s.sub; }},
                                 {"vertex", [](const SubVertex& s) { return s.vertex; }},
                                 {"x", [&at](const SubVertex& s) { return at(s).x; }},
                                 {"y", [&at](const SubVertex& s) { return at(s).y; }}},
                                vertices, notes);
  return field;
}

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  const std::vector<Vec2> pts = small_edge_polygon();
  const dda::Polygon poly = dda::make_polygon(pts.data(), static_cast<int>(pts.size()));
  const SubPolygons sp = sub_polygons(poly);
  const double r_in = dda::inscribed_circle(poly).radius;
  d.progress("d* = " + format_short(sp.depth, 4) + " m, inscribed radius " + format_short(r_in, 4) + " m");
  const FieldScan field = write_figure(d.out + "/data/previous_potential", pts, poly, sp);
  d.progress("undefined fraction " + format_short(field.undefined(), 3));

  // A regular hexagon as the control: d* = inscribed radius, nothing undefined.
  const double hex_ratio = depth_ratio(regular_hexagon());

  // Sect. 5.3: does the impact on the 0.01 m edge reach deeper than d*?
  const Impact impact = impact_depth(dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnSmallEdge));

  repro::write_claims(
      repro::claims_path(d.out, "3_2_2_previous_potential"),
      {undefined_row(field, sp.depth, r_in), hexagon_row(hex_ratio), mismatch_row(field), impact_row(impact)});
  d.progress("done");
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, {}, reproduce); }
