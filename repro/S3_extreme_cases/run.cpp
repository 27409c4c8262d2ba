// S3 extreme cases: one run of a case and what it watches (extreme_cases.hpp).
#include <algorithm>
#include <cmath>

#include "dda/overlap.hpp"
#include "dda/potential.hpp"
#include "repro/S3_extreme_cases/extreme_cases.hpp"
#include "repro/common/table.hpp"

namespace s3 {
namespace {
double inscribed_diameter(const dda::Polygon& p) { return 2.0 * dda::inscribed_circle(p).radius; }
}  // namespace

Outcome run(const Extreme& e, double dt_fraction) {
  Outcome o;
  dda::Scene s = e.scene;
  s.duration = e.duration;
  s.dt_fraction = dt_fraction;
  dda::Simulation sim(s);
  o.dt = sim.dt();
  o.ratio0 = sim.dt() / sim.predicted_critical_step();
  o.ratio_max = o.ratio0;
  const double small = std::min(inscribed_diameter(sim.polygon(0)), inscribed_diameter(sim.polygon(1)));
  const Vec2 p0 = sim.momentum();
  const dda::Energy en0 = sim.energy();
  const double e0 = en0.total(), ekin0 = en0.kinetic;
  double max_growth = 0.0, prev_force = 0.0, prev_thick = 0.0;
  const long steps = std::lround(e.duration / sim.dt());
  try {
    for (long k = 0; k < steps; ++k) {
      sim.step();
      const double t = sim.time();
      o.momentum_error = std::max(o.momentum_error, dda::length(sim.momentum() - p0) / dda::length(p0));
      max_growth = std::max(max_growth, (sim.energy().total() - e0) / ekin0);
      if (sim.contact_count() == 0) continue;
      o.ratio_max = std::max(o.ratio_max, sim.dt() / sim.critical_time_step());
      const dda::Polygon& a = sim.polygon(0);
      const dda::Polygon& b = sim.polygon(1);
      const double tol = dda::pair_tolerance(a, b);
      const dda::Polygon ip = dda::intersection_polygon(a, b, tol);
      const double thick = ip.count >= 3 ? inscribed_diameter(ip) : 0.0;
      o.overlap = std::max(o.overlap, thick / small);
      // Softening: the overlap grows while the normal force drops (negative
      // contact stiffness: past the middle of a block the far side is nearer).
      double force = 0.0;
      for (const dda::ContactInfo& c : sim.contacts()) force += dda::length(c.normal_force);
      if (o.t_soft < 0.0 && thick > prev_thick && force < prev_force && thick > 0.01 * small) o.t_soft = t;
      prev_force = force;
      prev_thick = thick;
      if (o.t_deep < 0.0 && repro::stab::deep_penetration(a, b)) o.t_deep = t;
      for (const dda::ContactInfo& c : sim.contacts()) {
        const Vec2 towards = sim.centroid(c.tp) - sim.centroid(c.cp);
        if (o.t_wrong < 0.0 && dda::dot(c.normal_force, towards) > 0.0) o.t_wrong = t;
      }
      if (o.t_swap < 0.0 && sim.centroid(1).x < sim.centroid(0).x) o.t_swap = t;
    }
  } catch (const dda::SimulationError& err) {
    o.message = err.what();
    if (sim.centroid(1).x < sim.centroid(0).x) o.t_swap = sim.time();  // stopped too late
    o.penetration_stop =
        err.reason == dda::StopReason::kPenetration || err.reason == dda::StopReason::kApproachEnergy;
    const bool motion = err.reason == dda::StopReason::kStepMotion;
    o.cls = motion && max_growth <= 0.01 ? RunClass::kFlipThrough : RunClass::kBlowUp;
    return o;
  }
  if (o.t_swap < 0.0 && sim.centroid(1).x < sim.centroid(0).x) o.t_swap = sim.time();
  o.energy_error = (sim.energy().total() - e0) / ekin0;
  o.va = sim.velocity(0)[0];
  o.vb = sim.velocity(1)[0];
  o.velocity_error = (std::fabs(o.va - e.va_expected) + std::fabs(o.vb - e.vb_expected)) / e.v0;
  if (o.t_swap >= 0.0) {
    o.cls = RunClass::kFlipThrough;
  } else if (o.energy_error > 0.01) {
    o.cls = RunClass::kEnergyGrowth;
  }
  return o;
}

Series guarded_series(dda::Simulation& sim, double duration, const std::string& path, const std::string& comment) {
  using S = dda::Simulation;
  repro::TableWriter<S> table(path,
                              {{"time", [](const S& m) { return m.time(); }},
                               {"x_A", [](const S& m) { return m.centroid(0).x; }},
                               {"x_B", [](const S& m) { return m.centroid(1).x; }},
                               {"vx_A", [](const S& m) { return m.velocity(0)[0]; }},
                               {"vx_B", [](const S& m) { return m.velocity(1)[0]; }},
                               {"total_energy", [](const S& m) { return m.energy().total(); }}},
                              {comment});
  Series series;
  try {
    while (sim.time() < duration) {
      sim.step();
      table.row(sim);
    }
  } catch (const dda::SimulationError& err) {
    series.message = err.what();
  }
  table.commit();
  series.rows = table.row_count();
  return series;
}

}  // namespace s3
