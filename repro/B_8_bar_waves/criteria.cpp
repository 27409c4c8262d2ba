// Two elastic bars head on: the criteria of the rows.
#include <algorithm>
#include <cmath>

#include "repro/B_8_bar_waves/bar_waves.hpp"

namespace bars {

double observed_order(const std::vector<Run>& runs, double Run::*err) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  int n = 0;
  for (const Run& r : runs) {
    if (!r.ok() || !(std::fabs(r.*err) > 0.0)) return 0.0;
    const double x = std::log(r.h), y = std::log(std::fabs(r.*err));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
    ++n;
  }
  if (n < 2) return 0.0;
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}
bool duration_ok(const Run& r, const Setup& s) {
  return r.ok() && std::fabs(r.duration - s.contact_time()) < kDurationTol * s.contact_time();
}
bool stress_ok(const Run& r, const Setup& s) {
  return r.ok() && std::fabs(r.mean_stress - s.contact_stress()) < kStressTol * s.contact_stress();
}
bool plateau_ok(const Run& r, const Setup& s) {
  return r.ok() && std::fabs(r.plateau_stress - s.contact_stress()) < kPlateauTol * s.contact_stress();
}
bool exchange_ok(const Run& r, const Setup& s) {
  return r.ok() && std::max(std::fabs(r.v0), std::fabs(r.v1 - s.speed)) < kExchangeTol * s.speed;
}
bool energy_never_grows(const std::vector<Run>& runs) {
  for (const Run& r : runs)
    if (!(r.energy_growth < kEnergyGrowthTol)) return false;
  return !runs.empty();
}
}  // namespace bars
