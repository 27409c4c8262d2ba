// Paper A, Sect. 3.2.2 "New potential function definition": Figs. 4b and 5.
//
// Reproduces the potential fields phi(p) = kn * d_exit(p) / H (Eq. 12) with
// kn = 1 Pa and H = 1 m, as in the paper's examples:
//   (a) Fig. 4b: a convex polygon with small edges, d_exit by Eqs. 13-14
//       (dda::exit_distance / dda::potential);
//   (b) Fig. 5:  a concave polygon, d_exit = shortest exit path.
//
// The paper's figures are lost (images), so BOTH GEOMETRIES ARE
// RECONSTRUCTIONS: (a) a ~1.2 m pentagon with two corners cut by edges of
// 0.03 m and 0.05 m; (b) a ~1.3 m, 13-vertex polygon with 4 reflex vertices
// (the paper's Fig. 5 polygon was decomposed into six convex parts). Every
// output file and claim says so.
//
// Concave potential: Eq. 12 defines d_exit as the shortest distance for p to
// leave the polygon. The paper evaluates it by cutting the polygon into
// convex parts with demarcation lines (which are not exits). For a point
// inside a simple polygon the shortest exit path is the straight segment to
// the nearest boundary point, so we evaluate d_exit directly as the minimum
// distance to the boundary segments; no decomposition is needed. (For a
// convex polygon this equals Eqs. 13-14; the driver checks that too.)
//
// What we expect (paper text): the potential is zero on the whole boundary
// ("the potential values of any points on polygon boundary should be
// equal"), it is defined and positive at every inner point, including near
// small edges ("the proposed definition ensures the potential value can be
// obtained for each point inside a polygon", unlike the previous sub-polygon
// definition of Fig. 4a, which leaves a large inner part undefined), and
// points with the same penetration below any edge have the same potential.
//
// Output (under --out DIR, default out):
//   DIR/data/potential_fields/fig04b_grid.csv     x,y,inside,d_exit,phi
//   DIR/data/potential_fields/fig04b_outline.csv  vertex,x,y,edge_length
//   DIR/data/potential_fields/fig05_grid.csv      x,y,inside,d_exit,phi
//   DIR/data/potential_fields/fig05_outline.csv   vertex,x,y,edge_length
//   DIR/claims/3_2_2_potential_fields.csv
// Grids are row-major: y outer, x inner. d_exit is signed (negative outside);
// phi = 0 outside (Eq. 12).
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "dda/paper_scenes.hpp"
#include "dda/polygon.hpp"
#include "dda/potential.hpp"
#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/common/common.hpp"
#include "repro/3_2_2_potential_fields/potential_fields.hpp"

using namespace potential_fields;

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {
    "potential_fields", "potential_fields",
    "Paper A Sect. 3.2.2 (Figs. 4b, 5): the potential fields phi = kn d_exit / H (Eq. 12) of "
    "the paper's polygons."};

namespace {

// (a) Fig. 4b: the convex polygon with small edges.
void fig4b(const repro::Driver& d, const std::string& dir, std::vector<Claim>& claims) {
  const std::vector<Vec2> pa = small_edge_polygon();
  const dda::PolygonCheck check = dda::validate_polygon(pa.data(), static_cast<int>(pa.size()));
  if (!check.ok())
    throw std::runtime_error(std::string("Fig. 4b polygon rejected: ") + dda::describe(check.fault) + " at vertex " +
                             std::to_string(check.vertex));
  const dda::Polygon poly = dda::make_polygon(pa.data(), static_cast<int>(pa.size()));
  std::vector<double> edge_len;
  for (int i = 0; i < poly.count; ++i) edge_len.push_back(dda::length(poly.edge(i)));
  std::string small_list;
  for (double l : edge_len)
    if (l < 0.1) small_list += (small_list.empty() ? "" : ", ") + format_short(l, 3) + " m";
  d.progress("Fig. 4b polygon: " + std::to_string(poly.count) + " vertices, small edges " + small_list);

  const Grid ga = convex_grid(pa);
  const std::vector<std::string> note_a = {
      "Paper A Sect. 3.2.2 Fig. 4b: shortest-exit potential phi = kn*d_exit/H (Eqs. 12-14), kn = 1 Pa, H = 1 m",
      "RECONSTRUCTED geometry (the paper's figure is lost): ~1.2 m convex polygon with edges of " + small_list};
  write_grid(dir + "/fig04b_grid.csv", ga, note_a);
  write_outline(dir + "/fig04b_outline.csv", pa, note_a);
  d.progress("Fig. 4b grid " + std::to_string(ga.nx) + "x" + std::to_string(ga.ny) + " written");

  auto eq12 = [&](Vec2 p) { return dda::potential(poly, p, kKn, kH); };
  add_common_claims(claims, "Fig. 4b", ga, boundary_max_abs(pa, eq12));

  // Equal penetration, equal potential, for every edge including the small
  // ones; Eqs. 13-14 vs the distance to the boundary segments; the largest
  // potential (criteria in potential_fields.hpp).
  claims.push_back(equal_penetration_row(poly, eq12));
  claims.back().scope = repro::Scope::kPaper;
  claims.push_back(edge_lines_row(pa, ga));
  claims.back().scope = repro::Scope::kPaper;
  claims.push_back(inscribed_row(poly, ga, eq12));
  claims.back().scope = repro::Scope::kExtension;  // follows from Eqs. 12-14; the paper does not state it
}

// (b) Fig. 5: the concave polygon.
void fig5(const repro::Driver& d, const std::string& dir, std::vector<Claim>& claims) {
  const std::vector<Vec2> pb = concave_polygon();
  check_simple_ccw(pb);
  const int reflex = reflex_count(pb);
  d.progress("Fig. 5 polygon: " + std::to_string(pb.size()) + " vertices, " + std::to_string(reflex) + " reflex");
  const Grid gb = concave_grid(pb);
  const std::vector<std::string> note_b = {
      "Paper A Sect. 3.2.2 Fig. 5: shortest-exit potential of a concave polygon, phi = kn*d_exit/H, kn = 1 Pa, H = 1 m; "
      "d_exit = shortest distance to the boundary segments (no convex decomposition needed)",
      "RECONSTRUCTED geometry (the paper's figure is lost): " + std::to_string(pb.size()) + "-vertex simple polygon with " +
          std::to_string(reflex) + " reflex vertices"};
  write_grid(dir + "/fig05_grid.csv", gb, note_b);
  write_outline(dir + "/fig05_outline.csv", pb, note_b);
  d.progress("Fig. 5 grid " + std::to_string(gb.nx) + "x" + std::to_string(gb.ny) + " written");

  add_common_claims(claims, "Fig. 5", gb, boundary_max_abs(pb, [&](Vec2 p) {
                      return inside_simple(pb, p) ? kKn * boundary_distance(pb, p) / kH : 0.0;
                    }));

  // Independent check of the segment-distance evaluation (a dense sampling of
  // the boundary), and the edge-line formula applied blindly.
  claims.push_back(nearest_point_row(pb, gb));
  claims.back().scope = repro::Scope::kPaper;
  claims.push_back(concave_lines_row(pb, gb));
  claims.back().scope = repro::Scope::kPaper;
}

// H of Eq. 12 per paper scene under both rules the paper states: Sect.
// 3.2.2 ("the average length of all polygon edges of the assembly") and
// Sect. 5.1 (the average of the largest and the smallest edge, the rule
// every run here uses). Measurements: the paper gives no H values.
void h_rows(std::vector<Claim>& claims) {
  struct HScene {
    std::string name;
    dda::Scene scene;
  };
  const std::vector<HScene> scenes = {
      {"4.1 two squares", dda::paper::two_squares()},
      {"4.2 symmetric stack", dda::paper::symmetric_stack().scene},
      {"4.3 incline", dda::paper::incline(20.0).scene},
      {"5.1 bouncing block, case 1", dda::paper::bouncing_block(0.1, dda::HRule::kMinMaxEdge).scene},
      {"5.1 bouncing block, case 2", dda::paper::bouncing_block(1.0, dda::HRule::kMinMaxEdge).scene},
      {"5.2 small-angle triangles", dda::paper::small_angle_triangles(5.0).scene},
      {"5.3 small edges, case 1", dda::paper::small_edge_impact(dda::paper::SmallEdgeCase::kOnSmallEdge).scene},
  };
  for (const HScene& h : scenes) {
    dda::Scene mean_edge = h.scene, min_max = h.scene;
    mean_edge.contact.h_rule = dda::HRule::kMeanEdge;
    min_max.contact.h_rule = dda::HRule::kMinMaxEdge;
    const double h_mean = dda::Simulation(mean_edge).potential_length(0);
    const double h_minmax = dda::Simulation(min_max).potential_length(0);
    claims.push_back(repro::measurement(
        "3.2.2 / 5.1", "H of Eq. 12 under the two stated rules: " + h.name,
        "Sect. 3.2.2: mean of all edges of the assembly; Sect. 5.1: mean of the largest and smallest edge",
        "mean edge " + format_short(h_mean, 4) + " m; (largest + smallest) / 2 " + format_short(h_minmax, 4) +
            " m (used in our runs); ratio " + format_short(h_minmax / h_mean, 3),
        "information: the paper gives no H values"));
    claims.back().scope = repro::Scope::kExtension;  // the two rules compared: not a statement of the paper
  }
}

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  const std::string dir = d.out + "/data/potential_fields";
  std::vector<Claim> claims;
  fig4b(d, dir, claims);
  fig5(d, dir, claims);
  h_rows(claims);
  repro::write_claims(repro::claims_path(d.out, "3_2_2_potential_fields"), claims);
  int passed = 0, checks = 0;
  for (const Claim& c : claims) {
    checks += c.kind == repro::Kind::kCheck ? 1 : 0;
    passed += c.kind == repro::Kind::kCheck && c.pass ? 1 : 0;
  }
  d.progress("claims: " + std::to_string(passed) + " of " + std::to_string(checks) + " checks pass");
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, {}, reproduce); }
