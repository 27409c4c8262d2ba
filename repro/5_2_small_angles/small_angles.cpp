// Paper A, Sect. 5.2 "Polygon with small angles" (Figs. 15-16).
//
// GEOMETRY RECONSTRUCTED: Fig. 15 is lost (dda::paper::small_angle_triangles).
// Two identical isosceles triangles with a 5 deg apex angle, 1 m from apex
// to base, axes horizontal, apexes pointing in opposite directions; the
// upper one is the point image of the lower one through the collision
// centre (0, 0). Their facing long sides (parallel, inclined 2.5 deg) overlap
// over 0.5 m with both 5 deg apexes inside the overlap, 0.01 m apart. The
// lower one moves up at 1 m/s, the upper one down at 1 m/s; no gravity,
// frictionless (Table 5 gives no friction angle). rho 2000, E 1 GPa,
// nu 0.25, kn 50 MPa, dt 2e-5 s, 0.2 s (Table 5).
// Expected (paper): "the two triangles move symmetrically regarding the
// collision centroid"; the apex ("angle end") points and the centroids are
// tracked, and the configuration after 0.2 s is shown (Fig. 16).
// Measured: the largest deviation from point symmetry through the centre
// over the run (vertex by vertex: block 1 = 2 c - block 0), energy
// conservation, the peak overlap.
// Variant (extra row): the same triangles apex to apex on a vertical line,
// each tilted 1 deg; the tips glance off each other.
//
// Output: data/small_angles/traces.csv, snapshots.csv, claims/5_2_small_angles.csv.
#include <cmath>
#include <string>
#include <vector>

#include "dda/robustness_scenes.hpp"
#include "dda/simulation.hpp"
#include "repro/5_2_small_angles/small_angles.hpp"
#include "repro/common/common.hpp"
#include "repro/common/sim_output.hpp"

using dda::Vec2;
using repro::format_short;
using small_angles::Result;
using small_angles::run;

// The driver: its name in errors, its progress lines' prefix and its usage line.
const repro::DriverInfo kInfo = {
    "small_angles", "5.2 small angles",
    "Paper A Sect. 5.2 (Figs. 15-16, geometry reconstructed): polygons with small angles."};

namespace {

// The run: what main's driver_main calls once the command line is checked.
int reproduce(const repro::Driver& d) {
  const std::string dir = d.out + "/data/small_angles";
  const dda::paper::SmallAngleTriangles st = dda::paper::small_angle_triangles(5.0);
  const std::vector<std::string> notes = {
      "Paper A Sect. 5.2, geometry RECONSTRUCTED (Fig. 15 lost): two 5 deg isosceles triangles, 1 m long, point "
      "images through (0,0), facing long sides overlapping 0.5 m, 0.01 m apart; +-1 m/s; kn 50 MPa, dt 2e-5 s, "
      "frictionless",
      "apex = vertex with the 5 deg angle; asymmetry = max_k |v0_k + v1_k - 2 c| (point symmetry), m"};
  repro::TableWriter<small_angles::Trace> traces(dir + "/traces.csv", small_angles::trace_columns(), notes);
  repro::TableWriter<repro::VertexRow> snaps(dir + "/snapshots.csv", repro::snapshot_columns(), notes);
  const Result r = run(st, &traces, &snaps);
  traces.commit();
  snaps.commit();
  d.progress("5 deg: asymmetry " + format_short(r.asymmetry, 3) + " m, energy error " +
             format_short(r.stats.energy_error, 3) + ", contact " + format_short(r.stats.first_contact, 4) + " to " +
             format_short(r.stats.last_contact, 4) + " s, " + format_short(r.seconds, 3) + " s");

  const dda::paper::SmallAngleTriangles tip =
      dda::paper::small_angle_triangles(5.0, 0.2, dda::paper::TriangleLayout::kApexToApex);
  const Result rt = run(tip, nullptr, nullptr);
  d.progress("apex-to-apex variant: asymmetry " + format_short(rt.asymmetry, 3) + " m, " + format_short(rt.seconds, 3) +
             " s");

  const std::string geo = " (reconstructed geometry, 5 deg triangles, +-1 m/s, 0.2 s)";
  repro::write_claims(repro::claims_path(d.out, "5_2_small_angles"), small_angles::claims(r, rt, geo));
  d.progress("done");
  return 0;
}

}  // namespace

int main(int argc, char** argv) { return repro::driver_main(argc, argv, kInfo, {}, reproduce); }
