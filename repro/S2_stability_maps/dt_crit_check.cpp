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

namespace s2 {

DtCritSummary dt_crit_check(const std::string& dir) {
  auto num = [](double x) { return repro::format_full(x); };
  repro::CsvWriter csv(dir + "/dt_crit_check.csv",
                       {"case", "kn", "linearized", "empirical", "solver_current", "solver_predicted", "old_estimate",
                        "empirical_over_linearized", "current_over_linearized", "predicted_over_linearized",
                        "old_over_linearized"},
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
    csv.row(std::vector<std::string>{rc.name, num(rc.scene.contact.kn), num(lin), num(emp), num(cur), num(pred),
                                     num(old), num(emp / lin), num(cur / lin), num(pred / lin), num(old / lin)});
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
