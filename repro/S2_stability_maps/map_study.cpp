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
#include "repro/common/table.hpp"

namespace s2 {
namespace {
using repro::stab::RunClass;

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
      if (sim.contact_count() > 0) l.current_min = std::min(l.current_min, sim.critical_time_step());
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

// One cell of map_<name>.csv: a run at (kn, dt).
struct Cell {
  double kn, dt;
  MapRun r;
};
const std::vector<repro::Column<Cell>> kMapColumns = {
    {"kn", [](const Cell& c) { return c.kn; }},
    {"dt", [](const Cell& c) { return c.dt; }},
    {"class", [](const Cell& c) { return repro::stab::class_name(c.r.cls); }},
    {"window_s", [](const Cell& c) { return c.r.window; }},
    {"dt_over_predicted", [](const Cell& c) { return c.r.ratio0; }},
    {"max_dt_over_current", [](const Cell& c) { return c.r.ratio_max; }},
    {"energy_change", [](const Cell& c) { return c.r.energy_change; }},
    {"max_energy_growth", [](const Cell& c) { return c.r.max_growth; }},
    {"message", [](const Cell& c) { return c.r.message; }}};

// One row of boundary_<name>.csv: the dt_crit lines of one kn and the
// empirical boundary (0: no such dt on the map).
struct Boundary {
  double kn;
  Lines l;
  double last_good, first_bad, first_blowup;
};
const std::vector<repro::Column<Boundary>> kBoundaryColumns = {
    {"kn", [](const Boundary& b) { return b.kn; }},
    {"predicted", [](const Boundary& b) { return b.l.predicted; }},
    {"old_estimate", [](const Boundary& b) { return b.l.old; }},
    {"linearized_at_peak", [](const Boundary& b) { return b.l.linearized; }},
    {"current_min", [](const Boundary& b) { return b.l.current_min; }},
    {"largest_stable_below_first_failure", [](const Boundary& b) { return b.last_good; }},
    {"smallest_not_stable", [](const Boundary& b) { return std::isfinite(b.first_bad) ? b.first_bad : 0.0; }},
    {"smallest_blowup", [](const Boundary& b) { return std::isfinite(b.first_blowup) ? b.first_blowup : 0.0; }}};

// dt_crit lines for one kn: the solver's prediction, the old estimate, and
// the linearised system at the peak contact force of a resolved run.
}  // namespace

MapSummary map_study(const MapScene& m, const std::string& dir) {
  std::vector<double> kns, dts;
  for (int i = 0; i <= 12; ++i) kns.push_back(std::pow(10.0, 6.0 + 0.5 * i));
  for (int i = 0; i <= 16; ++i) dts.push_back(std::pow(10.0, -6.0 + 0.25 * i));
  repro::TableWriter<Cell> map(dir + "/map_" + m.name + ".csv", kMapColumns,
                               {m.title + ": one run per (kn, dt); energy relative to the impact energy"});
  repro::TableWriter<Boundary> bnd(dir + "/boundary_" + m.name + ".csv", kBoundaryColumns,
                                   {m.title + ": dt_crit lines (s) and the empirical boundary per kn"});
  MapSummary s;
  for (double kn : kns) {
    const Lines l = lines_for(m, kn);
    int cells_below = 0, through_below = 0;
    double first_bad = std::numeric_limits<double>::infinity(), first_blowup = first_bad, last_good = 0.0;
    for (double dt : dts) {
      const MapRun r = map_run(m, kn, dt);
      map.row({kn, dt, r});
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
    bnd.row({kn, l, last_good, first_bad, first_blowup});
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
