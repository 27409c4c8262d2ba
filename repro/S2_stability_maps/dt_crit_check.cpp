// S2 stability maps, 1. the dt_crit check (studies.hpp).
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "dda/simulation.hpp"
#include "repro/S2_stability_maps/resting.hpp"
#include "repro/S2_stability_maps/studies.hpp"
#include "repro/S_common/stability.hpp"
#include "repro/common/common.hpp"
#include "repro/common/table.hpp"

namespace s2 {
namespace {

// One resting contact's critical steps, s.
struct Row {
  const RestCase& rc;
  double lin, emp, cur, pred, old;
};
repro::Column<Row> over_linearized(const char* name, double Row::*field) {
  return {name, [field](const Row& r) { return r.*field / r.lin; }};
}
const std::vector<repro::Column<Row>> kColumns = {
    {"case", [](const Row& r) { return r.rc.name; }},
    {"kn", [](const Row& r) { return r.rc.scene.contact.kn; }},
    repro::field("linearized", &Row::lin),
    repro::field("empirical", &Row::emp),
    repro::field("solver_current", &Row::cur),
    repro::field("solver_predicted", &Row::pred),
    repro::field("old_estimate", &Row::old),
    over_linearized("empirical_over_linearized", &Row::emp),
    over_linearized("current_over_linearized", &Row::cur),
    over_linearized("predicted_over_linearized", &Row::pred),
    over_linearized("old_over_linearized", &Row::old)};

}  // namespace

DtCritSummary dt_crit_check(const std::string& dir) {
  repro::TableWriter<Row> csv(dir + "/dt_crit_check.csv", kColumns,
                              {"dt_crit (s) of a resting contact: linearised 2/omega_max (independent), empirical "
                               "(bisection, 14 halvings of the log interval, 20000 steps), solver's current and "
                               "a-priori estimates, and the per-block estimate 2 kn L_max / H"});
  std::vector<RestCase> cases;
  for (double kn : {1e6, 1e7, 1e8, 1e9}) cases.push_back(resting(kn, false, false, false));
  for (double kn : {1e6, 1e7, 1e8, 1e9}) cases.push_back(resting(kn, true, false, false));
  for (double kn : {1e8, 1e9}) cases.push_back(resting(kn, false, false, true));
  for (double kn : {1e7, 1e8, 1e9}) cases.push_back(resting(kn, false, true, false));
  for (double kn : {1e7, 1e8}) cases.push_back(resting(kn, true, true, false));
  DtCritSummary s;
  s.cases = cases.size();
  for (const RestCase& rc : cases) {
    dda::Simulation sim(rc.scene);
    const double lin = repro::stab::linearized_critical_step(sim).dt_crit;
    const double emp = empirical_limit(rc.scene, lin);
    const double cur = sim.critical_time_step(), pred = sim.predicted_critical_step(), old = old_prior(sim);
    csv.row({rc, lin, emp, cur, pred, old});
    s.worst_emp = std::max(s.worst_emp, std::fabs(emp / lin - 1.0));
    s.worst_cur = std::max(s.worst_cur, cur / lin);
    s.best_cur = std::min(s.best_cur, cur / lin);
    s.worst_pred = std::max(s.worst_pred, pred / lin);
    s.worst_old = std::max(s.worst_old, old / lin);
  }
  csv.commit();
  return s;
}

}  // namespace s2
