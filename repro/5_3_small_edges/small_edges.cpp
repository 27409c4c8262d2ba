// Paper A, Sect. 5.3 "Polygon with small edges" (Figs. 17-18).
//
// GEOMETRY RECONSTRUCTED: Fig. 17 is lost (dda::paper::small_edge_impact).
// Lower block (fixed): a hexagon 1 m wide and 1 m high whose roof rises at
// 31 deg from (+-0.5, 0.7) to a 0.01 m top edge centred at (0, 1). Upper
// block: a 0.5 m square turned 45 deg, its lowest vertex 0.01 m above the
// lower block, starting at 1 m/s downward under gravity 9.81:
//   case 1 (Fig. 17a): the vertex is above the small edge's midpoint;
//   case 2 (Fig. 17b): above the right roof edge, 0.02 m right of the small
//   edge's end ("the right edges neighboring the small edge").
// rho 2000, E 1 GPa, nu 0.25, kn 50 MPa, dt 1e-4 s (Table 5), 0.2 s;
// frictionless (Table 5 gives kt but no friction angle); an extra row
// repeats case 2 with friction 30 deg and kt = 1e7 N/m. Contact with the
// library defaults: the paper's segmentation (Sect. 3.2.3) with the paper's
// small-edge rule (the virtual node's ray added to the vertex rays);
// repro/5_5_segmentation runs both cases also with the replacing reading (the
// virtual node replaces the vertex rays) and with the exact integration.
// Expected (paper): "the proposed approach can treat contacts of small edges
// with good robustness"; penetrations "around 0.01 m" reach the inner part
// of the polygon where the previous sub-polygon potential is undefined.
// Measured, per case: no flip-through (the contact force never pulls the
// upper block into the lower one, and the blocks are apart again at 0.2 s),
// bounded and conserved energy, the peak penetration (overlap thickness =
// diameter of the largest circle in the intersection polygon; deepest
// vertex = largest exit distance of a vertex inside the other block), and
// the mirror symmetry of case 1.
//
// Output: data/small_edges/traces.csv, snapshots.csv, claims/5_3_small_edges.csv.
#include <cmath>
#include <string>
#include <vector>

#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/5_3_small_edges/small_edges.hpp"
#include "repro/common/common.hpp"

using dda::paper::SmallEdgeCase;
using repro::format_short;
using small_edges::add_claims;
using small_edges::Result;
using small_edges::run;

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {
    "small_edges", "5.3 small edges",
    "Paper A Sect. 5.3 (Figs. 17-18, geometry reconstructed): a polygon with small edges."};

namespace {

// Cases 1 and 2 (Fig. 18): their traces and snapshots under `dir`, their rows
// (and case 1's mirror row) appended to `claims`.
void paper_cases(const repro::Driver& d, const std::string& dir, std::vector<repro::Claim>& claims) {
  const std::vector<std::string> notes = {
      "Paper A Sect. 5.3, geometry RECONSTRUCTED (Fig. 17 lost): fixed 1 m hexagon with a 0.01 m top edge; 0.5 m square "
      "turned 45 deg hitting with a vertex at 1 m/s under gravity; case 1 on the small edge, case 2 on the edge next to "
      "it; kn 50 MPa, dt 1e-4 s, frictionless",
      "vertex = the upper block's contacting vertex; overlap_thickness = diameter of the largest circle in the "
      "intersection polygon; vertex_depth = largest exit distance of a vertex inside the other block"};
  repro::TableWriter<small_edges::Trace> traces(dir + "/traces.csv", small_edges::trace_columns(), notes);
  repro::TableWriter<small_edges::Vertex> snaps(dir + "/snapshots.csv", small_edges::snapshot_columns(), notes);
  const char* names[2] = {"case 1, vertex on the 0.01 m edge (reconstructed geometry)",
                          "case 2, vertex on the edge next to it (reconstructed geometry)"};
  const SmallEdgeCase cases[2] = {SmallEdgeCase::kOnSmallEdge, SmallEdgeCase::kOnNeighbourEdge};
  for (int c = 0; c < 2; ++c) {
    const dda::paper::SmallEdgeImpact si = dda::paper::small_edge_impact(cases[c]);
    const Result r = run(si, c + 1, &traces, &snaps);
    d.progress(std::string(names[c]) + ": energy error " + format_short(r.stats.energy_error, 3) + ", overlap " +
               format_short(r.stats.peak_thickness, 3) + " m, vertex depth " +
               format_short(r.stats.peak_vertex_depth, 3) + " m, " + format_short(r.seconds, 3) + " s");
    const std::string section = "5.3";
    add_claims(claims, section, names[c], r, true);
    if (c == 0) claims.push_back(small_edges::mirror_row(section, names[c], r));
  }
  traces.commit();
  snaps.commit();
}

// Beyond the paper: case 2 with friction (30 deg, kt 1e7 N/m).
void friction_case(const repro::Driver& d, std::vector<repro::Claim>& claims) {
  dda::paper::SmallEdgeImpact si = dda::paper::small_edge_impact(SmallEdgeCase::kOnNeighbourEdge);
  si.scene.contact.kt = 1e7;
  si.scene.contact.friction_deg = 30.0;
  const Result r = run(si, 3, nullptr, nullptr);
  const std::size_t first = claims.size();
  add_claims(claims, "5.3 (extra)", "case 2 with friction 30 deg, kt 1e7 N/m", r, false);
  for (std::size_t i = first; i < claims.size(); ++i) claims[i].scope = repro::Scope::kExtension;  // not the paper's case
  d.progress("case 2 with friction: energy growth " + format_short(r.stats.energy_growth, 3));
}

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  std::vector<repro::Claim> claims;
  paper_cases(d, d.out + "/data/small_edges", claims);
  friction_case(d, claims);
  repro::write_claims(repro::claims_path(d.out, "5_3_small_edges"), claims);
  d.progress("done");
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, {}, reproduce); }
