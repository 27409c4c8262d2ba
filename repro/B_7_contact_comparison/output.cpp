// Paper A against Paper B on the same collisions: the data files, sweep.csv
// (one row per run), history.csv (the velocities at the base dt) and
// energy_history.csv (the CDEM runs' energy account), each declared as a
// column table.
#include "repro/B_7_contact_comparison/output.hpp"

#include "repro/common/common.hpp"
#include "repro/common/table.hpp"

namespace compare {
namespace {

using Account = dda::cdem::CdemEnergyAccount;

const std::vector<repro::Column<Result>> kSweepColumns = {
    repro::field("scene", &Result::scene),
    repro::field("model", &Result::model),
    repro::field("dt", &Result::dt),
    repro::field("wall_s", &Result::wall),
    repro::field("steps", &Result::steps),
    repro::field("t_touch", &Result::t_touch),
    repro::field("touch_err", &Result::touch_err),
    repro::field("momentum_err", &Result::mom_err),
    repro::field("energy_err_end", &Result::energy_err_end),
    repro::field("energy_err_max", &Result::energy_err_max),
    repro::field("v_i", &Result::v_i),
    repro::field("v_j", &Result::v_j),
    repro::field("vj_err_exchange", &Result::vj_err_exchange),
    repro::field("vj_err_self", &Result::vj_err_self),
    repro::field("contact_start", &Result::contact_start),
    repro::field("contact_end", &Result::contact_end)};

// One row of a history: its scene and model ("scene/model" key) and index.
struct Sample {
  std::string scene, model;
  const History* h;
  std::size_t k;
};
const Account& account(const Sample& s) { return s.h->accounts[s.k]; }
repro::Column<Sample> energy(const char* name, double Account::*field) {
  return {name, [field](const Sample& s) { return account(s).*field; }};
}
const std::vector<repro::Column<Sample>> kHistoryColumns = {
    {"scene", [](const Sample& s) { return s.scene; }},
    {"model", [](const Sample& s) { return s.model; }},
    {"time", [](const Sample& s) { return s.h->t[s.k]; }},
    {"vx_i", [](const Sample& s) { return s.h->vi[s.k]; }},
    {"vx_j", [](const Sample& s) { return s.h->vj[s.k]; }}};
const std::vector<repro::Column<Sample>> kEnergyColumns = {
    {"scene", [](const Sample& s) { return s.scene; }},
    {"model", [](const Sample& s) { return s.model; }},
    energy("time", &Account::time),
    energy("energy_initial", &Account::initial),
    energy("kinetic", &Account::kinetic),
    energy("strain", &Account::strain),
    energy("gravity", &Account::gravity),
    energy("touch_loss", &Account::touch_loss),
    energy("touch_loss_eq5", &Account::touch_loss_eq5),
    energy("refine_loss", &Account::refine_loss),
    energy("deletion_loss", &Account::deletion_loss),
    energy("energy_other", &Account::other)};

// Every sample of every history: `count(h)` rows each.
template <class Count>
std::vector<Sample> samples(const std::map<std::string, History>& histories, Count count) {
  std::vector<Sample> rows;
  for (const auto& [key, h] : histories) {
    const std::string scene = key.substr(0, key.find('/')), model = key.substr(key.find('/') + 1);
    for (std::size_t k = 0; k < count(h); ++k) rows.push_back({scene, model, &h, k});
  }
  return rows;
}

}  // namespace

void write_data(const std::string& dir, const std::vector<Result>& results,
                const std::map<std::string, History>& histories) {
  repro::write_table(
      dir + "sweep.csv", kSweepColumns, results,
      {"A: Paper A penalty (6-DOF DDA); B: Paper B clone node + subdivision (CDEM); B0: clone node "
       "without subdivision; P: node-to-edge penalty on B0's CST "
       "meshes (kn = E/100, frictionless, undamped; baseline, not Paper B). Prisms RECONSTRUCTED (7 m, Paper B Fig. 12 lost); A's kn on the "
       "prisms = E/100 = 0.4 GPa (our choice). vj_err_self: against the same model at its "
       "smallest dt. wall_s: mean of repeated runs.",
       // the mode scene_defs() sets for B (the figure labels B's curves with it)
       "subdivision mode of B: in-place refinement (beyond the paper)"});
  repro::write_table(dir + "history.csv", kHistoryColumns,
                     samples(histories, [](const History& h) { return h.t.size(); }));
  // The energy account of the CDEM runs (B, B0) at the base dt, per history row, J/m.
  repro::write_table(dir + "energy_history.csv", kEnergyColumns,
                     samples(histories, [](const History& h) { return h.accounts.size(); }),
                     {"Model::energy_account of the CDEM runs at the base dt: initial = kinetic + strain + gravity "
                      "+ touch_loss (measured; Eq. 5 beside it) + refine_loss + deletion_loss + energy_other"});
}

}  // namespace compare
