// S2 stability maps, 2. one map with its dt_crit lines (studies.hpp).
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "dda/simulation.hpp"
#include "repro/S2_stability_maps/resting.hpp"
#include "repro/S2_stability_maps/studies.hpp"
#include "repro/S_common/stability.hpp"
#include "repro/common/common.hpp"

namespace s2 {
namespace {
using repro::stab::RunClass;

std::string num(double x) { return repro::format_full(x); }

// dt_crit lines for one kn: the solver's prediction, the old estimate, and
// the linearised system at the peak contact force of a resolved run.
struct Lines {
  double predicted = 0.0, old = 0.0, linearized = 0.0, current_min = 0.0;
};

Lines lines_for(const MapScene& m, double kn) {
  Lines l;
  dda::Scene s = m.scene;
  s.contact.kn = kn;
  dda::Simulation probe(s);
  l.predicted = probe.predicted_critical_step();
  l.old = old_prior(probe);
  s.dt = 0.05 * l.predicted;
  s.duration = window(m, kn, s.dt);
  dda::Simulation sim(s);
  double fmax = 0.0;
  long peak = -1;
  l.current_min = std::numeric_limits<double>::infinity();
  try {
    while (sim.time() < s.duration - 0.5 * s.dt) {
      sim.step();
      double f = 0.0;
      for (const dda::ContactInfo& c : sim.contacts()) f += dda::length(c.normal_force);
      if (f > fmax) {
        fmax = f;
        peak = sim.step_count();
      }
      if (!sim.contacts().empty()) l.current_min = std::min(l.current_min, sim.critical_time_step());
    }
  } catch (const dda::SimulationError&) {
    // A soft kn lets the blocks pass through each other even at 0.05 of the
    // predicted step (the penetration guard stops the run): the lines use the
    // largest force reached before the stop.
  }
  dda::Simulation at(s);
  while (at.step_count() < peak) at.step();
  l.linearized = repro::stab::linearized_critical_step(at).dt_crit;
  return l;
}

}  // namespace

MapSummary map_study(const MapScene& m, const std::string& dir) {
  std::vector<double> kns, dts;
  for (int i = 0; i <= 12; ++i) kns.push_back(std::pow(10.0, 6.0 + 0.5 * i));
  for (int i = 0; i <= 16; ++i) dts.push_back(std::pow(10.0, -6.0 + 0.25 * i));
  repro::CsvWriter map(dir + "/map_" + m.name + ".csv",
                       {"kn", "dt", "class", "window_s", "dt_over_predicted", "max_dt_over_current", "energy_change",
                        "max_energy_growth", "message"},
                       {m.title + ": one run per (kn, dt); energy relative to the impact energy"});
  repro::CsvWriter bnd(dir + "/boundary_" + m.name + ".csv",
                       {"kn", "predicted", "old_estimate", "linearized_at_peak", "current_min",
                        "largest_stable_below_first_failure", "smallest_not_stable", "smallest_blowup"},
                       {m.title + ": dt_crit lines (s) and the empirical boundary per kn"});
  MapSummary s;
  for (double kn : kns) {
    const Lines l = lines_for(m, kn);
    int cells_below = 0, through_below = 0;
    double first_bad = std::numeric_limits<double>::infinity(), first_blowup = first_bad, last_good = 0.0;
    for (double dt : dts) {
      const MapRun r = map_run(m, kn, dt);
      map.row(std::vector<std::string>{num(kn), num(dt), repro::stab::class_name(r.cls), num(r.window),
                                       num(r.ratio0), num(r.ratio_max), num(r.energy_change), num(r.max_growth),
                                       r.message});
      const int c = static_cast<int>(r.cls);
      ++(dt <= l.predicted ? s.below : s.above)[c];
      if (fails_at_or_below(r, dt, l.predicted)) ++s.failures_below;
      if (dt <= l.predicted) {
        ++cells_below;
        through_below += r.cls == RunClass::kFlipThrough;
      }
      if (r.cls == RunClass::kBlowUp) {
        first_blowup = std::min(first_blowup, dt);
        if (dt <= l.old) ++s.old_blowups_below;
      }
      if (r.cls == RunClass::kEnergyGrowth) s.growth_ratio = std::min(s.growth_ratio, dt / l.predicted);
      if (r.cls == RunClass::kFlipThrough && dt <= l.predicted && (s.flip_below.empty() || s.flip_below.back() != kn))
        s.flip_below.push_back(kn);
      if (r.cls != RunClass::kStable) first_bad = std::min(first_bad, dt);
    }
    if (cells_below > 0 && through_below == cells_below) s.all_through_kn = std::max(s.all_through_kn, kn);
    for (double dt : dts)
      if (dt < first_bad) last_good = dt;
    bnd.row({kn, l.predicted, l.old, l.linearized, l.current_min, last_good,
             std::isfinite(first_bad) ? first_bad : 0.0, std::isfinite(first_blowup) ? first_blowup : 0.0});
    if (std::isfinite(first_blowup)) {
      s.min_blowup_ratio = std::min(s.min_blowup_ratio, first_blowup / l.predicted);
      s.max_blowup_ratio = std::max(s.max_blowup_ratio, first_blowup / l.predicted);
    }
  }
  map.commit();
  bnd.commit();
  return s;
}

}  // namespace s2
