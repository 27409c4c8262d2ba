// Paper A vs Paper B on the same collisions (a comparison neither paper
// makes). Two scenes, each run with
//   A  : Paper A's 6-DOF DDA blocks with the potential-based penalty contact
//        (dda::Simulation, kn as in the scene),
//   B  : Paper B's CDEM blocks (CST meshes) with the two-scale contact
//        (time-of-impact split, clone node, local subdivision; the
//        subdivision is the in-place refinement, SubdivisionMode::kInPlace,
//        set explicitly: a study, not a paper figure, so its outputs do not
//        follow the library default),
//   B0 : the same without local subdivision (clone of coarse nodes),
//   P  : baseline, not Paper B: the conventional node-to-edge penalty
//        contact on B0's CST meshes (kn = E/100, frictionless, undamped;
//        penalty_baseline.{hpp,cpp}, lib/cdem/src/model_penalty.cpp), with
//        a measured stability limit at kn x 1 and x 10^4,
// over a sweep of dt:
//   prisms  - Paper B Sect. 6 (RECONSTRUCTED 7 m prisms, see
//             dda/cdem/scenes.hpp), 3 m/s, run to 0.8 s; for A, kn = E/100
//             = 0.4 GPa (Paper A's ratio in Sect. 4.1; Paper B has no kn);
//   squares - Paper A Sect. 4.1 (1 m squares, 0.5 m gap, 1 m/s, kn 10 MPa),
//             run to 1.0 s; for B each square is 4 fan triangles split 4 x 4.
// References: the touch time gap / speed (exact), momentum (conserved),
// energy (conserved by an elastic collision), the velocity exchange of two
// equal rigid blocks (v_i -> 0, v_j -> v0), and for the squares the contact
// time of two elastic bars, 2 L / c (c = sqrt(E / rho)).
// Expected: B finds the touch time exactly, A up to one step late; A keeps
// energy and exchanges the velocities, B loses some energy in the clone
// impact and in the patch remaps and keeps some in vibration; the penalty
// contact lasts as long as kn makes it, B's as long as the elastic wave.
//
// Output under <out>/data/B_7_contact_comparison/: sweep.csv (one row per
// scene, model and dt, with the wall time), history.csv (x-velocities at
// the base dt), energy_history.csv (the energy account of B and B0 per
// history row); claims in <out>/claims/B_7_contact_comparison.csv.
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "repro/B_7_contact_comparison/contact_comparison.hpp"
#include "repro/B_7_contact_comparison/output.hpp"
#include "repro/B_7_contact_comparison/penalty_baseline.hpp"
#include "repro/common/common.hpp"
#include "repro/common/driver.hpp"

namespace {
using namespace compare;
const char* kDriver = "B_7_contact_comparison";

// Every run: A, B, B0 over each scene's dt sweep, then P (the node-to-edge
// penalty baseline on the CST blocks, penalty_baseline.cpp).
struct Runs {
  std::vector<SceneDef> scenes;
  std::vector<Result> results;
  std::map<std::string, History> histories;
  PenaltyRuns penalty;
};
Runs run_all(const Settings& set, const repro::Progress& progress) {
  Runs runs;
  runs.scenes = scene_defs(set);
  for (const SceneDef& def : runs.scenes) {
    for (const std::string model : {"A", "B", "B0"}) {
      const std::vector<Result> sweep = run_sweep(def, model, &runs.histories[def.name + "/" + model]);
      for (const Result& r : sweep)
        progress(def.name + " " + model + " dt " + format_short(r.dt) + ": " + format_short(r.wall, 3) + " s, v_j " +
                 format_short(r.v_j, 6) + ", dE " + format_short(r.energy_err_end, 3));
      runs.results.insert(runs.results.end(), sweep.begin(), sweep.end());
    }
  }
  runs.penalty = run_penalty_baseline(runs.scenes, runs.results, runs.histories, progress);
  return runs;
}

// The rows: per scene A against B and B0, A's kn dependence on the prisms
// (kn x 1, 10, 100 at the base dt; B has no such parameter), P's rows.
std::vector<repro::Claim> claim_rows(const Settings& set, const Runs& runs) {
  const std::vector<SceneDef>& scenes = runs.scenes;
  std::vector<repro::Claim> claims;
  for (const SceneDef& def : scenes)
    for (const repro::Claim& c : scene_rows(def, runs.results, runs.histories)) claims.push_back(c);
  claims.push_back(kn_row(scenes.front(), kn_sweep(scenes.front(), {1.0, 10.0, 100.0}),
                          pick(runs.results, "prisms", "B").front()));
  add_penalty_rows(scenes, runs.results, runs.penalty, claims);
  if (!set.is_default())  // rows of a run off the default meshes or time steps say so
    for (repro::Claim& c : claims)
      c.claim += " [NOT THE DEFAULT SETTINGS: prisms " + std::to_string(set.prism_divisions) + " divisions, dt " +
                 format_short(set.prisms_dt) + " s; squares " + std::to_string(set.square_divisions) +
                 " divisions, dt " + format_short(set.squares_dt) + " s]";
  repro::default_scope(claims, repro::Scope::kExtension);  // a comparison neither paper makes, every row
  return claims;
}
}  // namespace

int main(int argc, char** argv) {
  return repro::driver_main(
      argc, argv,
      {kDriver, "B-7 contact comparison", "Paper A against Paper B: both contact models on the same collisions."},
      {{"--prisms-divisions", "N", "CDEM mesh divisions of the prisms (default 2: Paper B's example here)", true},
       {"--squares-divisions", "N", "CDEM mesh divisions of the squares' fan triangles (default 4)", true},
       {"--prisms-dt", "S", "base dt of the prisms' sweep, s (default 5e-4: Paper B's; the sweep halves it)", false},
       {"--squares-dt", "S", "base dt of the squares' sweep, s (default 1e-4: Paper A's)", false}},
      [](const repro::Driver& d) {
        Settings set;
        set.prism_divisions = d.whole("--prisms-divisions", set.prism_divisions);
        set.square_divisions = d.whole("--squares-divisions", set.square_divisions);
        set.prisms_dt = d.number("--prisms-dt", set.prisms_dt);
        set.squares_dt = d.number("--squares-dt", set.squares_dt);
        if (set.prism_divisions < 1 || set.square_divisions < 1 || !(set.prisms_dt > 0.0) || !(set.squares_dt > 0.0)) {
          std::fprintf(stderr, "%s: divisions must be >= 1 and time steps > 0\n", kDriver);
          return 2;
        }
        const Runs runs = run_all(set, d.progress);
        write_data(d.out + "/data/" + kDriver + "/", runs.results, runs.histories);
        repro::write_claims(repro::claims_path(d.out, kDriver), claim_rows(set, runs));
        d.progress("done");
        return 0;
      });
}
