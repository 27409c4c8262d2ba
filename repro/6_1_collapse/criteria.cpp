// Paper A Sect. 6.1: the criteria of the claim rows (collapse.hpp), shared
// with the negative controls.
#include <algorithm>

#include "repro/6_1_collapse/collapse.hpp"

namespace collapse61 {

bool generator_ok(const CaseResult& r) {
  return r.dt_ratio0 < kStartRatio && r.dt_ratio_max < 1.0 && r.dropped_area < kDroppedShare * r.region_area;
}

EnergyBudget energy_budget(const CaseResult& r) {
  EnergyBudget b;
  for (const Sample& s : r.series) b.rise = std::max(b.rise, s.total - r.series.front().total);
  b.released = r.series.front().gravity - r.series.back().gravity;
  b.change = r.series.back().total - r.series.front().total;
  b.pass = r.stopped.empty() && b.released > 0.0 && b.rise < kEnergyRise * b.released;
  return b;
}

bool collapses_faster(const Sample& a, const Sample& b) {
  return a.mean_drop > kDropFactor * b.mean_drop && a.front_x > b.front_x + kLead;
}

FrontLead front_lead(const CaseResult& a, const CaseResult& b) {
  FrontLead f;
  for (std::size_t i = 0; i < std::min(a.series.size(), b.series.size()); ++i) {
    if (a.series[i].t < kStanding) continue;
    ++f.compared;
    if (a.series[i].front_x >= b.series[i].front_x) ++f.ahead;
  }
  return f;
}

bool runs_out_further(const Sample& a, const Sample& b) {
  return a.front_x > b.front_x + kLead && a.runout_mass > b.runout_mass;
}

bool ordering_survives(const Ends& ends) {
  bool holds = true;
  for (const auto& end : ends) holds = holds && runs_out_further(end[0], end[1]);
  return holds;
}

}  // namespace collapse61
