// An impact study beyond Paper B, on its two-scale contact
// (Sects. 3-5: two time stages, clone node by the perfectly inelastic Eq. 4,
// Mohr-Coulomb sliding, local subdivision): two 1 m CST-meshed squares of
// Paper B's material (E 40 GPa, nu 0.25, rho 2700 kg/m3, d_tol 5e-3 m), A
// striking B at rest face to face at angle 0-85 deg from the normal, speed
// 0.1-30 m/s, friction mu = tan(phi) 0 / 0.3 / 0.6, subdivision off / on
// ('on': the in-place refinement, SubdivisionMode::kInPlace, set explicitly;
// beyond the paper), and the 'on' cells again with Paper B Sect. 5's
// sub-model as we read it (subdivision 'sub-model', kSubModel), whose rows
// (the same per-cell criteria) stand beside the others.
// impact_study.hpp has the set-up, the rigid-body impact law compared with
// and the per-cell criteria.
//
// Expected: no pass-through, kinetic energy never above its initial value,
// the blocks separate (no cohesion or tensile strength), the touches' loss
// within Eq. 5 and the run's within Eq. 5 for the two blocks; the tangential
// impulse within Coulomb's mu J_n and on the rigid stick/slide law. Known
// beforehand: Eq. 4 takes the contact points' tangential relative velocity
// whatever phi is, so the Coulomb and rigid-law rows are expected to FAIL
// because of the paper's method.
//
// Output under <out>/data/B_9_impact_study/: cells.csv (one row per cell:
// outcome, penetration, separation, energy, loss vs Eq. 5, restitution,
// impulses and the law's prediction, the per-criterion verdicts); claims in
// <out>/claims/B_9_impact_study.csv.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "repro/B_9_impact_study/impact_study.hpp"
#include "repro/common/common.hpp"
#include "repro/common/options.hpp"

namespace {

const char* kDriver = "B_9_impact_study";

// A number as CSV text; empty if not finite (a stopped run's state is no data).
std::string num(double x) { return std::isfinite(x) ? repro::format_full(x) : std::string(); }
std::string yes(bool b) { return b ? "y" : "n"; }

}  // namespace

int main(int argc, char** argv) try {
  repro::check_command_line(argc, argv,
                            "Beyond Paper B: impact study of its two-scale contact (two 1 m squares, angle x "
                            "speed x friction x subdivision).",
                            {{"--dt", "S", "time step, s (default 2e-5: 0.28 of the squares' critical step)", false}});
  const double dt = repro::option_number(argc, argv, "--dt", impact::kDt);
  if (!(dt > 0.0)) throw std::invalid_argument("--dt must be > 0");
  const std::string note = dt == impact::kDt ? std::string() : " [NOT THE DEFAULT dt: " + repro::format_short(dt) + " s]";
  const std::string out = repro::out_dir(argc, argv);
  const repro::Progress progress("B-9 impact study");
  const std::string dir = out + "/data/" + kDriver + "/";

  repro::CsvWriter csv(
      dir + "cells.csv",
      {"angle_deg", "speed", "mu", "subdivision", "touch_impact", "outcome", "gap", "touches", "separations", "slips", "max_depth",
       "min_centre_dx", "pass_through", "separated", "t_sep", "ke0", "ke_growth", "total_growth", "touch_loss",
       "touch_loss_eq5", "touch_loss_eq5_group", "total_loss", "block_eq5", "restitution", "jn", "jt", "jt_over_jn", "jt_law", "law_regime",
       "omega_a", "omega_b", "slip0", "slip_end", "ok_pass_through", "ok_energy", "ok_separation", "ok_touch_loss",
       "ok_total_loss", "ok_coulomb", "ok_rigid_law", "wall_s"},
      {"Beyond Paper B: oblique impacts of two 1 m squares (Paper B material, 2 divisions, dt " +
       repro::format_short(dt) + " s); angle from the contact normal; impulses on B, N s/m; energies J/m; "
       "outcome 'ok' or the solver's stop message (a stopped run's state is reported where finite); touch_impact "
       "'paper' (Eq. 4) or 'coulomb' (option TouchImpact::kCoulomb, beyond the paper: the same grid again)"});
  // The paper's method, then the same grid with the Coulomb touch option.
  std::vector<impact::Cell> cells = impact::grid(false);
  for (const impact::Cell& c : impact::grid(true)) cells.push_back(c);
  // Paper B Sect. 5's sub-model: the subdivision-on cells again.
  for (const impact::Cell& c : impact::submodel_grid()) cells.push_back(c);
  std::vector<impact::CellResult> results, option_results, submodel_results;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const impact::CellResult r = impact::run_cell(cells[i], dt);
    (cells[i].submodel ? submodel_results : cells[i].coulomb ? option_results : results).push_back(r);
    if (!r.ok) progress("cell " + impact::cell_name(r.cell) + " stopped: " + r.outcome);
    if ((i + 1) % 30 == 0 || i + 1 == cells.size())
      progress(std::to_string(i + 1) + " of " + std::to_string(cells.size()) + " cells");
    const impact::Cell& c = r.cell;
    const bool has_jn = std::isfinite(r.jn) && r.jn > 0.0;
    csv.row(std::vector<std::string>{
        num(c.angle_deg), num(c.speed), num(c.mu), impact::subdivision_name(c), c.coulomb ? "coulomb" : "paper", r.outcome, num(r.gap),
        std::to_string(r.touches), std::to_string(r.separations), std::to_string(r.slips), num(r.max_depth),
        num(r.min_centre_dx), yes(r.pass_through), yes(r.separated), r.t_sep >= 0.0 ? num(r.t_sep) : "", num(r.ke0),
        num(r.ke_growth), num(r.total_growth), num(r.touch_loss), num(r.touch_loss_eq5), num(r.touch_loss_eq5_group), num(r.total_loss),
        num(r.block_eq5), num(r.e), num(r.jn), num(r.jt), has_jn ? num(r.jt / r.jn) : "", num(r.jt_law),
        r.law_sticks ? "stick" : "slide", num(r.omega_a), num(r.omega_b), num(r.slip0), num(r.slip_end),
        yes(impact::no_pass_through(r)), yes(impact::energy_never_grows(r)), yes(impact::separates(r)),
        yes(impact::touch_loss_within_eq5(r)), yes(impact::total_loss_within_block_eq5(r)),
        yes(impact::obeys_coulomb(r)), yes(impact::matches_rigid_law(r)), num(r.wall)});
  }
  csv.commit();
  std::vector<repro::Claim> claims = impact::rows(results, note, option_results);
  for (const repro::Claim& c : impact::submodel_rows(submodel_results, results, note)) claims.push_back(c);
  double wall = 0.0, slowest = 0.0;
  for (const impact::CellResult& r : results) {
    wall += r.wall;
    slowest = std::max(slowest, r.wall);
  }
  double sub_wall = 0.0, inplace_wall = 0.0;
  for (const impact::CellResult& r : option_results) {
    wall += r.wall;
    slowest = std::max(slowest, r.wall);
  }
  for (const impact::CellResult& r : results)
    if (r.cell.subdivision) inplace_wall += r.wall;
  for (const impact::CellResult& r : submodel_results) sub_wall += r.wall;
  claims.push_back(repro::measurement(
      "B-9", "cost of the impact study", "-",
      std::to_string(results.size()) + " + " + std::to_string(option_results.size()) + " (Coulomb touch) cells in " + repro::format_short(wall, 3) + " s of run time (slowest cell " +
          repro::format_short(slowest, 3) + " s); dt " + repro::format_short(dt) + " s, 2-division squares" + note,
      "wall time of the cells on this machine"));
  claims.back().key = "cost";
  claims.push_back(repro::measurement(
      "B-9", "cost of the sub-model cells (Sect. 5's sub-model) against the in-place refinement's", "-",
      std::to_string(submodel_results.size()) + " sub-model cells in " + repro::format_short(sub_wall, 3) +
          " s of run time; the same cells with the in-place refinement " + repro::format_short(inplace_wall, 3) +
          " s" + note,
      "wall time of the cells on this machine (not in the cost row above)"));
  claims.back().key = "submodel-cost";
  repro::default_scope(claims, repro::Scope::kExtension);  // beyond the paper; the option rows say so themselves
  repro::write_claims(repro::claims_path(out, kDriver), claims);
  progress("done");
  return 0;
} catch (const std::exception& e) {
  std::fprintf(stderr, "B_9_impact_study: error: %s\n", e.what());
  return 1;
}
