// The impact study's data file, cells.csv.
#include "repro/B_9_impact_study/output.hpp"

#include <cmath>
#include <vector>

namespace impact {
namespace {

// A number as CSV text; empty if not finite (a stopped run's state is no data).
std::string num(double x) { return std::isfinite(x) ? repro::format_full(x) : std::string(); }
std::string yes(bool b) { return b ? "y" : "n"; }

}  // namespace

CellsCsv::CellsCsv(const std::string& path, double dt)
    : csv_(path,
           {"angle_deg", "speed", "mu", "subdivision", "touch_impact", "outcome", "gap", "touches", "separations",
            "slips", "max_depth", "min_centre_dx", "pass_through", "separated", "t_sep", "ke0", "ke_growth",
            "total_growth", "touch_loss", "touch_loss_eq5", "touch_loss_eq5_group", "total_loss", "block_eq5",
            "restitution", "jn", "jt", "jt_over_jn", "jt_law", "law_regime", "omega_a", "omega_b", "slip0",
            "slip_end", "ok_pass_through", "ok_energy", "ok_separation", "ok_touch_loss", "ok_total_loss",
            "ok_coulomb", "ok_rigid_law", "wall_s"},
           {"Beyond Paper B: oblique impacts of two 1 m squares (Paper B material, 2 divisions, dt " +
            repro::format_short(dt) + " s); angle from the contact normal; impulses on B, N s/m; energies J/m; "
            "outcome 'ok' or the solver's stop message (a stopped run's state is reported where finite); touch_impact "
            "'paper' (Eq. 4) or 'coulomb' (option TouchImpact::kCoulomb, beyond the paper: the same grid again)"}) {}

void CellsCsv::row(const CellResult& r) {
  const Cell& c = r.cell;
  const bool has_jn = std::isfinite(r.jn) && r.jn > 0.0;
  csv_.row(std::vector<std::string>{
      num(c.angle_deg), num(c.speed), num(c.mu), subdivision_name(c), c.coulomb ? "coulomb" : "paper", r.outcome,
      num(r.gap), std::to_string(r.touches), std::to_string(r.separations), std::to_string(r.slips),
      num(r.max_depth), num(r.min_centre_dx), yes(r.pass_through), yes(r.separated),
      r.t_sep >= 0.0 ? num(r.t_sep) : "", num(r.ke0), num(r.ke_growth), num(r.total_growth), num(r.touch_loss),
      num(r.touch_loss_eq5), num(r.touch_loss_eq5_group), num(r.total_loss), num(r.block_eq5), num(r.e), num(r.jn),
      num(r.jt), has_jn ? num(r.jt / r.jn) : "", num(r.jt_law), r.law_sticks ? "stick" : "slide", num(r.omega_a),
      num(r.omega_b), num(r.slip0), num(r.slip_end), yes(no_pass_through(r)), yes(energy_never_grows(r)),
      yes(separates(r)), yes(touch_loss_within_eq5(r)), yes(total_loss_within_block_eq5(r)), yes(obeys_coulomb(r)),
      yes(matches_rigid_law(r)), num(r.wall)});
}

}  // namespace impact
