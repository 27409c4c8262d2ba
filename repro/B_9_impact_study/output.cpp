// The impact study's data file, cells.csv, declared as a column table.
#include "repro/B_9_impact_study/output.hpp"

#include <cmath>
#include <vector>

namespace impact {
namespace {

using Column = repro::Column<CellResult>;

// A number cell; empty if not finite (a stopped run's state is no data).
repro::Cell num(double x) { return repro::cell_if(std::isfinite(x), x); }
// A column of a result's number; of a criterion's verdict as y / n.
Column number(const char* name, double CellResult::*field) {
  return {name, [field](const CellResult& r) { return num(r.*field); }};
}
Column verdict(const char* name, bool (*criterion)(const CellResult&)) {
  return {name, [criterion](const CellResult& r) { return criterion(r) ? "y" : "n"; }};
}
Column yes(const char* name, bool CellResult::*field) {
  return {name, [field](const CellResult& r) { return r.*field ? "y" : "n"; }};
}

std::vector<Column> columns() {
  return {{"angle_deg", [](const CellResult& r) { return num(r.cell.angle_deg); }},
          {"speed", [](const CellResult& r) { return num(r.cell.speed); }},
          {"mu", [](const CellResult& r) { return num(r.cell.mu); }},
          {"subdivision", [](const CellResult& r) { return subdivision_name(r.cell); }},
          {"touch_impact", [](const CellResult& r) { return r.cell.coulomb ? "coulomb" : "paper"; }},
          repro::field("outcome", &CellResult::outcome),
          number("gap", &CellResult::gap),
          repro::field("touches", &CellResult::touches),
          repro::field("separations", &CellResult::separations),
          repro::field("slips", &CellResult::slips),
          number("max_depth", &CellResult::max_depth),
          number("min_centre_dx", &CellResult::min_centre_dx),
          yes("pass_through", &CellResult::pass_through),
          yes("separated", &CellResult::separated),
          {"t_sep", [](const CellResult& r) { return r.t_sep >= 0.0 ? num(r.t_sep) : repro::Cell(""); }},
          number("ke0", &CellResult::ke0),
          number("ke_growth", &CellResult::ke_growth),
          number("total_growth", &CellResult::total_growth),
          number("touch_loss", &CellResult::touch_loss),
          number("touch_loss_eq5", &CellResult::touch_loss_eq5),
          number("touch_loss_eq5_group", &CellResult::touch_loss_eq5_group),
          number("total_loss", &CellResult::total_loss),
          number("block_eq5", &CellResult::block_eq5),
          number("restitution", &CellResult::e),
          number("jn", &CellResult::jn),
          number("jt", &CellResult::jt),
          {"jt_over_jn",
           [](const CellResult& r) { return std::isfinite(r.jn) && r.jn > 0.0 ? num(r.jt / r.jn) : repro::Cell(""); }},
          number("jt_law", &CellResult::jt_law),
          {"law_regime", [](const CellResult& r) { return r.law_sticks ? "stick" : "slide"; }},
          number("omega_a", &CellResult::omega_a),
          number("omega_b", &CellResult::omega_b),
          number("slip0", &CellResult::slip0),
          number("slip_end", &CellResult::slip_end),
          verdict("ok_pass_through", no_pass_through),
          verdict("ok_energy", energy_never_grows),
          verdict("ok_separation", separates),
          verdict("ok_touch_loss", touch_loss_within_eq5),
          verdict("ok_total_loss", total_loss_within_block_eq5),
          verdict("ok_coulomb", obeys_coulomb),
          verdict("ok_rigid_law", matches_rigid_law),
          number("wall_s", &CellResult::wall)};
}

}  // namespace

CellsCsv::CellsCsv(const std::string& path, double dt)
    : table_(path, columns(),
             {"Beyond Paper B: oblique impacts of two 1 m squares (Paper B material, 2 divisions, dt " +
              repro::format_short(dt) + " s); angle from the contact normal; impulses on B, N s/m; energies J/m; "
              "outcome 'ok' or the solver's stop message (a stopped run's state is reported where finite); "
              "touch_impact 'paper' (Eq. 4) or 'coulomb' (option TouchImpact::kCoulomb, beyond the paper: the same "
              "grid again)"}) {}

}  // namespace impact
