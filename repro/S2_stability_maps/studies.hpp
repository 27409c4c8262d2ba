// S2 stability maps: the two studies of the driver (stability_maps.cpp says
// what they show), each writing its CSV files and returning what its claim
// rows read.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "repro/S2_stability_maps/maps.hpp"

namespace s2 {

// 1. dt_crit check (dt_crit_check.cpp): per resting case the linearised,
// empirical, solver's current and predicted and per-block ("old") critical
// steps, written to dir/dt_crit_check.csv; the extremes of their ratios.
struct DtCritSummary {
  std::size_t cases = 0;
  double worst_emp = 0.0;   // largest |empirical / linearised - 1|
  double worst_cur = 0.0, best_cur = 1e300;  // current / linearised
  double worst_pred = 0.0, worst_old = 0.0;  // predicted, old / linearised
};
DtCritSummary dt_crit_check(const std::string& dir);

// 2. One stability map (map_study.cpp): kn 1e6 .. 1e12 Pa (half decades) x
// dt 1e-6 .. 1e-2 s (quarter decades), written to dir/map_<name>.csv with
// its dt_crit lines and empirical boundary in dir/boundary_<name>.csv.
struct MapSummary {
  // Cells per class (RunClass order), at dt <= predicted and above it.
  int below[4] = {0, 0, 0, 0}, above[4] = {0, 0, 0, 0};
  int old_blowups_below = 0;  // blow-ups at dt <= the per-block estimate
  int failures_below = 0;     // fails_at_or_below the prediction
  // The largest kn at which every cell with dt <= predicted passes
  // through (0: none): where the scene's own kn sits against it.
  double all_through_kn = 0.0;
  double min_blowup_ratio = 1e300, max_blowup_ratio = 0.0;  // first blow-up dt / predicted, over kn
  double growth_ratio = 1e300;     // smallest dt/predicted of an 'energy growth' run
  std::vector<double> flip_below;  // kn with a flip-through at dt <= predicted
};
MapSummary map_study(const MapScene& m, const std::string& dir);

}  // namespace s2
