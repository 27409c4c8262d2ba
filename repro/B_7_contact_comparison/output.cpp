// Paper A against Paper B on the same collisions: the data files, sweep.csv
// (one row per run), history.csv (the velocities at the base dt) and
// energy_history.csv (the CDEM runs' energy account).
#include "repro/B_7_contact_comparison/output.hpp"

#include "repro/common/common.hpp"

namespace compare {

void write_data(const std::string& dir, const std::vector<Result>& results,
                const std::map<std::string, History>& histories) {
  repro::CsvWriter csv(
      dir + "sweep.csv",
      {"scene", "model", "dt", "wall_s", "steps", "t_touch", "touch_err", "momentum_err", "energy_err_end",
       "energy_err_max", "v_i", "v_j", "vj_err_exchange", "vj_err_self", "contact_start", "contact_end"},
      {"A: Paper A penalty (6-DOF DDA); B: Paper B clone node + subdivision (CDEM); B0: clone node "
       "without subdivision; P: node-to-edge penalty on B0's CST "
       "meshes (kn = E/100, frictionless, undamped; baseline, not Paper B). Prisms RECONSTRUCTED (7 m, Paper B Fig. 12 lost); A's kn on the "
       "prisms = E/100 = 0.4 GPa (our choice). vj_err_self: against the same model at its "
       "smallest dt. wall_s: mean of repeated runs.",
       // the mode scene_defs() sets for B (the figure labels B's curves with it)
       "subdivision mode of B: in-place refinement (beyond the paper)"});
  for (const Result& r : results) {
    std::vector<std::string> row = {r.scene, r.model, repro::format_full(r.dt), repro::format_full(r.wall),
                                    std::to_string(r.steps)};
    for (double v : {r.t_touch, r.touch_err, r.mom_err, r.energy_err_end, r.energy_err_max, r.v_i, r.v_j,
                     r.vj_err_exchange, r.vj_err_self, r.contact_start, r.contact_end})
      row.push_back(repro::format_full(v));
    csv.row(row);
  }
  csv.commit();
  repro::CsvWriter hcsv(dir + "history.csv", {"scene", "model", "time", "vx_i", "vx_j"});
  for (const auto& [key, h] : histories) {
    const std::string scene = key.substr(0, key.find('/')), model = key.substr(key.find('/') + 1);
    for (std::size_t k = 0; k < h.t.size(); ++k)
      hcsv.row(std::vector<std::string>{scene, model, repro::format_full(h.t[k]), repro::format_full(h.vi[k]),
                                        repro::format_full(h.vj[k])});
  }
  hcsv.commit();
  // The energy account of the CDEM runs (B, B0) at the base dt, per history row, J/m.
  repro::CsvWriter ecsv(dir + "energy_history.csv",
                        {"scene", "model", "time", "energy_initial", "kinetic", "strain", "gravity", "touch_loss",
                         "touch_loss_eq5", "refine_loss", "deletion_loss", "energy_other"},
                        {"Model::energy_account of the CDEM runs at the base dt: initial = kinetic + strain + gravity "
                         "+ touch_loss (measured; Eq. 5 beside it) + refine_loss + deletion_loss + energy_other"});
  for (const auto& [key, h] : histories) {
    const std::string scene = key.substr(0, key.find('/')), model = key.substr(key.find('/') + 1);
    for (const dda::cdem::CdemEnergyAccount& a : h.accounts)
      ecsv.row(std::vector<std::string>{
          scene, model, repro::format_full(a.time), repro::format_full(a.initial), repro::format_full(a.kinetic),
          repro::format_full(a.strain), repro::format_full(a.gravity), repro::format_full(a.touch_loss),
          repro::format_full(a.touch_loss_eq5), repro::format_full(a.refine_loss),
          repro::format_full(a.deletion_loss), repro::format_full(a.other)});
  }
  ecsv.commit();

}

}  // namespace compare
