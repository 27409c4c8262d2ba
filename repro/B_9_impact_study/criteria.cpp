// The impact study: the per-cell criteria, the grid of cells and their names.
#include "repro/B_9_impact_study/tally.hpp"

namespace impact {

bool no_pass_through(const CellResult& r) {
  return r.ok && r.max_depth <= r.tol && r.min_centre_dx >= 0.5 * kSide;
}
bool energy_never_grows(const CellResult& r) { return r.ok && r.ke_growth <= kEnergySlack; }
bool series_never_grows(const std::vector<double>& ke) {
  for (double k : ke)
    if (k > ke.front() * (1.0 + kEnergySlack)) return false;
  return true;
}
bool separates(const CellResult& r) { return r.ok && r.separated; }
bool touch_loss_within_eq5(const CellResult& r) {
  return r.ok && r.touch_loss >= -kEnergySlack * r.ke0 &&
         r.touch_loss <= r.touch_loss_eq5_group + kEnergySlack * r.ke0;
}
bool total_loss_within_block_eq5(const CellResult& r) {
  return r.ok && r.total_loss >= -kEnergySlack * r.ke0 && r.total_loss <= r.block_eq5 * (1.0 + kEnergySlack);
}
bool obeys_coulomb(const CellResult& r) {
  return r.ok && r.jn > 0.0 && std::fabs(r.jt) <= (r.cell.mu + kCoulombSlack) * r.jn;
}
bool matches_rigid_law(const CellResult& r) {
  return r.ok && r.jn > 0.0 && std::fabs(r.jt - r.jt_law) <= kLawTolerance * r.jn;
}
std::vector<Cell> grid(bool coulomb) {
  std::vector<Cell> cells;
  for (bool sub : {false, true})
    for (double mu : kFrictions)
      for (double v : kSpeeds)
        for (double a : kAngles) cells.push_back({a, v, mu, sub, coulomb});
  return cells;
}
std::vector<Cell> submodel_grid() {
  std::vector<Cell> cells;
  for (double mu : kFrictions)
    for (double v : kSpeeds)
      for (double a : kAngles) cells.push_back({a, v, mu, true, false, true});
  return cells;
}
std::string subdivision_name(const Cell& c) {
  return !c.subdivision ? "off" : c.submodel ? "sub-model" : "on";
}
std::string cell_name(const Cell& c) {
  return "(" + repro::format_short(c.angle_deg) + " deg, " + repro::format_short(c.speed) + " m/s, mu " +
         repro::format_short(c.mu) + ", sub " + subdivision_name(c) + (c.coulomb ? ", Coulomb touch" : "") + ")";
}
std::string count_text(const Tally& t) {
  return std::to_string(t.pass) + " of " + std::to_string(t.total) + " cells" +
         (t.failing.empty() ? std::string() : "; failing: " + t.failing);
}
std::string stopped_or(const CellResult& r, const std::string& text) {
  return r.ok ? text : "stopped: " + r.outcome.substr(0, 90);
}
repro::Claim tally_row(const std::string& key, const std::string& claim, const std::string& paper,
                       const std::string& measured, const std::string& tol, const Tally& t, const char* test) {
  repro::Claim c{"B-9", claim, paper, measured, tol, t.pass == t.total && t.total > 0};
  c.key = key;
  c.control = repro::control_test(test);
  return c;
}

std::vector<repro::Claim> cost_rows(const std::vector<CellResult>& results,
                                    const std::vector<CellResult>& option_results,
                                    const std::vector<CellResult>& submodel_results, double dt, const std::string& note) {
  std::vector<repro::Claim> claims;
  double wall = 0.0, slowest = 0.0;
  for (const CellResult& r : results) {
    wall += r.wall;
    slowest = std::max(slowest, r.wall);
  }
  double sub_wall = 0.0, inplace_wall = 0.0;
  for (const CellResult& r : option_results) {
    wall += r.wall;
    slowest = std::max(slowest, r.wall);
  }
  for (const CellResult& r : results)
    if (r.cell.subdivision) inplace_wall += r.wall;
  for (const CellResult& r : submodel_results) sub_wall += r.wall;
  claims.push_back(repro::measurement(
      "B-9", "cost of the impact study", "-",
      std::to_string(results.size()) + " + " + std::to_string(option_results.size()) + " (Coulomb touch) cells in " +
          repro::format_short(wall, 3) + " s of run time (slowest cell " + repro::format_short(slowest, 3) +
          " s); dt " + repro::format_short(dt) + " s, 2-division squares" + note,
      "wall time of the cells on this machine"));
  claims.back().key = "cost";
  claims.push_back(repro::measurement(
      "B-9", "cost of the sub-model cells (Sect. 5's sub-model) against the in-place refinement's", "-",
      std::to_string(submodel_results.size()) + " sub-model cells in " + repro::format_short(sub_wall, 3) +
          " s of run time; the same cells with the in-place refinement " + repro::format_short(inplace_wall, 3) +
          " s" + note,
      "wall time of the cells on this machine (not in the cost row above)"));
  claims.back().key = "submodel-cost";
  return claims;
}

}  // namespace impact
